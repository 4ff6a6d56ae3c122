#pragma once
// A vertex's rule as data (docs/design.md §1, §2 "limit projection"): the points a subdivision or
// limit rule reads at one vertex and their weights, taken from the connectivity alone. The reference
// applies a mask to values (core/reference/limit_masks.h, core/reference/catmull_clark.h,
// core/reference/loop.h); the plan builders take its terms as a stencil (core/patches/quad_nets.h). One
// source for both, so the two cannot drift apart.
#include <utility>
#include <vector>

#include "core/reference/loop.h"
#include "core/mesh/mesh_connectivity.h"

namespace gps {

/// (Σ_g w_g · Σ_{i ∈ group g} p_i) / d: groups of points that share one weight, as masks are written
/// (Catmull-Clark's limit: n² on the vertex, 4 on each edge neighbour, 1 on each diagonal, over
/// n(n + 5)). apply() sums in exactly that order. Refilled per vertex: keep one per thread so that
/// its storage is reused.
class VertexMask {
public:
  /// Empties the mask and sets its denominator.
  void reset(double denominator);
  /// Starts a group whose points (added next) all carry `weight`.
  void begin_group(double weight);
  /// Adds a point to the current group.
  void add(int point) { points_.push_back(point); }
  /// begin_group(weight) with one point.
  void add_group(double weight, int point) {
    begin_group(weight);
    add(point);
  }

  /// The mask applied to per-point values (any linear type with T::Zero(rows)).
  template <class T>
  T apply(const std::vector<T>& values) const;
  /// The mask as (point, weight / denominator) terms in group order: the stencil form.
  std::vector<std::pair<int, double>> terms() const;

private:
  int group_end(size_t g) const { return g + 1 < group_begins_.size() ? group_begins_[g + 1] : int(points_.size()); }

  std::vector<int> points_;
  std::vector<int> group_begins_;
  std::vector<double> group_weights_;
  double denominator_ = 1.0;
};

template <class T>
T VertexMask::apply(const std::vector<T>& values) const {
  T out = T::Zero(values.front().rows());
  for (size_t g = 0; g < group_weights_.size(); ++g) {
    T sum = T::Zero(values.front().rows());
    for (int i = group_begins_[g]; i < group_end(g); ++i) sum += values[size_t(points_[size_t(i)])];
    out += group_weights_[g] * sum;
  }
  return out / denominator_;
}

/// Which boundary rule: one subdivision step, (a + 6v + b)/8, or the limit position, (a + 4v + b)/6.
enum class BoundaryRule { step, limit };

/// The boundary rules Catmull-Clark and Loop share: a corner (one face) or isolated vertex stays; a
/// boundary vertex v between its boundary neighbours a and b follows the cubic B-spline curve of
/// its boundary. Returns false, leaving `mask` alone, for an interior vertex.
bool boundary_mask(const MeshConnectivity& c, int v, BoundaryRule rule, VertexMask& mask);

/// The Catmull-Clark limit position of vertex v of a mesh whose faces around v are quads: interior
/// (n²v + 4Σe_i + Σf_i)/(n(n + 5)), e_i the edge neighbours and f_i the diagonals; else boundary_mask.
void catmull_clark_limit_mask(const PolygonTopology& t, const MeshConnectivity& c, int v, VertexMask& mask);
/// The interior (smooth) case of catmull_clark_limit_mask, whatever the vertex's boundary.
void catmull_clark_smooth_limit_mask(const PolygonTopology& t, const MeshConnectivity& c, int v, VertexMask& mask);

/// The Loop vertex point of one step: interior (1 − nβ)v + βΣn_i; else boundary_mask.
void loop_vertex_mask(const MeshConnectivity& c, int v, LoopBeta kind, VertexMask& mask);
/// The interior (smooth) case of loop_vertex_mask.
void loop_smooth_vertex_mask(const MeshConnectivity& c, int v, LoopBeta kind, VertexMask& mask);

/// The Loop limit position: interior (1 − nχ)v + χΣn_i with χ = 1/(3/(8β) + n); else boundary_mask.
void loop_limit_mask(const MeshConnectivity& c, int v, LoopBeta kind, VertexMask& mask);
/// The interior (smooth) case of loop_limit_mask.
void loop_smooth_limit_mask(const MeshConnectivity& c, int v, LoopBeta kind, VertexMask& mask);

}  // namespace gps
