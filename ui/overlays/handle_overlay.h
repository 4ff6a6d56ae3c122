#pragma once
// Drawing the selection and the gizmo over the 3D view (Dear ImGui draw lists).
#include <optional>
#include <vector>

#include "ui/editing/axis_handles.h"

struct ImDrawList;

namespace gps {

/// A dot on every selected vertex, and the gizmo: both ends of each axis of `gizmo` (red, green,
/// blue by axis index: during a drag the index stays the grabbed one's) joined to the white centre
/// dot; the `hovered` (or dragged) handle is drawn lit.
void draw_handle_overlay(ImDrawList& draw, const Viewport& view, const CovarianceMesh& mesh,
                         const std::vector<int>& selected, const std::optional<HandleFrame>& gizmo,
                         const std::optional<Handle>& hovered);

}  // namespace gps
