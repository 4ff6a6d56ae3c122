#include "app/plan_arguments.h"

#include "core/error.h"

namespace gps {

PlanOptions PlanArguments::options() const {
  PlanOptions o;
  if (scheme == "loop") o.scheme = Scheme::loop;
  else if (scheme == "catmull-clark") o.scheme = Scheme::catmull_clark;
  else if (scheme != "auto") throw usage_error("scheme must be auto, loop or catmull-clark, got '" + scheme + "'");
  if (loop_beta != "loop" && loop_beta != "warren") throw usage_error("loop-beta must be loop or warren, got '" + loop_beta + "'");
  o.loop_beta = loop_beta == "warren" ? LoopBeta::warren : LoopBeta::loop;
  if (depth < 0 || depth > 8) throw usage_error("depth must be 1..8, got " + std::to_string(depth));
  o.exact = depth == 0;
  if (depth > 0) o.depth = depth;
  return o;
}

void add_plan_arguments(CLI::App* cmd, PlanArguments& a) {
  cmd->add_option("--scheme", a.scheme, "subdivision scheme: auto (Loop for a mesh of triangles only, else Catmull-Clark), loop, catmull-clark")
      ->check(CLI::IsMember({"auto", "loop", "catmull-clark"}));
  cmd->add_option("--loop-beta", a.loop_beta, "Loop vertex weight: Loop's original or Warren's 3/(8n)")->check(CLI::IsMember({"loop", "warren"}));
  cmd->add_option("--depth", a.depth,
                  "Catmull-Clark: approximate extraordinary vertices with the thesis' Bezier plans of this depth 1..8 "
                  "(default: evaluate them exactly; Loop plans are always exact)")
      ->check(CLI::Range(1, 8));
}

}  // namespace gps
