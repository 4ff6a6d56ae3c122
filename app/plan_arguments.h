#pragma once
// The command-line options that choose a mesh's plans: --scheme, --loop-beta, --depth.
#include <CLI/CLI.hpp>
#include <string>

#include "core/plans/planned_surface.h"

namespace gps {

struct PlanArguments {
  std::string scheme = "auto", loop_beta = "loop";
  int depth = -1;            // −1: the default of the plans asked for
  bool approximate = false;  // the thesis' Bézier plans instead of exact extraordinary nodes
  /// The options these name; throws a usage error for an unknown name (scripts are not checked by CLI11).
  PlanOptions options() const;
};

/// Adds --scheme auto|loop|catmull-clark, --loop-beta loop|warren and --depth and --approximate to `cmd`.
void add_plan_arguments(CLI::App* cmd, PlanArguments& arguments);

}  // namespace gps
