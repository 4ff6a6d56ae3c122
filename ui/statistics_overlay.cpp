#include "ui/statistics_overlay.h"

#include <imgui.h>

#include <algorithm>

namespace gps {

namespace {
constexpr size_t kWindow = 120;  // frames or edits the medians look back over

void push(std::deque<double>& values, double v) {
  values.push_back(v);
  if (values.size() > kWindow) values.pop_front();
}
}  // namespace

void FrameClock::frame_done() {
  const auto now = Clock::now();
  if (last_frame_ != Clock::time_point{}) push(frames_, std::chrono::duration<double, std::milli>(now - last_frame_).count());
  last_frame_ = now;
}

void FrameClock::edit_shown(Clock::time_point edit_time) {
  push(edits_, std::chrono::duration<double, std::milli>(Clock::now() - edit_time).count());
  ++edit_total_;
}

void draw_statistics_overlay(const FrameClock& clock, const std::vector<std::pair<std::string, double>>& gpu_passes,
                             const DrawStatistics& draw, bool* open) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + 10, viewport->WorkPos.y + 10), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.55f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
  if (ImGui::Begin("Statistics", open, flags)) {
    const double frame_ms = clock.median_frame_ms();
    ImGui::Text("%.1f fps  (%.2f ms / frame)", frame_ms > 0 ? 1000.0 / frame_ms : 0.0, frame_ms);
    for (const auto& [pass, ms] : gpu_passes) ImGui::Text("GPU %-14s %7.3f ms", pass.c_str(), ms);
    ImGui::Text("triangles %lld", draw.triangles);
    if (draw.vertices >= 0) ImGui::Text("vertices  %lld", draw.vertices);
    else ImGui::TextDisabled("vertices  (no pipeline statistics)");
    ImGui::Text("patches   %d", draw.patches);
    if (clock.edit_count() > 0)
      ImGui::Text("edit to frame %.2f ms (median %.2f)", clock.last_edit_ms(), clock.median_edit_ms());
    else
      ImGui::TextDisabled("edit to frame: no edit yet");
  }
  ImGui::End();
}

}  // namespace gps
