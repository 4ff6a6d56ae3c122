#include "ui/overlays/selection_overlay.h"

#include <imgui.h>

#include <optional>

#include "core/modelling/mesh_queries.h"

namespace gps {

namespace {

constexpr ImU32 kEdgeColour = IM_COL32(255, 170, 40, 255);
constexpr ImU32 kFaceFill = IM_COL32(255, 150, 40, 70), kFaceOutline = IM_COL32(255, 190, 80, 255);

// Whether face f winds clockwise in window pixels (y down), that is faces the camera; false when a
// corner is not in view.
bool faces_camera(std::span<const int> corners, const std::vector<std::optional<ImVec2>>& pixel) {
  double area = 0.0;
  for (size_t k = 0; k < corners.size(); ++k) {
    const auto& a = pixel[size_t(corners[k])];
    const auto& b = pixel[size_t(corners[(k + 1) % corners.size()])];
    if (!a || !b) return false;
    area += double(a->x) * double(b->y) - double(b->x) * double(a->y);
  }
  return area < 0.0;
}

}  // namespace

void draw_selection_overlay(ImDrawList& draw, const Viewport& v, const CovarianceMesh& mesh,
                            const std::vector<EdgeEnds>& edges, const std::vector<int>& faces, SelectMode mode) {
  if (mode == SelectMode::vertex || (edges.empty() && faces.empty())) return;
  std::vector<std::optional<ImVec2>> pixel(mesh.n_vertices());  // projected as needed
  const auto project = [&](int vertex) -> const std::optional<ImVec2>& {
    std::optional<ImVec2>& p = pixel[size_t(vertex)];
    if (!p)
      if (const auto q = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(vertex)))) p = ImVec2(q->x, q->y);
    return p;
  };
  const auto front = [&](int f) {
    for (const int corner : mesh.face(size_t(f))) project(corner);
    return faces_camera(mesh.face(size_t(f)), pixel);
  };
  if (mode == SelectMode::face)
    for (const int face : faces) {
      if (!front(face)) continue;
      std::vector<ImVec2> corners;
      for (const int corner : mesh.face(size_t(face))) corners.push_back(*pixel[size_t(corner)]);
      for (size_t k = 1; k + 1 < corners.size(); ++k)
        draw.AddTriangleFilled(corners[0], corners[k], corners[k + 1], kFaceFill);
      draw.AddPolyline(corners.data(), int(corners.size()), kFaceOutline, ImDrawFlags_Closed, 2.0f);
    }
  const std::vector<int>& sides = mesh.connectivity().edge_faces;
  for (const auto& [a, b] : edges) {
    const int e = mesh.find_edge(a, b);
    if (e < 0) continue;
    const int f0 = sides[2 * size_t(e)], f1 = sides[2 * size_t(e) + 1];
    const bool shown = f1 < 0 || front(f0) || front(f1);  // a boundary edge is always drawn
    if (shown && project(a) && project(b)) draw.AddLine(*pixel[size_t(a)], *pixel[size_t(b)], kEdgeColour, 2.5f);
  }
}

}  // namespace gps
