#include "render/exact_triangles.h"

#include <cstring>
#include <unordered_map>

#include "core/error.h"
#include "core/patch_eval.h"
#include "core/stencil_table.h"
#include "render/surface_renderer.h"

namespace gps {

TriangleMesh exact_triangles(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const Camera& camera, const DrawOptions& o,
                             int width, int height) {
  const std::vector<TessellatedVertex> captured = renderer.capture_vertices(camera, o, width, height);
  const PlanTables& tables = renderer.tables();
  const std::vector<Dual> points = apply_stencils(tables.stencils, base_points(mesh));
  // The triangles around a point each captured it: evaluated once per (patch, u, v), bit for bit.
  std::unordered_map<std::string, int> index;
  TriangleMesh out;
  out.triangles.resize(captured.size() / 3);
  for (size_t i = 0; i < out.triangles.size() * 3; ++i) {
    const TessellatedVertex& v = captured[i];
    std::string key(sizeof v.evaluated, '\0');
    std::memcpy(key.data(), v.evaluated, sizeof v.evaluated);
    auto [at, added] = index.try_emplace(std::move(key), int(out.positions.size()));
    if (added) {
      const auto s = evaluate_patch(tables.plans, points, int(v.evaluated[0]), v.evaluated[1], v.evaluated[2]);
      if (!s) throw Error("the exact evaluator has no limit at patch " + std::to_string(int(v.evaluated[0])) + " (" +
                          std::to_string(v.evaluated[1]) + ", " + std::to_string(v.evaluated[2]) + ")");
      out.positions.push_back(s->position);
      out.normals.push_back(s->normal);
    }
    out.triangles[i / 3][i % 3] = at->second;
  }
  return out;
}

}  // namespace gps
