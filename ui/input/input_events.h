#pragma once
// The editor's input as a stream of events: what GLFW reports live and what an events file replays
// go through the same path, so a recorded session replays exactly (gpsurf-editor --play).
#include <array>
#include <deque>
#include <string>
#include <vector>

#include <glm/glm.hpp>

struct ImGuiIO;
using ImGuiKey = int;  // imgui.h's enum type

namespace gps {

struct InputEvent {
  enum class Type { move, press, release, scroll, key_press, key_release, text, drop };
  Type type = Type::move;
  glm::vec2 position{0.0f};        // move, press, release, scroll: window pixels, origin top-left
  int button = 0;                  // press, release: 0 left, 1 right, 2 middle
  float steps = 0.0f;              // scroll: wheel steps, positive away from the user
  int key = 0;                     // key_press, key_release: GLFW key code
  unsigned codepoint = 0;          // text
  std::vector<std::string> paths;  // drop

  /// Presses and releases of buttons and keys, and drops: at most one of these per frame.
  bool is_transition() const { return type != Type::move && type != Type::scroll && type != Type::text; }
};

/// Live events waiting for the next frame. A frame takes the events up to and including the first
/// transition, so that a press and its release never fall in one frame (Dear ImGui 1.86 would miss
/// the click): the rest wait for the following frames.
class InputQueue {
public:
  void push(InputEvent event) { events_.push_back(std::move(event)); }
  std::vector<InputEvent> take_frame();
  bool empty() const { return events_.empty(); }

private:
  std::deque<InputEvent> events_;
};

/// What the events so far leave pressed, and where the cursor is.
struct InputState {
  glm::vec2 cursor{0.0f};
  std::array<bool, 3> buttons{};
  std::array<bool, 512> keys{};

  void apply(const InputEvent& event);
  bool ctrl() const;
  bool shift() const;
  bool alt() const;
};

/// Hands one frame's events to Dear ImGui (1.86 API: MousePos, MouseDown, KeysDown, modifiers,
/// wheel, characters); `state` must already include them.
void feed_imgui(ImGuiIO& io, const InputState& state, const std::vector<InputEvent>& events);

/// Whether Dear ImGui saw `key` (an ImGuiKey_) go down this frame, through the key map.
bool imgui_key_pressed(ImGuiKey key);

/// Sets Dear ImGui's key map to GLFW key codes (1.86 looks keys up in KeysDown through it).
void map_imgui_keys(ImGuiIO& io);

/// The GLFW key code of a key name ("a", "7", "f1", "escape", "enter", "ctrl", "shift", ...); −1 if unknown.
int key_code(const std::string& name);
/// The name key_code() maps back to this code; "" if it has none.
std::string key_name(int code);

}  // namespace gps
