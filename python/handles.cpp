#include "python/handles.h"

#include <new>

namespace gps::python {
namespace {

// The empty mesh and its plans, held without ownership (an aliasing shared_ptr with no control
// block): a handle made without __init__ points at them, and writing over it releases nothing.
const CovarianceMesh& empty_mesh() {
  static const CovarianceMesh mesh;
  return mesh;
}

template <class T>
std::shared_ptr<T> unowned(T& object) {
  return std::shared_ptr<T>(std::shared_ptr<void>(), &object);
}

}  // namespace

void* MeshHandle::operator new(size_t size) {
  void* storage = ::operator new(size);
  return ::new (storage) MeshHandle{unowned(empty_mesh())};
}

void* SurfaceHandle::operator new(size_t size) {
  static PlannedSurface empty_plans(empty_mesh(), Scheme::catmull_clark, SurfaceTables{});
  void* storage = ::operator new(size);
  return ::new (storage) SurfaceHandle{unowned(empty_plans), unowned(empty_mesh()), PlanOptions{}};
}

}  // namespace gps::python
