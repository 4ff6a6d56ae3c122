#include "core/mesh/mesh_shape.h"

#include "core/mesh/spare_connectivity.h"

namespace gps {

std::shared_ptr<MeshShape> new_mesh_shape() {
  return std::shared_ptr<MeshShape>(new MeshShape(), [](MeshShape* shape) {
    keep_spare_connectivity(std::move(shape->connectivity));
    delete shape;
  });
}

const std::shared_ptr<const MeshShape>& empty_mesh_shape() {
  static const std::shared_ptr<const MeshShape> empty = std::make_shared<const MeshShape>();
  return empty;
}

}  // namespace gps
