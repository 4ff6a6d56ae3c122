#include "render/comparison/exact_triangles.h"

#include <string>

#include "core/support/error.h"
#include "core/evaluation/patch_eval.h"
#include "core/plans/stencil_table.h"
#include "render/comparison/patch_triangles.h"
#include "render/pipeline/surface_renderer.h"

namespace gps {

PlacedTriangles exact_triangles(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const Camera& camera,
                                const DrawOptions& o, int width, int height) {
  const SurfaceTables& tables = renderer.tables();
  const Vec3 origin = evaluation_origin(mesh);
  const std::vector<Dual> points = apply_stencils(tables.stencils, base_points(mesh, origin));
  const auto exact_at = [&](int patch, double u, double v) {
    const auto s = evaluate_patch(tables.plans, points, patch, u, v);
    if (!s)
      throw Error("the exact evaluator has no limit at patch " + std::to_string(patch) + " (" + std::to_string(u) +
                  ", " + std::to_string(v) + ")");
    return SurfaceValues{s->position, s->normal};
  };
  return {patch_triangles(renderer, camera, o, width, height, exact_at), origin};
}

}  // namespace gps
