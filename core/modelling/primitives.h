#pragma once
// Primitive shapes added to a mesh as a new part, the editor's Add menu.
//
// Like every modelling operation (core/modelling/mesh_arrays.h) this takes a mesh and returns a new
// one with a selection and a one-line summary, never changing its input; on refusal it throws
// gps::Error with a one-line reason and nothing is changed. The primitive's vertices and faces are
// appended; the existing mesh keeps its indices.
#include <optional>
#include <string>
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

enum class Primitive { plane, cube, cylinder, cone, sphere, torus };

/// "plane", "cube", "cylinder", "cone", "sphere", "torus", in the order of Primitive.
std::vector<std::string> primitive_names();
/// The primitive of that name, or none.
std::optional<Primitive> primitive_named(const std::string& name);

/// Adds the primitive, `size` (> 0) across its largest extent, its bounding box centred at `center`.
/// Y is up. plane: a 2×2 grid of quads facing +y; cube: 6 quads; cylinder: 8 side quads and two
/// octagon caps; cone: 8 triangles to the apex and an octagon base; sphere: a cube-sphere of 24 quads;
/// torus: 8×6 quads. All but the plane are closed; every face is oriented outward. Every vertex gets
/// the isotropic covariance σ²·I with σ half the primitive's mean edge length, as the built-in samples
/// (core/modelling/samples.h, isotropic_covariances). An empty input mesh (no vertices) is allowed.
/// Selection: the new vertices.
Modelled add_primitive(const CovarianceMesh& mesh, Primitive primitive, const Vec3& center, double size);
/// The same on arrays, for a run of additions that builds its mesh once (OperationList): appends the
/// primitive's vertices and faces, refusing its Gaussians as build_mesh would; returns the new
/// vertices and sets `summary`.
std::vector<int> append_primitive(MeshArrays& arrays, Primitive primitive, const Vec3& center, double size,
                                  std::string& summary);

/// Where the editor's Add menu puts a primitive: its centre and its size (as add_primitive takes them).
struct PrimitivePlacement {
  Vec3 center;
  double size = 1.0;
};
/// At the selected vertices' centre, a quarter of the mesh's bounding-box diagonal across. With
/// nothing selected, beside the mesh, clear of its bounding box along +x and half its largest extent
/// across, so that it is seen rather than hidden inside the surface. In an empty mesh: the origin, 2
/// across (Blender's default cube).
PrimitivePlacement primitive_placement(const CovarianceMesh& mesh, const std::vector<int>& selected);

}  // namespace gps
