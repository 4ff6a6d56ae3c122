#include "view/element_picking.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace gps {

namespace {

std::vector<std::optional<glm::vec3>> project_vertices(const Viewport& view, const CovarianceMesh& mesh) {
  std::vector<std::optional<glm::vec3>> projected(mesh.n_vertices());
  for (size_t i = 0; i < projected.size(); ++i)
    projected[i] = visible_pixel(view.camera, view.width, view.height, mesh.mean(i));
  return projected;
}

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

}  // namespace

std::optional<std::array<int, 2>> pick_edge(const Viewport& view, glm::vec2 pixel, const CovarianceMesh& mesh,
                                            float radius, const std::vector<char>* hidden) {
  const auto projected = project_vertices(view, mesh);
  const glm::vec2 centre = pixel + glm::vec2(0.5f);
  constexpr float kTie = 0.5f;
  std::optional<std::array<int, 2>> best;
  float best_distance = radius, best_depth = std::numeric_limits<float>::infinity();
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    if (hidden && e < hidden->size() && (*hidden)[e]) continue;
    const auto [a, b] = mesh.edge(e);
    const auto& pa = projected[size_t(a)];
    const auto& pb = projected[size_t(b)];
    if (!pa || !pb) continue;
    const glm::vec2 d = glm::vec2(*pb) - glm::vec2(*pa);
    const float length2 = glm::dot(d, d);
    const float t = length2 > 0.0f ? std::clamp(glm::dot(centre - glm::vec2(*pa), d) / length2, 0.0f, 1.0f) : 0.0f;
    const float distance = glm::length(glm::vec2(*pa) + t * d - centre);
    const float depth = pa->z + t * (pb->z - pa->z);
    if (distance > radius) continue;
    const bool nearer = distance < best_distance - kTie;
    const bool as_near_in_front = distance <= best_distance + kTie && depth < best_depth;
    if (!best || nearer || as_near_in_front) {
      best = std::array<int, 2>{std::min(a, b), std::max(a, b)};
      best_distance = distance;
      best_depth = depth;
    }
  }
  return best;
}

int pick_face(const Viewport& view, glm::vec2 pixel, const CovarianceMesh& mesh, const std::vector<char>* hidden) {
  const auto projected = project_vertices(view, mesh);
  const glm::vec2 s = pixel + glm::vec2(0.5f);
  int best = -1;
  float best_depth = std::numeric_limits<float>::infinity();
  std::vector<glm::vec3> corners;
  for (size_t f = 0; f < mesh.n_faces(); ++f) {
    if (hidden && f < hidden->size() && (*hidden)[f]) continue;
    corners.clear();
    for (const int v : mesh.face(f)) {
      if (!projected[size_t(v)]) break;
      corners.push_back(*projected[size_t(v)]);
    }
    if (corners.size() != size_t(mesh.face_size(f))) continue;
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      const glm::vec2 a(corners[0]), b(corners[k]), c(corners[k + 1]);
      const float area = cross(b - a, c - a);
      if (area == 0.0f) continue;
      const float wa = cross(c - b, s - b) / area, wb = cross(a - c, s - c) / area, wc = cross(b - a, s - a) / area;
      if (wa < 0.0f || wb < 0.0f || wc < 0.0f) continue;
      const float depth = wa * corners[0].z + wb * corners[k].z + wc * corners[k + 1].z;
      if (depth < best_depth) best_depth = depth, best = int(f);
    }
  }
  return best;
}

}  // namespace gps
