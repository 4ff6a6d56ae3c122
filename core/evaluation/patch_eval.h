#pragma once
// CPU evaluation of the plans, written to mirror the evaluation shader line for line
// (docs/design.md §2 step 6): descend to the node under (u, v), evaluate q, q_u, q_v in 9D, map back.
#include <optional>
#include <vector>

#include "core/mesh/dual_map.h"
#include "core/plans/patch_plans.h"

namespace gps {

struct PatchSample {
  Dual q, q_u, q_v;  // in patch parameters
  Vec3 position;
  Mat3 covariance;
  Vec3 du, dv;    // μ_u, μ_v (thesis Eq. 3.12)
  Vec3 normal;    // normalize(μ_u × μ_v)
  int depth = 0;  // of the leaf node
  NodeKind kind = NodeKind::regular;
};

/// q and its derivatives at (u, v) of a patch; `points` are all plan points (apply_stencils()).
void evaluate_dual(const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u, double v, Dual& q,
                   Dual& q_u, Dual& q_v, int* depth = nullptr, NodeKind* kind = nullptr);

/// The limit surface at (u, v) of a patch. Empty if q̂ left the positive definite cone.
std::optional<PatchSample> evaluate_patch(const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u,
                                          double v);

}  // namespace gps
