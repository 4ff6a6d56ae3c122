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
bool faces_camera(const PolyMesh& m, OpenMesh::SmartFaceHandle f, const std::vector<std::optional<ImVec2>>& pixel) {
  double area = 0.0;
  for (const auto h : m.fh_range(f)) {
    const auto& a = pixel[size_t(h.from().idx())];
    const auto& b = pixel[size_t(h.to().idx())];
    if (!a || !b) return false;
    area += double(a->x) * double(b->y) - double(b->x) * double(a->y);
  }
  return area < 0.0;
}

}  // namespace

void draw_selection_overlay(ImDrawList& draw, const Viewport& v, const CovarianceMesh& mesh,
                            const std::vector<EdgeEnds>& edges, const std::vector<int>& faces, SelectMode mode) {
  if (mode == SelectMode::vertex || (edges.empty() && faces.empty())) return;
  const PolyMesh& m = mesh.mesh;
  std::vector<std::optional<ImVec2>> pixel(mesh.n_vertices());  // projected as needed
  const auto project = [&](int vertex) -> const std::optional<ImVec2>& {
    std::optional<ImVec2>& p = pixel[size_t(vertex)];
    if (!p)
      if (const auto q = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(vertex)))) p = ImVec2(q->x, q->y);
    return p;
  };
  const auto front = [&](OpenMesh::SmartFaceHandle f) {
    for (const auto corner : m.fv_range(f)) project(corner.idx());
    return faces_camera(m, f, pixel);
  };
  if (mode == SelectMode::face)
    for (const int face : faces) {
      const auto f = OpenMesh::make_smart(m.face_handle(face), &m);
      if (!front(f)) continue;
      std::vector<ImVec2> corners;
      for (const auto corner : m.fv_range(f)) corners.push_back(*pixel[size_t(corner.idx())]);
      for (size_t k = 1; k + 1 < corners.size(); ++k)
        draw.AddTriangleFilled(corners[0], corners[k], corners[k + 1], kFaceFill);
      draw.AddPolyline(corners.data(), int(corners.size()), kFaceOutline, ImDrawFlags_Closed, 2.0f);
    }
  for (const auto& [a, b] : edges) {
    const auto h = m.find_halfedge(m.vertex_handle(a), m.vertex_handle(b));
    if (!h.is_valid()) continue;
    const auto f0 = h.face(), f1 = h.opp().face();
    const bool shown = !f0.is_valid() || !f1.is_valid() || front(f0) || front(f1);
    if (shown && project(a) && project(b)) draw.AddLine(*pixel[size_t(a)], *pixel[size_t(b)], kEdgeColour, 2.5f);
  }
}

}  // namespace gps
