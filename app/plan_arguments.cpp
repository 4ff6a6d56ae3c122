#include "app/plan_arguments.h"

#include "core/mesh/error.h"

namespace gps {

PlanOptions PlanArguments::options() const {
  PlanOptions o;
  if (scheme == "loop")
    o.scheme = Scheme::loop;
  else if (scheme == "catmull-clark")
    o.scheme = Scheme::catmull_clark;
  else if (scheme != "auto")
    throw usage_error("scheme must be auto, loop or catmull-clark, got '" + scheme + "'");
  if (loop_beta != "loop" && loop_beta != "warren")
    throw usage_error("loop-beta must be loop or warren, got '" + loop_beta + "'");
  o.loop_beta = loop_beta == "warren" ? LoopBeta::warren : LoopBeta::loop;
  o.exact = !approximate;
  if (approximate) o.depth = 3;
  if (depth >= 0) o.depth = depth;
  if (o.depth < (approximate ? 1 : 0) || o.depth > 8)
    throw usage_error("depth must be " + std::string(approximate ? "1" : "0") + "..8, got " + std::to_string(depth));
  return o;
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
      ->check(CLI::Range(0, 8));
  cmd->add_flag("--approximate", a.approximate,
                "Catmull-Clark: the thesis' plans, Bezier patches approximating the surface at extraordinary vertices");
}

}  // namespace gps
