#include "ui/panels/view_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>

#include "render/image/matcap.h"
#include "render/overlays/distance_ramp.h"
#include "ui/overlays/ellipsoid_scope.h"

namespace gps {

namespace {

constexpr float kViewPanelWidth = 340.0f;

// The panel is a list of sections, each a function of the options: a new setting goes in its
// section, a new section (say, the subdivision scheme) in kSections.
void tessellation_section(ViewOptions& o, ViewPanelChanges& changes) {
  ImGui::Checkbox("adaptive", &o.adaptive);
  ImGui::SameLine();
  if (o.adaptive)
    ImGui::SliderFloat("px/edge", &o.adaptive_pixels, 1.0f, 32.0f, "%.1f");
  else
    ImGui::SliderFloat("level", &o.draw.level, 1.0f, 64.0f, "%.0f");
  o.draw.pixels = o.adaptive ? o.adaptive_pixels : 0.0f;
  ImGui::Checkbox("surface cache", &o.draw.surface_cache);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "redraw the stored triangles while the mesh and the levels stay (else every frame evaluates every patch)");
  if (o.triangle_mesh) {
    if (ImGui::Combo("scheme", &o.scheme, "automatic (Loop)\0Loop\0Catmull-Clark\0")) changes.depth = true;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Loop patches are exact at every depth; Catmull-Clark splits each triangle into three quads");
    if (o.scheme != 2 && ImGui::Checkbox("Warren's beta", &o.warren)) changes.depth = true;
  }
  if (!o.triangle_mesh || o.scheme == 2) {
    if (ImGui::Checkbox("exact", &o.exact)) {
      changes.depth = true;
      o.depth = o.exact ? kExactPlanDepth : 3;
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("extraordinary vertices evaluated exactly (else the thesis' Bezier plans)");
    ImGui::SameLine();
    if (ImGui::SliderInt("plan depth", &o.depth, o.exact ? 0 : 1, 6)) changes.depth = true;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(o.exact ? "where the exact nodes take over (deeper: more stencil rows, cheaper frames)"
                                : "quadtree depth of the thesis' approximate plans");
  }
}

void shading_section(ViewOptions& o, ViewPanelChanges& changes) {
  if (ImGui::BeginCombo("MatCap", o.matcap.c_str())) {
    for (const std::string& name : builtin_matcap_names())
      if (ImGui::Selectable(name.c_str(), name == o.matcap)) o.matcap = name, changes.matcap = true;
    if (ImGui::Selectable("Load from file...")) changes.load_matcap = true;
    ImGui::EndCombo();
  }
  int mode = int(o.draw.mode);
  if (ImGui::Combo("shading", &mode, "MatCap\0normals\0flat\0")) o.draw.mode = ShadingMode(mode);
  if (ImGui::Combo("up axis", &o.up_axis, "x\0y\0z\0")) changes.up_axis = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the world axis drawn upward (kept for this file; --up on the command line)");
}

void overlay_section(ViewOptions& o, ViewPanelChanges&) {
  ImGui::Checkbox("base mesh", &o.draw.mesh_lines);
  ImGui::SameLine();
  ImGui::Checkbox("wireframe", &o.draw.wireframe);
  ImGui::Checkbox("ellipsoids", &o.draw.ellipsoids);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  ImGui::SliderFloat("k-sigma", &o.draw.sigma_scale, 0.1f, 10.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
  if (o.draw.ellipsoids) {
    ImGui::Combo("of", &o.ellipsoid_scope, "automatic\0selection and neighbours\0all vertices\0");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "automatic: every vertex's ellipsoid up to %zu vertices, else those of the selection and its neighbours",
          kAllEllipsoidsUpTo);
  }
}

// The target points (while a target is loaded): their toggle, the distance ramp as a legend from 0 to
// its end (the 99th percentile unless the slider chose another), and the point size.
void target_section(ViewOptions& o, ViewPanelChanges& changes) {
  TargetPointsView& t = o.target;
  if (t.name.empty()) return;
  ImGui::Separator();
  if (ImGui::Checkbox("target points", &t.shown)) changes.target_shown = true;
  ImGui::SameLine();
  ImGui::TextDisabled("%zu of %s%s", t.count, t.name.c_str(), t.measuring ? "  (measuring...)" : "");
  if (!t.shown) return;
  // The legend: the ramp, with 0 (on the surface) at its left and its end at its right.
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = ImGui::GetFontSize() * 0.8f;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  constexpr int kSegments = 32;
  for (int i = 0; i < kSegments; ++i) {
    const auto colour = [](float f) {
      const glm::vec3 c = ramp_colour(f);
      return ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1.0f));
    };
    const ImU32 left = colour(float(i) / kSegments), right = colour(float(i + 1) / kSegments);
    draw->AddRectFilledMultiColor(ImVec2(at.x + width * float(i) / kSegments, at.y),
                                  ImVec2(at.x + width * float(i + 1) / kSegments, at.y + height), left, right, right,
                                  left);
  }
  ImGui::Dummy(ImVec2(width, height));
  ImGui::TextUnformatted("0");
  char end[64];
  std::snprintf(end, sizeof end, "%s%.3g", t.automatic ? "99%: " : "", t.max_distance);
  ImGui::SameLine(std::max(0.0f, width - ImGui::CalcTextSize(end).x));
  ImGui::TextUnformatted(end);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("points this far from the surface or farther are red");
  const float largest = float(std::max(t.largest, double(t.max_distance)));
  if (largest > 0.0f &&
      ImGui::SliderFloat("ramp end", &t.max_distance, 0.0f, largest, "%.3g", ImGuiSliderFlags_Logarithmic))
    t.automatic = false;
  ImGui::SameLine();
  ImGui::Checkbox("99%", &t.automatic);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("the ramp ends at the distances' 99th percentile");
  ImGui::SliderFloat("point size", &t.point_size, 1.0f, 16.0f, "%.0f px");
  ImGui::TextDisabled("rms %.3g, max %.3g (%.3g %% of its size)", t.rms, t.largest,
                      100.0 * t.largest / (t.length > 0.0 ? t.length : 1.0));
  ImGui::Separator();
}

void editing_section(ViewOptions& o, ViewPanelChanges&) {
  ImGui::Checkbox("G/S/R carry the Gaussians", &o.transform_gaussians);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "a grab, scale or rotation maps the Gaussians with the positions (else it moves the positions "
        "only, each Gaussian kept as it was)");
  ImGui::SetNextItemWidth(90.0f);
  ImGui::Combo("transform orientation", &o.transform_orientation, "Global\0Normal\0");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "the axes X, Y, Z take first in G / S / R (pressed again: the other; a third time: free); Normal follows "
        "the selection's surface");
  ImGui::Checkbox("snap", &o.snap.enabled);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("G / S / R snap (Shift+Tab); Ctrl held while transforming inverts it");
  ImGui::SameLine();
  int target = int(o.snap.target);
  ImGui::SetNextItemWidth(90.0f);
  if (ImGui::Combo("to", &target, "increments\0vertices\0edges\0faces\0")) o.snap.target = SnapTarget(target);
  if (o.snap.target == SnapTarget::increment) {
    float step = float(o.snap.distance_step);
    if (ImGui::InputFloat("increment", &step, 0.0f, 0.0f, "%.4g") && step > 0.0f) o.snap.distance_step = step;
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("a grab moves in whole steps of this many units; a scale in steps of %.2g, a rotation of %.3g°",
                        o.snap.factor_step, o.snap.angle_step);
  }
  ImGui::Checkbox("common frame", &o.common_frame);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("a multi-selection drag scales every Gaussian along the grabbed axis (else each along its own)");
  ImGui::Combo("gizmo at", &o.pivot, "active vertex\0centroid\0");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "where the one gizmo of a multi-selection sits: the vertex last clicked, or the selected vertices' mean "
        "position");
}

void window_section(ViewOptions& o, ViewPanelChanges&) {
  ImGui::Checkbox("v-sync", &o.vsync);
  ImGui::SameLine();
  ImGui::Checkbox("statistics", &o.show_statistics);
}

using Section = void (*)(ViewOptions&, ViewPanelChanges&);
constexpr Section kSections[] = {tessellation_section, shading_section, overlay_section,
                                 target_section,       editing_section, window_section};

}  // namespace

ViewPanelChanges draw_view_panel(ViewOptions& o, bool* open) {
  ViewPanelChanges changes;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10, viewport->WorkPos.y + viewport->WorkSize.y - 40),
      ImGuiCond_FirstUseEver, ImVec2(1, 1));
  // As tall as its rows (a triangle mesh adds the scheme's), as wide as before: every row shows.
  ImGui::SetNextWindowSizeConstraints(ImVec2(kViewPanelWidth, 0.0f), ImVec2(kViewPanelWidth, FLT_MAX));
  if (!ImGui::Begin("View", open, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return changes;
  }
  ImGui::PushItemWidth(170);
  for (const Section section : kSections) section(o, changes);
  ImGui::PopItemWidth();
  // Grown below the status bar: moved up until its last row shows.
  const float bottom = viewport->WorkPos.y + viewport->WorkSize.y - ImGui::GetFrameHeight() - 4.0f;
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  if (pos.y + size.y > bottom) ImGui::SetWindowPos(ImVec2(pos.x, std::max(viewport->WorkPos.y, bottom - size.y)));
  ImGui::End();
  return changes;
}

}  // namespace gps
