#include "ui/overlays/crease_overlay.h"

#include <imgui.h>

#include <optional>
#include <vector>

#include "ui/editing/crease_tool.h"

namespace gps {

namespace {

ImU32 colour_of(double sharpness) {
  const auto c = crease_colour(sharpness);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c[0], c[1], c[2], c[3]));
}

}  // namespace

void draw_crease_overlay(ImDrawList& draw, const Viewport& v, const CovarianceMesh& mesh,
                         const HiddenElements* hidden) {
  if (mesh.sharpness.empty()) return;
  const PolyMesh& m = mesh.mesh;
  std::vector<std::optional<ImVec2>> pixel(mesh.n_vertices());
  std::vector<bool> projected(mesh.n_vertices(), false);
  const auto at = [&](int vertex) -> const std::optional<ImVec2>& {
    if (!projected[size_t(vertex)]) {
      projected[size_t(vertex)] = true;
      if (const auto q = visible_pixel(v.camera, v.width, v.height, mesh.mean(size_t(vertex))))
        pixel[size_t(vertex)] = ImVec2(q->x, q->y);
    }
    return pixel[size_t(vertex)];
  };
  // Face f faces the camera where it winds clockwise in window pixels (y down).
  const auto front = [&](OpenMesh::SmartFaceHandle f) {
    if (!f.is_valid()) return false;
    double area = 0.0;
    for (const auto h : m.fh_range(f)) {
      const auto& a = at(h.from().idx());
      const auto& b = at(h.to().idx());
      if (!a || !b) return false;
      area += double(a->x) * double(b->y) - double(b->x) * double(a->y);
    }
    return area < 0.0;
  };
  for (const EdgeCrease& c : mesh.sharpness.creases) {
    const auto h = m.find_halfedge(m.vertex_handle(unsigned(c.a)), m.vertex_handle(unsigned(c.b)));
    if (!h.is_valid() || (hidden && hidden->edge_hidden(mesh, c.a, c.b))) continue;
    const auto sh = OpenMesh::make_smart(h, &m);
    const bool boundary = !sh.face().is_valid() || !sh.opp().face().is_valid();
    if (!boundary && !front(sh.face()) && !front(sh.opp().face())) continue;
    if (at(c.a) && at(c.b)) draw.AddLine(*at(c.a), *at(c.b), colour_of(c.sharpness), 3.0f);
  }
  for (size_t vertex = 0; vertex < mesh.sharpness.corners.size(); ++vertex) {
    const double s = mesh.sharpness.corners[vertex];
    if (s <= 0.0 || (hidden && hidden->vertex_hidden(int(vertex)))) continue;
    bool shown = false;
    for (const auto f : m.vf_range(m.vertex_handle(unsigned(vertex)))) shown = shown || front(f);
    if (!shown || !at(int(vertex))) continue;
    const ImVec2 p = *at(int(vertex));
    draw.AddRectFilled(ImVec2(p.x - 5, p.y - 5), ImVec2(p.x + 5, p.y + 5), colour_of(s));
    draw.AddRect(ImVec2(p.x - 5, p.y - 5), ImVec2(p.x + 5, p.y + 5), IM_COL32(20, 20, 20, 255));
  }
}

}  // namespace gps
