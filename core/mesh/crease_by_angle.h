#pragma once
// Creases from the shape: edges where the surface folds by more than an angle become infinitely
// sharp, as Blender's "sharp by angle" marks them.
#include <array>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

/// The dihedral angle of every edge of the mesh in degrees, in the mesh's edge order: the angle between
/// the normals (Newell's, of the means) of its two faces, 0 for a flat edge, 180 for one folded back
/// on itself; −1 for a boundary edge or one beside a face without a normal (zero area).
std::vector<double> dihedral_angles(const CovarianceMesh& mesh);

/// The interior edges whose dihedral angle exceeds `degrees`, each as (min, max), ascending: what
/// Blender's "Select Sharp Edges" selects.
std::vector<std::array<int, 2>> edges_sharper_than(const CovarianceMesh& mesh, double degrees);

/// Makes every interior edge whose dihedral angle exceeds `degrees` infinitely sharp
/// (kInfiniteSharpness; a sharper value stays); returns how many edges that is.
int crease_by_angle(CovarianceMesh& mesh, double degrees);

}  // namespace gps
