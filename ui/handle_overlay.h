#pragma once
// Drawing the selection and the ellipsoid-axis handles over the 3D view (Dear ImGui draw lists).
#include <optional>
#include <vector>

#include "ui/axis_handles.h"

struct ImDrawList;

namespace gps {

/// A dot on every selected vertex, and for `handle_vertices` their handles: both ends of each axis
/// (red, green, blue by ascending σ) joined to the white centre dot; `hovered` is drawn lit.
void draw_handle_overlay(ImDrawList& draw, const Viewport& view, const CovarianceMesh& mesh, const std::vector<int>& selected,
                         const std::vector<int>& handle_vertices, double k_sigma, const std::optional<Handle>& hovered);

}  // namespace gps
