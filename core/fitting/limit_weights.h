#pragma once
// The limit surface at one (patch, u, v) as weights over the control vertices: q, q_u and q_v are
// linear in the vertices' 9D points (docs/design.md §1), so each is a sparse weighted sum of them.
#include <vector>

#include "core/mesh/linalg.h"
#include "core/plans/patch_plans.h"

namespace gps {

/// q(u, v) = Σₖ value[k] · q[vertex[k]], and likewise q_u with du, q_v with dv; vertices sorted, without repeats.
struct LimitWeights {
  std::vector<int> vertex;
  std::vector<double> value, du, dv;
  size_t size() const { return vertex.size(); }
};

/// The weights of evaluate_dual (core/evaluation/patch_eval.h) at (u, v) of `patch`, over the base
/// vertices: the plan's basis weights of its plan points, composed with the stencil rows that make them.
LimitWeights limit_weights(const PatchPlans& plans, const StencilTable& stencils, int patch, double u, double v);

/// Σₖ value[k] · points[vertex[k]] and the same for du, dv.
void apply_limit_weights(const LimitWeights& weights, const std::vector<Dual>& points, Dual& q, Dual& q_u, Dual& q_v);

}  // namespace gps
