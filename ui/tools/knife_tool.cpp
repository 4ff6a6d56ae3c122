// The knife as a modal tool, and where a click lands on the control mesh.
#include "ui/tools/knife_tool.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <limits>

#include "core/modelling/knife.h"
#include "core/support/error.h"
#include "ui/document/editor_document.h"
#include "view/element_picking.h"

namespace gps {

namespace {

constexpr float kSnapPixels = 8.0f;  // how near a corner, edge middle or edge a click snaps to it

// The corners of face f of `mesh`, in order.
std::vector<int> corners_of(const CovarianceMesh& mesh, int f) {
  std::vector<int> out;
  for (const auto v : mesh.mesh.fv_range(mesh.mesh.face_handle(f))) out.push_back(v.idx());
  return out;
}

// Newell's normal of a polygon's corners.
Vec3 polygon_normal(const CovarianceMesh& mesh, const std::vector<int>& corners) {
  Vec3 n = Vec3::Zero();
  for (size_t k = 0; k < corners.size(); ++k)
    n += mesh.mean(size_t(corners[k])).cross(mesh.mean(size_t(corners[(k + 1) % corners.size()])));
  return n;
}

// The point of segment a–b nearest the ray (the closest points of two lines, clamped to the segment).
Vec3 nearest_on_segment(const Vec3& a, const Vec3& b, const Ray& ray) {
  const Vec3 o = to_vec(ray.origin), d = to_vec(ray.direction), e = b - a, w = a - o;
  const double ee = e.dot(e), ed = e.dot(d), denominator = ee - ed * ed;  // |d| = 1
  const double t = denominator > 0 ? (ed * d.dot(w) - e.dot(w)) / denominator : 0.0;
  return a + std::clamp(t, 0.0, 1.0) * e;
}

}  // namespace

std::optional<Vec3> knife_point_under(const CovarianceMesh& mesh, const Viewport& view, glm::vec2 pixel) {
  const int face = pick_face(view, pixel, mesh);
  const Ray ray = pixel_ray(view.camera, view.width, view.height, pixel);
  std::vector<int> faces;
  if (face >= 0) {
    faces.push_back(face);
  } else {
    for (const auto f : mesh.mesh.faces())
      if (polygon_normal(mesh, corners_of(mesh, f.idx())).dot(to_vec(ray.direction)) < 0) faces.push_back(f.idx());
  }
  const auto pixel_distance = [&](const Vec3& p) {
    const auto q = visible_pixel(view.camera, view.width, view.height, p);
    return q ? glm::length(glm::vec2(q->x, q->y) - pixel) : std::numeric_limits<float>::infinity();
  };
  // Corners first, then edge middles, then edges, each the nearest within the snap.
  std::optional<Vec3> corner, middle, on_edge;
  float corner_pixels = kSnapPixels, middle_pixels = kSnapPixels, edge_pixels = kSnapPixels;
  for (const int f : faces) {
    const std::vector<int> c = corners_of(mesh, f);
    for (size_t k = 0; k < c.size(); ++k) {
      const Vec3 a = mesh.mean(size_t(c[k])), b = mesh.mean(size_t(c[(k + 1) % c.size()]));
      if (const float d = pixel_distance(a); d < corner_pixels) corner_pixels = d, corner = a;
      if (const float d = pixel_distance((a + b) / 2); d < middle_pixels) middle_pixels = d, middle = (a + b) / 2;
      const Vec3 p = nearest_on_segment(a, b, ray);
      if (const float d = pixel_distance(p); d < edge_pixels) edge_pixels = d, on_edge = p;
    }
  }
  if (corner) return corner;
  if (middle) return middle;
  if (on_edge) return on_edge;
  if (face < 0) return std::nullopt;
  // Where the ray meets the face's plane (Newell's normal through its centroid).
  const std::vector<int> c = corners_of(mesh, face);
  const Vec3 n = polygon_normal(mesh, c), o = to_vec(ray.origin), d = to_vec(ray.direction);
  Vec3 centre = Vec3::Zero();
  for (int v : c) centre += mesh.mean(size_t(v)) / double(c.size());
  const double along = n.dot(d);
  if (along == 0) return std::nullopt;
  return o + (n.dot(centre - o) / along) * d;
}

KnifeTool::KnifeTool(ToolContext&) { show_count(); }

void KnifeTool::show_count() {
  error_ = false;
  status_ = "knife: " + std::to_string(points_.size()) + (points_.size() == 1 ? " point" : " points") +
            "; click on the mesh to add one (snaps to corners and edge middles), Enter or Space cuts, "
            "Backspace takes one back, Esc cancels";
}

ToolResult KnifeTool::handle(const InputEvent& e, ToolContext& ctx) {
  if (cancels(e)) {
    ctx.report("knife cancelled", false);
    return ToolResult::cancelled;
  }
  if (e.type == InputEvent::Type::press && e.button == 0) {
    const std::optional<Vec3> p = knife_point_under(ctx.document.mesh(), ctx.viewport, e.position);
    if (!p) {
      status_ = "knife: that is not on the mesh; click on a face";
      error_ = true;
    } else if (points_.empty() || (*p - points_.back()).norm() > 0) {
      points_.push_back(*p);
      show_count();
    }
    return ToolResult::consumed;
  }
  if (e.type != InputEvent::Type::key_press)
    return e.type == InputEvent::Type::scroll ? ToolResult::passed_on : ToolResult::consumed;
  if (e.key == GLFW_KEY_BACKSPACE) {
    if (!points_.empty()) points_.pop_back();
    show_count();
  } else if (e.key == GLFW_KEY_ENTER || e.key == GLFW_KEY_KP_ENTER || e.key == GLFW_KEY_SPACE) {
    if (points_.size() < 2) {
      status_ = "knife: click at least 2 points on the mesh before cutting";
      error_ = true;
      return ToolResult::consumed;
    }
    try {
      const Modelled cut = knife(ctx.document.mesh(), points_);
      ctx.install(cut, nullptr);
      ctx.note("knife: " + cut.summary, false);
    } catch (const Error& refusal) {  // nothing changed: the path stays to be mended
      status_ = std::string("knife refused: ") + refusal.what() + " (Backspace takes a point back, Esc cancels)";
      error_ = true;
      return ToolResult::consumed;
    }
    return ToolResult::confirmed;
  }
  return ToolResult::consumed;
}

// The path as a line through its points, on to the pointer.
void KnifeTool::draw_overlay(ImDrawList& draw, const ToolContext& ctx) const {
  const Viewport& v = ctx.viewport;
  std::vector<ImVec2> pixels;
  for (const Vec3& p : points_)
    if (const auto q = project_to_pixel(v.camera, v.width, v.height, p)) pixels.emplace_back(q->x, q->y);
  const ImU32 colour = IM_COL32(255, 210, 60, 255);
  if (pixels.size() >= 2) draw.AddPolyline(pixels.data(), int(pixels.size()), colour, ImDrawFlags_None, 2.0f);
  if (!pixels.empty())
    draw.AddLine(pixels.back(), ImVec2(ctx.cursor.x, ctx.cursor.y), IM_COL32(255, 210, 60, 140), 1.5f);
  for (const ImVec2& p : pixels) draw.AddCircleFilled(p, 4.0f, colour);
}

}  // namespace gps
