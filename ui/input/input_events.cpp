#include "ui/input/input_events.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <utility>

namespace gps {

std::vector<InputEvent> InputQueue::take_frame() {
  std::vector<InputEvent> frame;
  while (!events_.empty()) {
    frame.push_back(std::move(events_.front()));
    events_.pop_front();
    if (frame.back().is_transition()) break;
  }
  return frame;
}

void InputState::apply(const InputEvent& e) {
  switch (e.type) {
    case InputEvent::Type::move:
    case InputEvent::Type::scroll:
      cursor = e.position;
      break;
    case InputEvent::Type::press:
    case InputEvent::Type::release:
      cursor = e.position;
      if (e.button >= 0 && e.button < 3) buttons[size_t(e.button)] = e.type == InputEvent::Type::press;
      break;
    case InputEvent::Type::key_press:
    case InputEvent::Type::key_release:
      if (e.key >= 0 && e.key < int(keys.size())) keys[size_t(e.key)] = e.type == InputEvent::Type::key_press;
      break;
    case InputEvent::Type::text:
    case InputEvent::Type::drop:
      break;
  }
}

bool InputState::ctrl() const { return keys[GLFW_KEY_LEFT_CONTROL] || keys[GLFW_KEY_RIGHT_CONTROL]; }
bool InputState::shift() const { return keys[GLFW_KEY_LEFT_SHIFT] || keys[GLFW_KEY_RIGHT_SHIFT]; }
bool InputState::alt() const { return keys[GLFW_KEY_LEFT_ALT] || keys[GLFW_KEY_RIGHT_ALT]; }

void feed_imgui(ImGuiIO& io, const InputState& state, const std::vector<InputEvent>& events) {
  io.MousePos = ImVec2(state.cursor.x, state.cursor.y);
  for (int b = 0; b < 3; ++b) io.MouseDown[b] = state.buttons[size_t(b)];
  for (size_t k = 0; k < state.keys.size() && k < IM_ARRAYSIZE(io.KeysDown); ++k) io.KeysDown[k] = state.keys[k];
  // Tab goes to Dear ImGui only while it has the keyboard (between text fields): otherwise Shift+Tab
  // (snapping) would focus a panel's field and Ctrl+Tab open its window switcher, both taking the keys.
  if (state.ctrl() || !io.WantCaptureKeyboard) io.KeysDown[GLFW_KEY_TAB] = false;
  io.KeyCtrl = state.ctrl();
  io.KeyShift = state.shift();
  io.KeyAlt = state.alt();
  io.KeySuper = state.keys[GLFW_KEY_LEFT_SUPER] || state.keys[GLFW_KEY_RIGHT_SUPER];
  for (const InputEvent& e : events) {
    if (e.type == InputEvent::Type::scroll) io.MouseWheel += e.steps;
    if (e.type == InputEvent::Type::text) io.AddInputCharacter(e.codepoint);
  }
}

void map_imgui_keys(ImGuiIO& io) {
  const std::pair<ImGuiKey_, int> keys[] = {{ImGuiKey_Tab, GLFW_KEY_TAB},
                                            {ImGuiKey_LeftArrow, GLFW_KEY_LEFT},
                                            {ImGuiKey_RightArrow, GLFW_KEY_RIGHT},
                                            {ImGuiKey_UpArrow, GLFW_KEY_UP},
                                            {ImGuiKey_DownArrow, GLFW_KEY_DOWN},
                                            {ImGuiKey_PageUp, GLFW_KEY_PAGE_UP},
                                            {ImGuiKey_PageDown, GLFW_KEY_PAGE_DOWN},
                                            {ImGuiKey_Home, GLFW_KEY_HOME},
                                            {ImGuiKey_End, GLFW_KEY_END},
                                            {ImGuiKey_Insert, GLFW_KEY_INSERT},
                                            {ImGuiKey_Delete, GLFW_KEY_DELETE},
                                            {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE},
                                            {ImGuiKey_Space, GLFW_KEY_SPACE},
                                            {ImGuiKey_Enter, GLFW_KEY_ENTER},
                                            {ImGuiKey_Escape, GLFW_KEY_ESCAPE},
                                            {ImGuiKey_KeyPadEnter, GLFW_KEY_KP_ENTER},
                                            {ImGuiKey_A, GLFW_KEY_A},
                                            {ImGuiKey_C, GLFW_KEY_C},
                                            {ImGuiKey_V, GLFW_KEY_V},
                                            {ImGuiKey_X, GLFW_KEY_X},
                                            {ImGuiKey_Y, GLFW_KEY_Y},
                                            {ImGuiKey_Z, GLFW_KEY_Z}};
  for (const auto& [imgui_key, glfw_key] : keys) io.KeyMap[imgui_key] = glfw_key;
}

namespace {

const std::vector<std::pair<std::string, int>>& named_keys() {
  static const std::vector<std::pair<std::string, int>> names = [] {
    std::vector<std::pair<std::string, int>> n = {{"ctrl", GLFW_KEY_LEFT_CONTROL},
                                                  {"shift", GLFW_KEY_LEFT_SHIFT},
                                                  {"alt", GLFW_KEY_LEFT_ALT},
                                                  {"super", GLFW_KEY_LEFT_SUPER},
                                                  {"escape", GLFW_KEY_ESCAPE},
                                                  {"enter", GLFW_KEY_ENTER},
                                                  {"tab", GLFW_KEY_TAB},
                                                  {"backspace", GLFW_KEY_BACKSPACE},
                                                  {"delete", GLFW_KEY_DELETE},
                                                  {"space", GLFW_KEY_SPACE},
                                                  {"left", GLFW_KEY_LEFT},
                                                  {"right", GLFW_KEY_RIGHT},
                                                  {"up", GLFW_KEY_UP},
                                                  {"down", GLFW_KEY_DOWN},
                                                  {"home", GLFW_KEY_HOME},
                                                  {"end", GLFW_KEY_END},
                                                  {"pageup", GLFW_KEY_PAGE_UP},
                                                  {"pagedown", GLFW_KEY_PAGE_DOWN},
                                                  {"period", GLFW_KEY_PERIOD},
                                                  {"minus", GLFW_KEY_MINUS},
                                                  {"kpadd", GLFW_KEY_KP_ADD},
                                                  {"kpsubtract", GLFW_KEY_KP_SUBTRACT},
                                                  {"kpmultiply", GLFW_KEY_KP_MULTIPLY},
                                                  {"kpdivide", GLFW_KEY_KP_DIVIDE},
                                                  {"kpdecimal", GLFW_KEY_KP_DECIMAL},
                                                  {"kpenter", GLFW_KEY_KP_ENTER},
                                                  {"comma", GLFW_KEY_COMMA},
                                                  {"right_ctrl", GLFW_KEY_RIGHT_CONTROL},
                                                  {"right_shift", GLFW_KEY_RIGHT_SHIFT},
                                                  {"right_alt", GLFW_KEY_RIGHT_ALT}};
    for (char c = 'a'; c <= 'z'; ++c) n.push_back({std::string(1, c), GLFW_KEY_A + (c - 'a')});
    for (char c = '0'; c <= '9'; ++c) n.push_back({std::string(1, c), GLFW_KEY_0 + (c - '0')});
    for (int f = 1; f <= 12; ++f) n.push_back({"f" + std::to_string(f), GLFW_KEY_F1 + f - 1});
    for (char c = '0'; c <= '9'; ++c) n.push_back({"kp" + std::string(1, c), GLFW_KEY_KP_0 + (c - '0')});
    return n;
  }();
  return names;
}

}  // namespace

int key_code(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  for (const auto& [n, code] : named_keys())
    if (n == lower) return code;
  return -1;
}

std::string key_name(int code) {
  for (const auto& [n, c] : named_keys())
    if (c == code) return n;
  return "";
}

bool imgui_key_pressed(ImGuiKey key) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), false); }

}  // namespace gps
