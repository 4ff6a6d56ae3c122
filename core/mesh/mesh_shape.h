#pragma once
// A mesh's faces and their connectivity, held together. Made once and never changed after, so that
// copies of a mesh and what plans it (core/patches/local_mesh.h) share one instead of copying it.
#include <memory>
#include <vector>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

struct MeshShape;

/// Where a shape made from another by a change came from, as make_covariance_mesh found it while
/// carrying the other's connectivity over (core/mesh/connectivity_update.h): that shape, and per
/// vertex and per face of this one the element of that one it continues (−1: new). `from` is empty
/// where it is not known.
struct ShapeOrigin {
  std::weak_ptr<const MeshShape> from;
  std::vector<int> vertices, faces;
};

struct MeshShape {
  PolygonTopology topology;
  MeshConnectivity connectivity;
  ShapeOrigin origin;
};

/// A new shape, empty, whose connectivity's arrays are kept as the spare of the thread that lets the
/// shape's last copy go (core/mesh/spare_connectivity.h), for the next connectivity made from another.
std::shared_ptr<MeshShape> new_mesh_shape();

/// The shape of no faces and no vertices, shared by every empty mesh.
const std::shared_ptr<const MeshShape>& empty_mesh_shape();

}  // namespace gps
