#pragma once
// Adjust last operation (F9, as Blender's): a panel with the numbers of the last operation a tool made
// (a bevel's width, segments and profile; a spin's angle and steps; a grid fill's span and offset; an
// extrusion's or duplication's move; an inset's thickness and depth; a loop cut's number of cuts and
// slide), each kept within its range.
#include <optional>
#include <vector>

#include "ui/editing/adjustable_operation.h"

namespace gps {

/// Draws the panel while `shown` (its close box clears it): `operation`'s numbers, or where there is
/// none to adjust (nullptr) a line saying which operations can be. The numbers once one was changed
/// and entered, else none.
std::optional<std::vector<double>> draw_adjust_last_panel(bool& shown, const AdjustableOperation* operation);

}  // namespace gps
