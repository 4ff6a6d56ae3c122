#pragma once
// Exact limit tangents of subdivision vertices, for the reference's normals: two masks per vertex
// whose results span the limit surface's tangent plane there. Each mask is a left
// eigenvector of the local subdivision matrix for a subdominant eigenvalue, so applied to a
// vertex's ring at any level it gives the tangent of the limit surface at that vertex exactly.
// In 9D the masks give q_u, q_v, and thesis Eq. 3.12 (mean_derivative) takes them to 3D.
#include <vector>

#include "core/mesh/linalg.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/sharpness.h"
#include "core/reference/loop.h"
#include "core/reference/vertex_mask.h"

namespace gps {

/// Catmull-Clark, every face around v a quad. Interior (Halstead, Kass and DeRose 1993):
/// Σ_i A_n c_i e_i + (c_i + c_{i+1}) f_i with c_i = cos(2πi/n) (first) or sin(2πi/n) (second),
/// A_n = 1 + cos(2π/n) + cos(π/n)·√(2(9 + cos(2π/n))), e_i counter-clockwise, f_i between e_i and
/// e_{i+1}. A boundary vertex or corner: the eigenvectors of its ring's subdivision matrix under
/// the boundary rules, computed once per number of faces. first × second is the normal on the side
/// the faces' corners turn to (outward for counter-clockwise faces). False where there is no tangent plane to take
/// (isolated vertex, an open fan, eigenvalues not real or not separated).
bool catmull_clark_tangent_masks(const PolygonTopology& t, const MeshConnectivity& c, int v, VertexMask& first,
                                 VertexMask& second);

/// Loop, every face around v a triangle. Interior (Loop 1987): Σ_i cos(2πi/n) e_i and
/// Σ_i sin(2πi/n) e_i, e_i counter-clockwise (whatever β: the subdominant left eigenvectors do not
/// involve it). Boundary as for Catmull-Clark.
bool loop_tangent_masks(const PolygonTopology& t, const MeshConnectivity& c, int v, VertexMask& first,
                        VertexMask& second);

/// q_u and q_v (first and second mask applied to the 9D points p) at every vertex; zero where the
/// vertex has no masks. Under `creases` a dart of an infinitely sharp edge takes its own masks
/// (core/reference/dart_masks.h; Loop's with β `kind`); the other vertices the smooth ones.
void limit_tangents(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<Dual>& p, bool loop,
                    std::vector<Dual>& first, std::vector<Dual>& second, const CreaseLevel* creases = nullptr,
                    LoopBeta kind = LoopBeta::loop);

/// The unit limit normal μ_u × μ_v (thesis Eq. 3.12) at a vertex whose 9D limit is q, its mean
/// `mean`, from its tangents; zero where they are missing or degenerate.
Vec3 limit_normal(const Dual& q, const Vec3& mean, const Dual& first, const Dual& second);

}  // namespace gps
