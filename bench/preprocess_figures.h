#pragma once
// `gpsurf bench --preprocess`: plan building and stencil application for one sample mesh.
#include <nlohmann/json.hpp>
#include <string>

#include "core/plans/planned_surface.h"

namespace gps {

/// Median times of building the plans, the dual map, applying every stencil and updating the rows
/// of one vertex, with the tables' sizes, for sample `name` at `size` faces (0: its default).
nlohmann::json preprocess_figures(const std::string& name, int size, const PlanOptions& options);

}  // namespace gps
