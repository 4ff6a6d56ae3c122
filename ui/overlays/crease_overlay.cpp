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
  const MeshConnectivity& c = mesh.connectivity();
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
  const auto front = [&](int f) {
    const std::span<const int> corners = mesh.face(size_t(f));
    double area = 0.0;
    for (size_t k = 0; k < corners.size(); ++k) {
      const auto& a = at(corners[k]);
      const auto& b = at(corners[(k + 1) % corners.size()]);
      if (!a || !b) return false;
      area += double(a->x) * double(b->y) - double(b->x) * double(a->y);
    }
    return area < 0.0;
  };
  for (const EdgeCrease& crease : mesh.sharpness.creases) {
    const int e = mesh.find_edge(crease.a, crease.b);
    if (e < 0 || (hidden && hidden->edge_hidden(mesh, crease.a, crease.b))) continue;
    const int f0 = c.edge_faces[2 * size_t(e)], f1 = c.edge_faces[2 * size_t(e) + 1];
    if (f1 >= 0 && !front(f0) && !front(f1)) continue;  // a boundary edge is always drawn
    if (at(crease.a) && at(crease.b)) draw.AddLine(*at(crease.a), *at(crease.b), colour_of(crease.sharpness), 3.0f);
  }
  for (size_t vertex = 0; vertex < mesh.sharpness.corners.size(); ++vertex) {
    const double s = mesh.sharpness.corners[vertex];
    if (s <= 0.0 || (hidden && hidden->vertex_hidden(int(vertex)))) continue;
    bool shown = false;
    for (int k = c.vertex_face_offsets[vertex]; k < c.vertex_face_offsets[vertex + 1]; ++k)
      shown = shown || front(c.vertex_faces[size_t(k)]);
    if (!shown || !at(int(vertex))) continue;
    const ImVec2 p = *at(int(vertex));
    draw.AddRectFilled(ImVec2(p.x - 5, p.y - 5), ImVec2(p.x + 5, p.y + 5), colour_of(s));
    draw.AddRect(ImVec2(p.x - 5, p.y - 5), ImVec2(p.x + 5, p.y + 5), IM_COL32(20, 20, 20, 255));
  }
}

}  // namespace gps
