// The surface cache's stored triangles read back (render/cache/surface_cache.h): what the benchmarks'
// static floor draws and what the tests count. Not on any frame's path.
#include <glad/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "render/gl/gl_context.h"
#include "render/cache/surface_cache.h"

namespace gps {

long long SurfaceCache::distinct_vertices() const {
  const long long vertices = 3 * blocks_.total();
  if (!stored_vertices_welded() || !has_stored_triangles()) return vertices;
  std::vector<GLuint> indices(static_cast<size_t>(vertices), 0u);
  glGetNamedBufferSubData(indices_, 0, GLsizeiptr(indices.size() * sizeof(GLuint)), indices.data());
  check_gl_errors("reading the surface cache's indices");
  std::sort(indices.begin(), indices.end());
  return std::unique(indices.begin(), indices.end()) - indices.begin();
}

std::vector<float> SurfaceCache::captured_vertices() {
  if (!has_stored_triangles()) return {};
  copy_back_evaluated();
  std::vector<float> vertices(size_t(3 * blocks_.total()) * (kCapturedVertexBytes / sizeof(float)));
  glGetNamedBufferSubData(buffer_, 0, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data());
  check_gl_errors("reading the surface cache");
  return vertices;
}

TriangleMesh SurfaceCache::stored_triangles() {
  TriangleMesh mesh;
  if (!has_stored_triangles()) return mesh;
  const size_t floats_per_vertex = kCapturedVertexBytes / sizeof(float);
  const std::vector<float> vertices = captured_vertices();
  using Bits = std::array<uint32_t, 6>;  // position and normal
  struct BitsHash {
    size_t operator()(const Bits& b) const {
      size_t h = 0;
      for (const uint32_t x : b) h = h * 0x9E3779B97F4A7C15ull + x;
      return h;
    }
  };
  std::unordered_map<Bits, int, BitsHash> index;
  mesh.triangles.resize(size_t(blocks_.total()));
  for (size_t v = 0; v < vertices.size() / floats_per_vertex; ++v) {
    const float* f = &vertices[v * floats_per_vertex];
    Bits bits;
    std::memcpy(bits.data(), f, sizeof(bits));
    const auto [it, added] = index.emplace(bits, int(mesh.positions.size()));
    if (added) {
      const glm::dvec3 world = frame_.to_world(glm::dvec3(f[0], f[1], f[2]));
      mesh.positions.emplace_back(world.x, world.y, world.z);
      // The stored normal is the normal times 2^kind (shaders/cache_vert.glsl).
      const glm::dvec3 turned = frame_.direction_to_world(glm::dvec3(f[3], f[4], f[5]));
      const Vec3 stored(turned.x, turned.y, turned.z);
      mesh.normals.push_back(stored * std::exp2(-std::round(std::log2(stored.norm()))));
    }
    mesh.triangles[v / 3][v % 3] = it->second;
  }
  return mesh;
}

}  // namespace gps
