#pragma once
// Polygon shapes (points and outward faces, no Gaussians) that both the editor's primitives
// (primitives.h) and the built-in samples (samples.h) are made of, each at its own size.
#include <vector>

#include "core/mesh/linalg.h"

namespace gps {

struct Shape {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
};

/// The cube [−1, 1]³: 8 corners, 6 quads.
Shape cube_shape();

/// A capped cylinder around the y axis: `rings` rings of `sides` points of radius `radius`, the first
/// at height `bottom` and each next `spacing` higher; quads between neighbouring rings and a
/// `sides`-gon cap at each end.
Shape cylinder_shape(int sides, int rings, double radius, double bottom, double spacing);

/// A cone around the y axis: its apex at height `apex` (point 0), a ring of `sides` points of radius
/// `radius` at height `base`, a triangle from each ring edge to the apex; with `closed`, a
/// `sides`-gon base.
Shape cone_shape(int sides, double radius, double apex, double base, bool closed);

/// A regular `sides`-gon of radius `radius` around the y axis in the plane y = 0: one face.
Shape polygon_shape(int sides, double radius);

/// A cube whose faces are m×m grids of quads, projected to the unit sphere (8 valence-3 vertices).
Shape cube_sphere_shape(int m);

/// A torus around the y axis: `around` × `across` quads, the tube's centre circle of radius `ring`,
/// the tube of radius `tube`.
Shape torus_shape(int around, int across, double ring, double tube);

}  // namespace gps
