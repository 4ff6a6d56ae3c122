#include "ui/editing/crease_tool.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "core/mesh/sharpness.h"
#include "core/modelling/crease_edges.h"

namespace gps {

namespace {

// Each selected vertex's mirror image (the vertex itself where it has none).
std::map<int, int> mirror_partners(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                                   const ReachOptions& reach) {
  std::map<int, int> partner;
  for (const int v : vertices) partner[v] = v;
  if (!reach.mirror) return partner;
  ReachOptions mirror_only = reach;
  mirror_only.proportional = false;
  std::vector<Vec3> means(mesh.n_vertices());
  for (size_t v = 0; v < means.size(); ++v) means[v] = mesh.mean(v);
  for (const ReachedVertex& r : edit_reach(means, vertices, mirror_only))
    if (r.mirrored) partner[vertices[r.source]] = r.vertex;
  return partner;
}

}  // namespace

float crease_drag_span(float viewport_width) { return std::max(0.4f * viewport_width, 50.0f); }

double sharpness_after_drag(double start, float dx, float viewport_width) {
  const double s = start + kInfiniteSharpness * double(dx) / double(crease_drag_span(viewport_width));
  return std::round(std::clamp(s, 0.0, kInfiniteSharpness) * 10.0) / 10.0;
}

std::string sharpness_text(double sharpness) {
  if (is_infinitely_sharp(sharpness)) return "∞";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", sharpness);
  return text;
}

std::array<float, 4> crease_colour(double sharpness) {
  const float t = float(std::clamp(sharpness / kInfiniteSharpness, 0.0, 1.0));
  const std::array<float, 4> grey = {0.45f, 0.45f, 0.45f, 1.0f}, magenta = {1.0f, 0.1f, 0.85f, 1.0f};
  std::array<float, 4> c{};
  for (int k = 0; k < 4; ++k) c[size_t(k)] = (1.0f - t) * grey[size_t(k)] + t * magenta[size_t(k)];
  return c;
}

double common_crease(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges) {
  if (edges.empty()) return 0.0;
  const double first = mesh.sharpness.crease(edges.front()[0], edges.front()[1]);
  for (const auto& [a, b] : edges)
    if (mesh.sharpness.crease(a, b) != first) return std::numeric_limits<double>::quiet_NaN();
  return first;
}

double common_corner(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  if (vertices.empty()) return 0.0;
  const double first = mesh.sharpness.corner(vertices.front());
  for (const int v : vertices)
    if (mesh.sharpness.corner(v) != first) return std::numeric_limits<double>::quiet_NaN();
  return first;
}

std::vector<std::array<int, 2>> with_mirrored_edges(const CovarianceMesh& mesh,
                                                    const std::vector<std::array<int, 2>>& edges,
                                                    const ReachOptions& reach) {
  std::vector<int> ends;
  for (const auto& [a, b] : edges) ends.insert(ends.end(), {a, b});
  const std::map<int, int> partner = mirror_partners(mesh, ends, reach);
  std::vector<std::array<int, 2>> out;
  for (const auto& [a, b] : edges) {
    out.push_back({std::min(a, b), std::max(a, b)});
    const int pa = partner.at(a), pb = partner.at(b);
    if (pa == pb) continue;
    if (mesh.find_edge(pa, pb) >= 0) out.push_back({std::min(pa, pb), std::max(pa, pb)});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> with_mirrored_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices,
                                        const ReachOptions& reach) {
  std::vector<int> out;
  for (const auto& [v, p] : mirror_partners(mesh, vertices, reach)) out.insert(out.end(), {v, p});
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Modelled sharpened_selection(const CovarianceMesh& mesh, const Selection& selection, bool corners, double sharpness,
                             const ReachOptions& reach) {
  if (corners) return set_corner(mesh, with_mirrored_vertices(mesh, selection.vertices(), reach), sharpness);
  return set_crease(mesh, with_mirrored_edges(mesh, selection.edges(mesh), reach), sharpness);
}

}  // namespace gps
