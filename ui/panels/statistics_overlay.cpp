#include "ui/panels/statistics_overlay.h"

#include <imgui.h>
#include <imgui_internal.h>

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
  if (last_frame_ != Clock::time_point{})
    push(frames_, std::chrono::duration<double, std::milli>(now - last_frame_).count());
  last_frame_ = now;
}

void FrameClock::edit_shown(Clock::time_point edit_time) {
  push(edits_, std::chrono::duration<double, std::milli>(Clock::now() - edit_time).count());
  ++edit_total_;
}

glm::vec2 statistics_position(const ScreenBox& free, glm::vec2 size, const std::vector<ScreenBox>& keep_clear) {
  constexpr float kMargin = 10.0f;
  const float left = free.min.x + kMargin, top = free.min.y + kMargin;
  const float right = std::max(left, free.max.x - kMargin - size.x),
              bottom = std::max(top, free.max.y - kMargin - size.y);
  for (const glm::vec2 corner :
       {glm::vec2(left, top), glm::vec2(left, bottom), glm::vec2(right, top), glm::vec2(right, bottom)}) {
    const ScreenBox box{corner, corner + size};
    if (std::none_of(keep_clear.begin(), keep_clear.end(), [&box](const ScreenBox& k) { return box.overlaps(k); }))
      return corner;
  }
  return {left, top};
}

void draw_statistics_overlay(const FrameClock& clock, const std::vector<std::pair<std::string, double>>& gpu_passes,
                             const DrawStatistics& draw, const ScreenBox& free,
                             const std::vector<ScreenBox>& keep_clear, bool* open) {
  const ImGuiWindow* last = ImGui::FindWindowByName("Statistics");
  const glm::vec2 size = last ? glm::vec2(last->Size.x, last->Size.y) : glm::vec2(280.0f, 170.0f);
  const glm::vec2 at = statistics_position(free, size, keep_clear);
  ImGui::SetNextWindowPos(ImVec2(at.x, at.y), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.55f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("Statistics", open, flags)) {
    const double frame_ms = clock.median_frame_ms();
    ImGui::Text("%.1f fps  (%.2f ms / frame)", frame_ms > 0 ? 1000.0 / frame_ms : 0.0, frame_ms);
    for (const auto& [pass, ms] : gpu_passes) ImGui::Text("GPU %-14s %7.3f ms", pass.c_str(), ms);
    ImGui::Text("triangles %lld", draw.triangles);
    if (draw.vertices >= 0)
      ImGui::Text("vertices  %lld", draw.vertices);
    else
      ImGui::TextDisabled("vertices  (no pipeline statistics)");
    ImGui::Text("patches   %d", draw.patches);
    if (clock.edit_count() > 0)
      ImGui::Text("edit to frame %.2f ms (median %.2f)", clock.last_edit_ms(), clock.median_edit_ms());
    else
      ImGui::TextDisabled("edit to frame: no edit yet");
  }
  ImGui::End();
}

}  // namespace gps
