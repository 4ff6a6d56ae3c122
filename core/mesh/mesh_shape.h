#pragma once
// A mesh's faces and their connectivity, held together. Made once and never changed after, so that
// copies of a mesh and what plans it (core/patches/local_mesh.h) share one instead of copying it.
#include <memory>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

struct MeshShape {
  PolygonTopology topology;
  MeshConnectivity connectivity;
};

/// The shape of no faces and no vertices, shared by every empty mesh.
const std::shared_ptr<const MeshShape>& empty_mesh_shape();

}  // namespace gps
