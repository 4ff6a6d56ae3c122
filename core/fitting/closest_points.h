#pragma once
// Closest points on a GPS limit surface, as surface parameters (patch, u, v): the correspondences of
// subdivision-surface fitting (Marinov and Kobbelt 2005).
#include <vector>

#include "core/mesh/linalg.h"
#include "core/plans/patch_plans.h"

namespace gps {

/// A point of a limit surface by its parameters, and its distance from the point it answers.
struct SurfacePoint {
  int patch = 0;
  double u = 0, v = 0;
  double distance = 0;
};

/// Where each of `targets` lies closest to the limit surface of `plans` over the plan points `points`
/// (apply_stencils): the closest point of every patch tessellated at `level` (an AABB tree, CGAL),
/// its parameters interpolated (or a corner of its triangle where nearer), then up to
/// `projection_steps` Gauss-Newton steps on its patch (clamped to the patch's domain, each halved
/// until it brings it closer). Where that point lies twice as far as the tessellation, the patches
/// of the triangles around it are tried too, the nearest kept. On all cores, the same on any number.
/// Throws gps::Error if the surface leaves the cone of positive definite matrices.
std::vector<SurfacePoint> closest_limit_points(const PatchPlans& plans, const std::vector<Dual>& points,
                                               const std::vector<Vec3>& targets, int level, int projection_steps = 6);

/// The point at (u, v) of a patch clamped into its domain: [0,1]² (quads) or u, v ≥ 0, u + v ≤ 1 (triangles).
void clamp_to_patch(PatchShape shape, double& u, double& v);

}  // namespace gps
