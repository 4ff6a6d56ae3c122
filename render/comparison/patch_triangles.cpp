#include "render/comparison/patch_triangles.h"

#include <cstring>
#include <string>
#include <unordered_map>

#include "render/pipeline/surface_renderer.h"

namespace gps {

TriangleMesh patch_triangles(SurfaceRenderer& renderer, const Camera& camera, const DrawOptions& o, int width,
                             int height, const SurfaceAt& surface_at) {
  const std::vector<TessellatedVertex> captured = renderer.capture_vertices(camera, o, width, height);
  // The triangles around a point each captured it: given values once per (patch, u, v), bit for bit.
  std::unordered_map<std::string, int> index;
  TriangleMesh out;
  out.triangles.resize(captured.size() / 3);
  for (size_t i = 0; i < out.triangles.size() * 3; ++i) {
    const TessellatedVertex& v = captured[i];
    std::string key(sizeof v.evaluated, '\0');
    std::memcpy(key.data(), v.evaluated, sizeof v.evaluated);
    auto [at, added] = index.try_emplace(std::move(key), int(out.positions.size()));
    if (added) {
      // On a crease the vertex's own side, whose position the CPU's doubles give to rounding.
      const SurfaceValues s = v.on_crease() ? surface_at(int(v.patch), v.u, v.v)
                                            : surface_at(int(v.evaluated[0]), v.evaluated[1], v.evaluated[2]);
      out.positions.push_back(s.position);
      out.normals.push_back(s.normal);
    }
    out.triangles[i / 3][i % 3] = at->second;
  }
  fill_missing_normals(out);
  return out;
}

}  // namespace gps
