#pragma once
// The editor's commands in one table: label, shortcuts, whether enabled, the action. Key handling,
// the menus and the F1 help are all drawn from it, so a binding exists once.
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace gps {

/// A key with exactly these modifiers (GLFW key code).
struct Shortcut {
  int key = -1;
  bool ctrl = false, shift = false, alt = false;
  bool matches(int pressed, bool ctrl_down, bool shift_down, bool alt_down) const {
    return key == pressed && ctrl == ctrl_down && shift == shift_down && alt == alt_down;
  }
  /// "Ctrl+Shift+Z", "F1", "Numpad 5".
  std::string text() const;
};

struct Command {
  std::string menu;   // "File", "Edit", "View", "Help"; "" for keys only
  std::string label;  // menu label and help text
  std::vector<Shortcut> shortcuts = {};
  std::function<void()> action = nullptr;
  std::function<bool()> enabled = nullptr;  // null: always
  std::function<bool()> checked = nullptr;  // null: not a toggle
  std::function<void()> submenu = nullptr;  // instead of an action: draws the items of a submenu
  bool separator_before = false;
};

class CommandTable {
public:
  void add(Command command) { commands_.push_back(std::move(command)); }
  /// Runs the enabled command bound to this key and these modifiers; false when there is none. Where
  /// a key is bound to several, one with an enabled() test that passes now comes first (Shift+E:
  /// crease with edges selected, else the ellipsoids' toggle).
  bool handle_key(int key, bool ctrl, bool shift, bool alt) const;
  /// Called with a command's label where its key is pressed while it is disabled (to say why).
  void on_disabled_key(std::function<void(const std::string& label)> said) { disabled_key_ = std::move(said); }
  /// Runs the command with this label (menus and tests); false when there is none or it is disabled.
  bool run(const std::string& label) const;
  /// The menu names in first-use order.
  std::vector<std::string> menus() const;
  /// Draws the main menu bar from the table (between ImGui::NewFrame and ImGui::Render).
  void draw_menu_bar() const;
  /// (shortcuts, label) of every command that has a shortcut, for the help.
  std::vector<std::pair<std::string, std::string>> key_bindings() const;

private:
  static bool is_enabled(const Command& c) { return !c.enabled || c.enabled(); }
  std::vector<Command> commands_;
  std::function<void(const std::string&)> disabled_key_;
};

}  // namespace gps
