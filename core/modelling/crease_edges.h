#pragma once
// Marking edges as creases and vertices as corners (OpenSubdiv's semi-sharp sharpness, docs/design.md §1
// "Creases and corners"), as Blender's Edge Crease and Vertex Crease do: the topology and the Gaussians
// stay as they are.
#include <array>
#include <string>
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Gives every listed edge the sharpness (0 makes it smooth; kInfiniteSharpness and above sharp at
/// every level). Selects the edges' vertices. Throws gps::Error for a sharpness that is negative or
/// not finite, a vertex out of range or a pair that is not an edge ("edge 2–7 is not in the mesh").
Modelled set_crease(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges, double sharpness);
/// The same on `mesh` itself, at the cost of the edges (each found among its ends' edges): returns the
/// selection and sets `summary`; a refusal changes nothing.
std::vector<int> set_crease_in_place(CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                                     double sharpness, std::string& summary);

/// Gives every interior edge whose dihedral angle exceeds `degrees` (0 ≤ degrees < 180; the angle
/// between its faces' normals, core/mesh/crease_by_angle.h) the sharpness, as Blender's Select Sharp
/// Edges then Edge Crease: the Gaussians stay as they are. Selects the edges' vertices. Throws as
/// set_crease, and for an angle outside that range.
Modelled crease_sharp_edges(const CovarianceMesh& mesh, double degrees, double sharpness);

/// Gives every listed vertex the corner sharpness (0 removes it); selects them. Throws as set_crease.
Modelled set_corner(const CovarianceMesh& mesh, const std::vector<int>& vertices, double sharpness);
/// The same on `mesh` itself, at the cost of the vertices: returns the selection and sets `summary`.
std::vector<int> set_corner_in_place(CovarianceMesh& mesh, const std::vector<int>& vertices, double sharpness,
                                     std::string& summary);

}  // namespace gps
