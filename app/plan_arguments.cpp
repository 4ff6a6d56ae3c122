#include "app/plan_arguments.h"

#include "app/cli_checks.h"
#include "core/support/error.h"

namespace gps {

PlanOptions PlanArguments::options() const {
  // The options' own check, in the command line's words: --depth 0 is refused with --approximate alone.
  if (approximate && depth == 0) throw usage_error("--depth: with --approximate the depth is 1..8, got '0'");
  return plan_options_named(scheme, loop_beta, depth, approximate);
}

void add_plan_arguments(CLI::App* cmd, PlanArguments& a) {
  cmd->add_option(
         "--scheme", a.scheme,
         "subdivision scheme: auto (Loop for a mesh of triangles only, else Catmull-Clark), loop, catmull-clark")
      ->check(CLI::IsMember({"auto", "loop", "catmull-clark"}));
  cmd->add_option("--loop-beta", a.loop_beta, "Loop vertex weight: Loop's original or Warren's 3/(8n)")
      ->check(CLI::IsMember({"loop", "warren"}));
  cmd->add_option("--depth", a.depth,
                  "Catmull-Clark plan depth: where exact extraordinary nodes take over, 0..8 (default " +
                      std::to_string(kExactPlanDepth) +
                      "; deeper: more stencil rows, cheaper evaluation), or with --approximate the depth of the Bezier "
                      "patches, 1..8 "
                      "(default 3). Loop plans are always exact.")
      ->transform(integer_in(0, 8));
  cmd->add_flag("--approximate", a.approximate,
                "Catmull-Clark: the thesis' plans, Bezier patches approximating the surface at extraordinary vertices");
}

}  // namespace gps
