#include "ui/input/command_table.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>

#include "ui/input/input_events.h"

namespace gps {

std::string Shortcut::text() const {
  std::string name;
  if (key >= GLFW_KEY_KP_0 && key <= GLFW_KEY_KP_9) {
    name = "Numpad " + std::to_string(key - GLFW_KEY_KP_0);
  } else if (key == GLFW_KEY_KP_ADD || key == GLFW_KEY_KP_SUBTRACT) {
    name = key == GLFW_KEY_KP_ADD ? "Numpad +" : "Numpad -";
  } else {
    name = key_name(key);
    if (name.size() == 1)
      name[0] = char(std::toupper(static_cast<unsigned char>(name[0])));
    else if (!name.empty() && name[0] == 'f' && name.size() <= 3)
      name[0] = 'F';
    else if (!name.empty())
      name[0] = char(std::toupper(static_cast<unsigned char>(name[0])));
  }
  return std::string(ctrl ? "Ctrl+" : "") + (shift ? "Shift+" : "") + (alt ? "Alt+" : "") + name;
}

bool CommandTable::handle_key(int key, bool ctrl, bool shift, bool alt) const {
  const auto bound = [&](const Command& c) {
    return c.action && std::any_of(c.shortcuts.begin(), c.shortcuts.end(),
                                   [&](const Shortcut& s) { return s.matches(key, ctrl, shift, alt); });
  };
  // A command enabled only in some states takes a shared key first while it is enabled.
  for (const Command& c : commands_)
    if (bound(c) && c.enabled && c.enabled()) {
      c.action();
      return true;
    }
  for (const Command& c : commands_)
    if (bound(c)) {
      if (is_enabled(c))
        c.action();
      else if (disabled_key_)
        disabled_key_(c.label);
      return true;
    }
  return false;
}

bool CommandTable::run(const std::string& label) const {
  for (const Command& c : commands_)
    if (c.label == label && c.action && is_enabled(c)) {
      c.action();
      return true;
    }
  return false;
}

std::vector<std::string> CommandTable::menus() const {
  std::vector<std::string> names;
  for (const Command& c : commands_)
    if (!c.menu.empty() && std::find(names.begin(), names.end(), c.menu) == names.end()) names.push_back(c.menu);
  return names;
}

void CommandTable::draw_menu_bar() const {
  if (!ImGui::BeginMainMenuBar()) return;
  for (const std::string& menu : menus()) {
    if (!ImGui::BeginMenu(menu.c_str())) continue;
    for (const Command& c : commands_) {
      if (c.menu != menu) continue;
      if (c.separator_before) ImGui::Separator();
      if (c.submenu) {
        if (ImGui::BeginMenu(c.label.c_str(), is_enabled(c))) {
          c.submenu();
          ImGui::EndMenu();
        }
        continue;
      }
      const std::string shortcut = c.shortcuts.empty() ? "" : c.shortcuts.front().text();
      if (ImGui::MenuItem(c.label.c_str(), shortcut.empty() ? nullptr : shortcut.c_str(), c.checked && c.checked(),
                          is_enabled(c)) &&
          c.action)
        c.action();
    }
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

std::vector<std::pair<std::string, std::string>> CommandTable::key_bindings() const {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const Command& c : commands_) {
    if (c.shortcuts.empty()) continue;
    std::string keys;
    for (const Shortcut& s : c.shortcuts) keys += (keys.empty() ? "" : ", ") + s.text();
    rows.emplace_back(keys, c.label);
  }
  return rows;
}

}  // namespace gps
