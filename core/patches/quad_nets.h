#pragma once
// The control nets of Catmull-Clark patches over a piece of a subdivided mesh (core/patches/local_mesh.h):
// the 4×4 B-spline net of a regular quad and the Bézier net of a terminal node (thesis Fig. 2.5).
#include <array>
#include <utility>
#include <vector>

#include "core/patches/local_mesh.h"

namespace gps {

/// A point as a combination of the vertices of a LocalMesh (before it becomes a base stencil).
using LocalCombination = std::vector<std::pair<int, double>>;

/// Corner k of face f (k taken cyclically).
int face_vertex(const LocalMesh& m, int f, int k);
/// The corner of face f at vertex v.
int corner_index(const LocalMesh& m, int f, int v);
/// The face across edge e from face f, or −1 on the boundary.
int other_face(const LocalMesh& m, int e, int f);

/// Interior valence 4, boundary with two faces, or a corner with one face; all faces around quads.
bool regular_vertex(const LocalMesh& m, int v);

/// Whether vertex v is a regular corner of the bicubic patch of quad face q: as regular_vertex where
/// the mesh has no sharpness. With sharpness, v must have no semi-sharp edge or corner, and its
/// sector (the faces reached from q around v without crossing a boundary or an infinitely sharp
/// crease) must be quads, four of them around a smooth vertex, two where v has the crease rule and
/// one where it has the corner rule: then the sector is the regular boundary patch of the mesh cut
/// along its creases, whose rules at v are the crease (or corner) rules.
bool regular_corner(const LocalMesh& m, int v, int q);

/// The 4×4 B-spline net of quad q with corners c (all regular), net index i + 4j with i along the
/// edge c[0] → c[1]; boundary phantoms p₋₁ = 2p₀ − p₁, also beyond an infinitely sharp crease. Written into `net`, whose vectors keep
/// their capacity: a builder that reuses one allocates nothing per regular leaf.
void bspline_net(const LocalMesh& m, int q, const std::array<int, 4>& c, std::array<LocalCombination, 16>& net);

/// The Bézier net of a terminal node with corners c by the rules of thesis Fig. 2.5 (docs/design.md §2).
std::array<LocalCombination, 16> bezier_net(const LocalMesh& m, const std::array<int, 4>& c);

}  // namespace gps
