#pragma once
// Which patches a polygon mesh has and how their (u, v) domains sit on its faces (DESIGN.md §2 step 1).
//
// Patches are numbered in base-face order. In a mesh of quads only, each face is one patch: its
// corners, in the order face_vertices() returns them, sit at (u, v) = (0,0), (1,0), (1,1), (0,1).
// In a mesh with any face that is not a quad, every face with n vertices c_0..c_{n-1} (quads too)
// is n patches, after one Catmull-Clark step: patch first_patch(f) + k is the quad
// (c_k', e'(c_k, c_{k+1}), f', e'(c_{k-1}, c_k)) — vertex point, edge point, face point, edge
// point — with the same corner placement. Splitting the quads too keeps patch edges matched one to
// one (no T-junction between a quad's patch and the half-size patches of its n-gon neighbour), so
// tessellation stays crack-free (a deviation from DESIGN.md §2 step 1, which splits n-gons only).
#include <vector>

#include "core/covariance_mesh.h"

namespace gps {

/// A point on the limit surface named by patch and parameters in [0,1]².
struct PatchParam {
  int patch = -1;
  double u = 0.0;
  double v = 0.0;
};

/// The vertices of a face in the one order every part of gpsurf uses (OpenMesh's face-vertex order).
std::vector<int> face_vertices(const PolyMesh& mesh, PolyMesh::FaceHandle f);

/// Patch numbering of a mesh: first patch per face and the total.
struct PatchLayout {
  std::vector<int> first_patch;  // per face, plus one entry at the end holding the total
  int n_patches() const { return first_patch.empty() ? 0 : first_patch.back(); }
};

PatchLayout make_patch_layout(const PolyMesh& mesh);

/// Whether every face of the mesh is a quad (then each face is one patch, unsplit).
bool is_quad_mesh(const PolyMesh& mesh);

}  // namespace gps
