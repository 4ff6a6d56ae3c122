#pragma once
// Splitting faces off the rest of the mesh, as Blender's Split (Y) and Separate (P) do: the faces
// become a part of their own, joined to nothing.
//
// Like every modelling operation (core/modelling/mesh_arrays.h) this takes a mesh and returns a new
// one with a selection and a one-line summary, never changing its input; on refusal it throws
// gps::Error with a one-line reason and nothing is changed.
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Detaches the faces (checked) from the others: every vertex the faces share with the other faces
/// is duplicated, the copy (appended, with the same Gaussian and corner sharpness) taken by the faces
/// of one fan of them around it, so that each side keeps a manifold border; where the other faces
/// meet at such a vertex in more than one fan (they touched only there once the faces are gone),
/// every fan after its first gets a copy too. No face is added, removed or turned; a crease on a cut
/// edge stays on both sides. Refuses no faces, every face (nothing to split from) and faces that
/// share no vertex with the rest (a part of their own already). Selection: the split faces' vertices.
Modelled split_faces(const CovarianceMesh& mesh, const std::vector<int>& faces);

}  // namespace gps
