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
  Vec3 normal;    // normalize(μ_u × μ_v); where they run parallel, evaluate_patch's fold normal
  int depth = 0;  // of the leaf node
  NodeKind kind = NodeKind::regular;
};

/// q and its derivatives at (u, v) of a patch; `points` are all plan points (apply_stencils()).
void evaluate_dual(const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u, double v, Dual& q,
                   Dual& q_u, Dual& q_v, int* depth = nullptr, NodeKind* kind = nullptr);

/// Tangents whose cross product is at most this much of their lengths' product: parallel, the cross
/// product's direction rounding alone.
constexpr double kParallelSine = 1e-4;
bool tangents_parallel(const Vec3& du, const Vec3& dv);
/// Where the tangents run parallel the parametrisation folds (a patch corner between two edges in one
/// line, as at the vertex that splits a boundary edge, a corner of one face): the normal there is that
/// a step of this much of the way towards the patch's centre (u = v = ½, or ⅓ on a triangle), which
/// tends to the surface's normal as the step shrinks. The GPU's corner pass takes the same step
/// (shaders/corner_limit_comp.glsl).
constexpr double kFoldStep = 1.0 / 256.0;

/// The limit surface at (u, v) of a patch. Empty if q̂ left the positive definite cone. Where the
/// tangents run parallel, the normal a kFoldStep towards the centre, or zero where there too.
std::optional<PatchSample> evaluate_patch(const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u,
                                          double v);

}  // namespace gps
