#pragma once
// The 3D cursor (as Blender's): a point the user places (Shift+right click on the surface or at its
// depth, Shift+S to the selection, Shift+C to the origin), the pivot TransformPivot::cursor and, once
// placed, where new primitives go.
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "core/mesh/linalg.h"
#include "view/projection.h"

namespace gps {

struct Cursor3D {
  Vec3 point = Vec3::Zero();
  bool placed = false;

  /// Places the cursor at `point`; the status line that says where ("3D cursor at the world origin
  /// (0, 0, 0)", `how` being "at the world origin").
  std::string place(const Vec3& point, const std::string& how);

  /// Where the ray through `pixel` meets the plane through the cursor facing the view, which keeps the
  /// cursor's depth; none where the ray runs along that plane.
  std::optional<Vec3> at_its_depth(const Viewport& view, glm::vec2 pixel) const;
};

}  // namespace gps
