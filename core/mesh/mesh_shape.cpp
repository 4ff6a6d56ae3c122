#include "core/mesh/mesh_shape.h"

namespace gps {

const std::shared_ptr<const MeshShape>& empty_mesh_shape() {
  static const std::shared_ptr<const MeshShape> empty = std::make_shared<const MeshShape>();
  return empty;
}

}  // namespace gps
