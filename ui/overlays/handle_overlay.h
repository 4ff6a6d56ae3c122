#pragma once
// Drawing the gizmo over the 3D view (Dear ImGui draw lists); the selected vertices' dots are drawn
// on the GPU (render/overlays/vertex_dots.h).
#include <optional>

#include "ui/editing/axis_handles.h"

struct ImDrawList;

namespace gps {

/// The gizmo: both ends of each axis of `gizmo` (red, green, blue by axis index: during a drag the
/// index stays the grabbed one's) joined to the white centre dot; the `hovered` (or dragged) handle
/// is drawn lit.
void draw_handle_overlay(ImDrawList& draw, const Viewport& view, const std::optional<HandleFrame>& gizmo,
                         const std::optional<Handle>& hovered);

}  // namespace gps
