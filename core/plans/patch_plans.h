#pragma once
// Subdivision plans and the stencil table: the real-time representation of the GPS limit surface
// (thesis 2.3, docs/design.md §2 steps 2–3). Flat arrays of 32-bit ints and floats that a GPU reads as
// they are; built once per topology by plan_builder.h.
//
// Points. The plans read an array of 9D points: points [0, n_base) are the base vertices' dual
// vectors q_i; point first_row() + r is row r of the stencil table, Σ_k weights[k] · q[indices[k]] over
// k in [offsets[r], offsets[r+1]). A whole surface's rows start past a gap of unused points
// (row_start_for), so that an operation that adds or removes a few base vertices leaves every row's
// point index, and so the plans that read it, as they were.
//
// Nodes. nodes[] holds one record per quadtree node, addressed by its offset:
//   nodes[o] = kind (NodeKind) | boundary << kNodeKindBits (core/patches/patch_basis.h: a regular quad
//             leaf's boundary edges, whose phantom points its basis takes in; 0 for every other)
//   internal: nodes[o+1 .. o+4] = offsets of the four children, child c = ubit + 2·vbit, where
//             ubit = (u ≥ ½), vbit = (v ≥ ½) in the node's own [0,1]² domain;
//   regular:  nodes[o+1 .. o+16] = point indices of a bicubic B-spline patch, index i + 4·j with
//             i along u and j along v; the patch spans the middle cell [1,2]² of the 4×4 net; beyond
//             a boundary edge the slots repeat the points next to them;
//   terminal: nodes[o+1 .. o+16] = point indices of a bicubic Bézier patch (thesis Fig. 2.5
//             rules baked into the stencils), same i + 4·j order.
// A node at depth k covers a square of side 2^-k of its patch; its domain is rescaled to [0,1]²,
// so derivatives in patch parameters are 2^k times the node's.
//
// Triangle plans (Loop, core/plans/loop_plan_builder.h) use the same arrays with triangle nodes over
// parameters (u, v), barycentrics (1−u−v, u, v):
//   internal: nodes[o+1 .. o+4] = the four children of triangle_child() (core/patches/patch_basis.h);
//   regular:  nodes[o+1 .. o+12] = the 12 control points of Loop's box-spline patch, in the
//             order of loop_box_spline_basis();
//   extraordinary: nodes[o+1] = r, the corner of the node at the extraordinary vertex;
//             nodes[o+2] = offset of its table in extraordinary_tables; nodes[o+3] = K; nodes[o+4 .. o+3+K]
//             = the K points of its neighbourhood (core/extraordinary/loop_extraordinary_tables.h), evaluated exactly.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/patches/patch_basis.h"

namespace gps {

enum class NodeKind : int32_t {
  internal = kNodeInternal,
  regular = kNodeRegular,
  terminal = kNodeTerminal,
  extraordinary = kNodeExtraordinary
};

/// The shape of the patches of a plan: quads (Catmull-Clark) or triangles (Loop).
enum class PatchShape : int32_t { quad = 4, triangle = 3 };

struct StencilTable {
  int32_t n_base = 0;            // number of base vertices (points that are q_i themselves)
  int32_t row_gap = 0;           // unused points between the base vertices and the first row
  std::vector<int32_t> offsets;  // n_rows + 1 entries
  std::vector<int32_t> indices;  // base-vertex indices
  std::vector<double> weights;   // double for the CPU reference; the GPU gets a float copy
  int32_t n_rows() const { return offsets.empty() ? 0 : int32_t(offsets.size()) - 1; }
  int32_t first_row() const { return n_base + row_gap; }
  int32_t n_points() const { return first_row() + n_rows(); }
};

/// The point index of the first row of a whole surface's tables over `n_base` base vertices: n_base
/// rounded up to a multiple of kRowStartStep, a function of n_base alone, so that tables built whole
/// and tables kept through changes number their points alike.
inline constexpr int32_t kRowStartStep = 1024;
inline int32_t row_start_for(int32_t n_base) { return (n_base + kRowStartStep - 1) / kRowStartStep * kRowStartStep; }

struct PatchPlans {
  PatchShape shape = PatchShape::quad;
  int32_t max_depth = 0;                     // of the deepest node
  std::vector<int32_t> nodes;                // node records, see above
  std::vector<int32_t> patch_roots;          // per patch: offset of its root node in nodes
  std::vector<int32_t> patch_corner_points;  // 4 (quads) or 3 (triangles) per patch: points whose means
                                             // are the corners of the patch's control polygon (for edge
                                             // tessellation levels); a corner shared by two patches has
                                             // the same index in both
  std::vector<int32_t> patch_edges;          // quads: 4 × 3 per patch, see PatchEdgePart
  std::vector<int32_t> patch_neighbours;     // 4 per patch edge and corner_owners 2 per patch corner:
  std::vector<int32_t> corner_owners;        // core/plans/patch_adjacency.h (build_surface_plans fills them)
  std::vector<double> extraordinary_tables;  // triangles: the tables of core/extraordinary/loop_extraordinary_tables.h
  int32_t corners() const { return int32_t(shape); }
  int32_t n_patches() const { return int32_t(patch_roots.size()); }
};

/// Patch edge k of a patch runs from its corner k to corner k+1 and is described by three ints in
/// PatchPlans::patch_edges[kPatchEdgeStride·patch + kPatchEdgeInts·k ...]: the points whose means are the two ends of
/// the edge of the (base or split-face) mesh it lies on, in the patch edge's direction, and its part of that edge. A
/// quad next to a split face meets two half-size patches along one edge (a T-junction): it gives that edge an even
/// tessellation level and each half takes half of it, so the vertices of both sides sit at the same parameters of the
/// same limit curve (core/plans/patch_layout.h).
enum class PatchEdgePart : int32_t {
  whole = kEdgeWhole,                            // all of the edge, and so is the patch beside it
  whole_beside_halves = kEdgeWholeBesideHalves,  // all of the edge; the other side is split into two halves
  first_half = kEdgeFirstHalf,                   // the half at `from`: the patch edge runs from `from` to the midpoint
  second_half = kEdgeSecondHalf,                 // the half at `to`: the patch edge runs from the midpoint to `to`
};

struct PatchEdge {
  int32_t from, to;
  PatchEdgePart part;
};

inline PatchEdge patch_edge(const PatchPlans& plans, int patch, int k) {
  const int32_t* e = &plans.patch_edges[size_t(kPatchEdgeStride * patch + kPatchEdgeInts * k)];
  return {e[0], e[1], PatchEdgePart(e[2])};
}

/// Calls `point(int32_t&)` on every point index the plans' records hold: the points of the leaves and
/// of the extraordinary nodes, the patch corner points and the ends of the patch edges (never a child
/// offset, a table offset or an edge part).
template <class Point>
void for_each_point(PatchPlans& plans, Point&& point) {
  const size_t leaf_points = plans.shape == PatchShape::quad ? 16 : 12;
  std::vector<int32_t>& nodes = plans.nodes;
  for (size_t o = 0; o < nodes.size();) {
    const auto kind = NodeKind(node_kind(nodes[o]));
    if (kind == NodeKind::extraordinary) {  // corner, table, K, K points
      const size_t k = size_t(nodes[o + 3]);
      for (size_t i = o + 4; i < o + 4 + k; ++i) point(nodes[i]);
      o += 4 + k;
      continue;
    }
    const size_t n = kind == NodeKind::internal ? 4 : leaf_points;
    if (kind != NodeKind::internal)
      for (size_t i = o + 1; i <= o + n; ++i) point(nodes[i]);
    o += n + 1;
  }
  for (int32_t& q : plans.patch_corner_points) point(q);
  for (size_t i = 0; i < plans.patch_edges.size(); i += kPatchEdgeInts) {  // from, to, part
    point(plans.patch_edges[i]);
    point(plans.patch_edges[i + 1]);
  }
}

/// Whether the patch is one of a split face's half-size patches (quads).
inline bool half_size_patch(const PatchPlans& plans, int patch) {
  return plans.shape == PatchShape::quad && half_size_part(plans.patch_edges[size_t(kPatchEdgeStride * patch + 2)]);
}

/// Whether the plan below `node` holds an extraordinary node (its evaluation may take the exact
/// branch; every other evaluates a regular or terminal leaf).
inline bool holds_extraordinary_node(const PatchPlans& plans, int32_t node) {
  const int kind = node_kind(plans.nodes[size_t(node)]);
  if (kind != kNodeInternal) return kind == kNodeExtraordinary;
  for (size_t child = 1; child <= 4; ++child)
    if (holds_extraordinary_node(plans, plans.nodes[size_t(node) + child])) return true;
  return false;
}

}  // namespace gps
