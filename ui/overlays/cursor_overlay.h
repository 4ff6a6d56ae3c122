#pragma once
// The 3D cursor over the view: a point in space that transforms turn about, and where new primitives
// are added, drawn as Blender draws it (a red and white ring with a cross).
#include "view/projection.h"

struct ImDrawList;

namespace gps {

/// Draws the 3D cursor at `point` (nothing where it lies behind the eye).
void draw_cursor_overlay(ImDrawList& draw, const Viewport& view, const Vec3& point);

}  // namespace gps
