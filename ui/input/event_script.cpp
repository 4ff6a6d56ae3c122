#include "ui/input/event_script.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/atomic_file.h"
#include "core/io/json_text.h"
#include "core/support/quoted_text.h"
#include "core/support/error.h"
#include "core/io/text_file.h"

namespace gps {

namespace {

using Json = nlohmann::json;

// The integer at `key` of an event, from `lo` to `hi` (1.9 and 4294967297 are refused, not cut).
int integer_of(const Json& e, const char* key, int lo, int hi) {
  try {
    return int(json_integer(e.at(key), lo, hi));
  } catch (const Error& x) {
    throw usage_error(std::string(key) + " " + x.what());
  }
}

// The number at `key` of an event, from `lo` to `hi` (a scroll's steps may be fractional, as a
// touchpad's are); another type, or one out of range, is refused naming the key.
float number_of(const Json& e, const char* key, long long lo, long long hi) {
  const Json& value = e.at(key);
  const double x = value.is_number() ? value.get<double>() : std::nan("");
  if (!(x >= double(lo) && x <= double(hi)))
    throw usage_error(std::string(key) + " must be a number from " + json_shown(lo) + " to " + json_shown(hi) +
                      ", got " + json_shown(value));
  return float(x);
}

// The string at `key` of an event; another type is refused naming the key.
std::string text_of(const Json& e, const char* key) {
  const Json& value = e.at(key);
  if (!value.is_string()) throw usage_error(std::string(key) + " must be a string, got " + json_shown(value));
  return value.get<std::string>();
}

int button_of(const Json& e) {
  const std::string name = e.value("button", std::string("left"));
  if (name == "left") return 0;
  if (name == "right") return 1;
  if (name == "middle") return 2;
  throw usage_error("unknown button " + quoted_token(name) + " (left, right or middle)");
}

std::string button_name(int button) { return button == 1 ? "right" : button == 2 ? "middle" : "left"; }

// Window positions: finite, within a generous margin of any window.
constexpr long long kFarthestPixel = 1000000;

glm::vec2 xy_of(const Json& e) {
  return {number_of(e, "x", -kFarthestPixel, kFarthestPixel), number_of(e, "y", -kFarthestPixel, kFarthestPixel)};
}

glm::vec2 point_of(const Json& e, const char* key) {
  const Json& p = e.at(key);
  if (!p.is_array() || p.size() != 2) throw usage_error(std::string("'") + key + "' needs [x, y]");
  try {
    return xy_of(Json{{"x", p[0]}, {"y", p[1]}});
  } catch (const Error& x) {
    throw usage_error(std::string(key) + ": " + x.what());
  }
}

// "ctrl+shift+z" → the key codes, modifiers first.
std::vector<int> chord_of(const std::string& chord) {
  std::vector<int> keys;
  std::stringstream in(chord);
  for (std::string name; std::getline(in, name, '+');) {
    const int code = key_code(name);
    if (code < 0) throw usage_error("unknown key " + quoted_token(name));
    keys.push_back(code);
  }
  if (keys.empty()) throw usage_error("empty key");
  return keys;
}

// UTF-8 to code points (what GLFW's character callback reports).
std::vector<unsigned> code_points(const std::string& text) {
  std::vector<unsigned> out;
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    const int length = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (length == 0 || i + size_t(length) > text.size()) throw usage_error("text is not valid UTF-8");
    unsigned cp = length == 1 ? c : c & (0xFF >> (length + 1));
    for (int k = 1; k < length; ++k) cp = (cp << 6) | (static_cast<unsigned char>(text[i + size_t(k)]) & 0x3F);
    out.push_back(cp);
    i += size_t(length);
  }
  return out;
}

}  // namespace

EventScript EventScript::load(const std::string& path) { return parse(read_text_file(path), path); }

EventScript EventScript::parse(const std::string& text, const std::string& source) {
  const Json doc = parse_json(text, source);
  if (!doc.is_object() || !doc.contains("events") || !doc["events"].is_array())
    throw usage_error(source + ": expected {\"events\": [ ... ]}");
  EventScript script;
  auto& steps = script.steps_;
  const auto add = [&steps](InputEvent e) { steps.push_back({std::move(e), 0}); };
  const auto wait = [&steps](int frames) { steps.push_back({InputEvent{}, frames, false}); };
  const auto boundary = [&steps] { steps.push_back({InputEvent{}, 0, true}); };
  const auto mouse = [](InputEvent::Type type, glm::vec2 p, int button = 0) {
    InputEvent e;
    e.type = type;
    e.position = p;
    e.button = button;
    return e;
  };
  const auto key = [](InputEvent::Type type, int code) {
    InputEvent e;
    e.type = type;
    e.key = code;
    return e;
  };
  size_t index = 0;
  for (const Json& e : doc["events"]) {
    try {
      if (!e.is_object()) throw usage_error("expected an object");
      const std::string type = text_of(e, "type");
      const std::vector<int> mods = e.contains("mods") ? chord_of(text_of(e, "mods")) : std::vector<int>{};
      if (type == "move") {
        add(mouse(InputEvent::Type::move, xy_of(e)));
      } else if (type == "press" || type == "release") {
        add(mouse(type == "press" ? InputEvent::Type::press : InputEvent::Type::release, xy_of(e), button_of(e)));
      } else if (type == "click" || type == "drag") {
        for (const int m : mods) add(key(InputEvent::Type::key_press, m));
        const glm::vec2 from = type == "click" ? xy_of(e) : point_of(e, "from");
        const glm::vec2 to = type == "click" ? from : point_of(e, "to");
        const int button = button_of(e);
        const int n = type == "click" ? 0 : e.contains("steps") ? integer_of(e, "steps", 0, 10000) : 10;
        add(mouse(InputEvent::Type::move, from));
        add(mouse(InputEvent::Type::press, from, button));
        for (int s = 1; s <= n; ++s) {
          add(mouse(InputEvent::Type::move, from + (to - from) * (float(s) / float(n))));
          boundary();
        }
        add(mouse(InputEvent::Type::release, to, button));
        for (auto m = mods.rbegin(); m != mods.rend(); ++m) add(key(InputEvent::Type::key_release, *m));
      } else if (type == "scroll") {
        InputEvent s = mouse(InputEvent::Type::scroll, xy_of(e));
        s.steps = number_of(e, "steps", -1000, 1000);
        add(s);
        boundary();
      } else if (type == "key") {
        const std::vector<int> chord = chord_of(text_of(e, "key"));
        for (const int k : chord) add(key(InputEvent::Type::key_press, k));
        for (auto k = chord.rbegin(); k != chord.rend(); ++k) add(key(InputEvent::Type::key_release, *k));
      } else if (type == "key_press" || type == "key_release") {
        for (const int k : chord_of(text_of(e, "key")))
          add(key(type == "key_press" ? InputEvent::Type::key_press : InputEvent::Type::key_release, k));
      } else if (type == "text") {
        for (const unsigned cp : code_points(text_of(e, "text"))) {
          InputEvent t;
          t.type = InputEvent::Type::text;
          t.codepoint = cp;
          add(t);
        }
        boundary();
      } else if (type == "drop") {
        InputEvent d;
        d.type = InputEvent::Type::drop;
        d.paths = e.at("paths").get<std::vector<std::string>>();
        add(d);
      } else if (type == "wait") {
        const int frames = integer_of(e, "frames", 0, 1000000);
        if (frames > 0) wait(frames);
      } else {
        throw usage_error("unknown type " + quoted_token(type));
      }
    } catch (const Json::exception& x) {
      throw usage_error(source + ": event " + std::to_string(index) + ": " + json_error_words(x));
    } catch (const Error& x) {
      throw usage_error(source + ": event " + std::to_string(index) + ": " + x.what());
    }
    ++index;
  }
  return script;
}

std::vector<InputEvent> EventScript::next_frame() {
  std::vector<InputEvent> frame;
  while (next_ < steps_.size()) {
    const Step& s = steps_[next_];
    if (s.boundary) {
      ++next_;
      if (!frame.empty()) break;
      continue;
    }
    if (s.wait_frames > 0) {
      if (!frame.empty()) break;  // the pause starts with the next frame
      if (++waited_ >= s.wait_frames) waited_ = 0, ++next_;
      break;
    }
    frame.push_back(s.event);
    ++next_;
    if (s.event.is_transition()) break;
  }
  return frame;
}

void EventRecorder::flush_wait(std::vector<std::string>& lines) const {
  if (idle_frames_ > 0) lines.push_back(Json{{"type", "wait"}, {"frames", idle_frames_}}.dump());
}

void EventRecorder::record_frame(const std::vector<InputEvent>& events) {
  if (events.empty()) {
    ++idle_frames_;
    return;
  }
  // A frame that had events is followed by at least the frame boundary: frames with events end at
  // their transition anyway, so only the idle frames in between need a wait.
  flush_wait(lines_);
  idle_frames_ = 0;
  for (const InputEvent& e : events) {
    Json j;
    switch (e.type) {
      case InputEvent::Type::move:
        j = {{"type", "move"}, {"x", e.position.x}, {"y", e.position.y}};
        break;
      case InputEvent::Type::press:
      case InputEvent::Type::release:
        j = {{"type", e.type == InputEvent::Type::press ? "press" : "release"},
             {"button", button_name(e.button)},
             {"x", e.position.x},
             {"y", e.position.y}};
        break;
      case InputEvent::Type::scroll:
        j = {{"type", "scroll"}, {"steps", e.steps}, {"x", e.position.x}, {"y", e.position.y}};
        break;
      case InputEvent::Type::key_press:
      case InputEvent::Type::key_release: {
        const std::string name = key_name(e.key);
        if (name.empty()) continue;  // keys the editor has no use for
        j = {{"type", e.type == InputEvent::Type::key_press ? "key_press" : "key_release"}, {"key", name}};
        break;
      }
      case InputEvent::Type::text: {
        std::string utf8;
        const unsigned c = e.codepoint;
        if (c < 0x80)
          utf8 += char(c);
        else if (c < 0x800)
          utf8 += {char(0xC0 | (c >> 6)), char(0x80 | (c & 0x3F))};
        else if (c < 0x10000)
          utf8 += {char(0xE0 | (c >> 12)), char(0x80 | ((c >> 6) & 0x3F)), char(0x80 | (c & 0x3F))};
        else
          utf8 += {char(0xF0 | (c >> 18)), char(0x80 | ((c >> 12) & 0x3F)), char(0x80 | ((c >> 6) & 0x3F)),
                   char(0x80 | (c & 0x3F))};
        j = {{"type", "text"}, {"text", utf8}};
        break;
      }
      case InputEvent::Type::drop:
        j = {{"type", "drop"}, {"paths", e.paths}};
        break;
    }
    lines_.push_back(j.dump());
  }
}

void EventRecorder::save(const std::string& path) const {
  std::vector<std::string> lines = lines_;
  flush_wait(lines);
  write_file_atomically(path, [&lines](std::ostream& out) {
    out << "{\"events\": [\n";
    for (size_t i = 0; i < lines.size(); ++i) out << "  " << lines[i] << (i + 1 < lines.size() ? ",\n" : "\n");
    out << "]}\n";
  });
}

}  // namespace gps
