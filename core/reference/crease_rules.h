#pragma once
// Semi-sharp creases and corners (DeRose, Kass, Truong 1998) as OpenSubdiv's Sdc applies them with its
// uniform crease method and EDGE_AND_CORNER boundaries (docs/design.md §1 "Creases and corners"):
// which rule a vertex follows, the weights that blend a rule with the next level's, and the
// sharpness one level finer. Catmull-Clark and Loop share all of it; only their smooth masks differ.
#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/sharpness.h"
#include "core/reference/vertex_mask.h"

namespace gps {

/// Sdc's vertex rules: no sharp edge (smooth), one (dart, subdivided as smooth), two (crease:
/// the cubic B-spline of the crease curve), more than two or a sharp vertex (corner: it stays).
enum class VertexRule { smooth, dart, crease, corner };

/// Edge e's sharpness as the rules read it: a boundary edge is infinitely sharp. `level` may be
/// empty (no sharpness anywhere).
double edge_sharpness(const MeshConnectivity& c, const CreaseLevel& level, int e);

/// Vertex v's sharpness as the rules read it: a vertex with at most one face (a boundary corner)
/// is infinitely sharp.
double vertex_sharpness(const MeshConnectivity& c, const CreaseLevel& level, int v);

/// The rule at v under `level`; for a crease, a and b get the other ends of its two sharp edges
/// (in vertex_edges order). Boundary vertices are creases along their boundary or corners.
VertexRule vertex_rule(const MeshConnectivity& c, const CreaseLevel& level, int v, int* a = nullptr, int* b = nullptr);

/// How one subdivision step moves vertex v: the rule under the parent's sharpness, the rule under
/// the sharpness one level finer, and where they differ the weight of the parent's rule
/// (Sdc::Crease::ComputeFractionalWeightAtVertex: the mean of the parent sharpnesses of the edges
/// and vertex that decay to smooth in this step, at most 1); the point is
/// parent_weight · parent mask + (1 − parent_weight) · child mask.
struct VertexPointRule {
  VertexRule parent = VertexRule::smooth, child = VertexRule::smooth;
  int parent_a = -1, parent_b = -1;  // crease neighbours under the parent rule
  int child_a = -1, child_b = -1;    // crease neighbours under the child rule
  double parent_weight = 1.0;        // 1 where the two rules are the same
};
VertexPointRule vertex_point_rule(const MeshConnectivity& c, const CreaseLevel& level, int v);

/// The weight of the crease rule (the midpoint) in edge e's edge point, min(s, 1) for its sharpness
/// s (boundary edges 1); the smooth rule has the rest.
double edge_crease_weight(const MeshConnectivity& c, const CreaseLevel& level, int e);

/// The mask of a crease or corner vertex: corner v; crease (a + 6v + b)/8 for one step, or its limit
/// (a + 4v + b)/6. Smooth and dart vertices have their scheme's own masks.
void sharp_vertex_mask(VertexRule rule, int v, int a, int b, BoundaryRule step_or_limit, VertexMask& mask);

/// The sharpness one level finer, numbered as the child connectivity `child` (both schemes keep the
/// vertex indices and give edge e's point index t.n_vertices + e): the two halves of a parent edge
/// get decayed_sharpness of it, new interior edges 0, vertex points the decayed corner sharpness,
/// edge and face points 0. An empty parent gives an empty level.
CreaseLevel refined_crease_level(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& parent,
                                 const MeshConnectivity& child);

/// The sharpness of `level` as a mesh carries it (edge creases by their vertices, corners).
Sharpness sharpness_of(const MeshConnectivity& c, const CreaseLevel& level);

}  // namespace gps
