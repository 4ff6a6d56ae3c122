#include "ui/input/event_script.h"

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "../support/temp_dir.h"
#include "core/support/error.h"

namespace gps {
namespace {

using Type = InputEvent::Type;

std::vector<std::vector<InputEvent>> play_all(EventScript script) {
  std::vector<std::vector<InputEvent>> frames;
  while (!script.done()) frames.push_back(script.next_frame());
  return frames;
}

TEST(EventScript, OneTransitionPerFrameAndDragsMoveFrameByFrame) {
  const auto frames = play_all(EventScript::parse(R"({"events": [
    {"type": "click", "x": 10, "y": 20, "mods": "shift"},
    {"type": "wait", "frames": 3},
    {"type": "drag", "from": [100, 100], "to": [140, 60.5], "steps": 4},
    {"type": "key", "key": "ctrl+z"}
  ]})",
                                                  "test"));
  int transitions = 0, moves_in_drag = 0;
  for (const auto& f : frames) {
    int t = 0;
    for (const auto& e : f) t += e.is_transition();
    EXPECT_LE(t, 1);
    transitions += t;
    for (const auto& e : f) moves_in_drag += e.type == Type::move && e.position.x > 100.0f;
  }
  // shift down, press, release, shift up, press, release, ctrl down, z down, z up, ctrl up
  EXPECT_EQ(transitions, 10);
  EXPECT_EQ(moves_in_drag, 4);
  // The first frame presses shift; the click's press comes with the cursor already there.
  EXPECT_EQ(frames[0].back().type, Type::key_press);
  EXPECT_EQ(frames[0].back().key, GLFW_KEY_LEFT_SHIFT);
  EXPECT_EQ(frames[1].front().type, Type::move);
  EXPECT_EQ(frames[1].back().type, Type::press);
  EXPECT_EQ(frames[1].back().position, glm::vec2(10, 20));
  // The drag ends exactly where it was told, with fractional pixels kept.
  bool released_at_end = false;
  for (const auto& f : frames)
    for (const auto& e : f)
      released_at_end = released_at_end || (e.type == Type::release && e.position == glm::vec2(140.0f, 60.5f));
  EXPECT_TRUE(released_at_end);
  // Three empty frames for the wait.
  int empty = 0;
  for (const auto& f : frames) empty += f.empty();
  EXPECT_GE(empty, 3);
}

// The numpad's keys and the comma have names, as typed values and Blender's numpad views use them.
TEST(EventScript, NumpadKeysAndTheCommaHaveNames) {
  const std::pair<const char*, int> keys[] = {{"kpadd", GLFW_KEY_KP_ADD},
                                              {"kpsubtract", GLFW_KEY_KP_SUBTRACT},
                                              {"kpmultiply", GLFW_KEY_KP_MULTIPLY},
                                              {"kpdivide", GLFW_KEY_KP_DIVIDE},
                                              {"kpdecimal", GLFW_KEY_KP_DECIMAL},
                                              {"kpenter", GLFW_KEY_KP_ENTER},
                                              {"comma", GLFW_KEY_COMMA},
                                              {"kp7", GLFW_KEY_KP_7}};
  for (const auto& [name, code] : keys) {
    const auto frames =
        play_all(EventScript::parse(R"({"events": [{"type": "key", "key": ")" + std::string(name) + R"("}]})", "test"));
    bool pressed = false;
    for (const auto& f : frames)
      for (const auto& e : f) pressed = pressed || (e.type == Type::key_press && e.key == code);
    EXPECT_TRUE(pressed) << name;
  }
}

TEST(EventScript, ErrorsNameTheFileAndTheEvent) {
  const auto message = [](const std::string& text) {
    try {
      EventScript::parse(text, "events.json");
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("{").find("events.json: not valid JSON"), std::string::npos);
  EXPECT_NE(message("[]").find("events.json: expected"), std::string::npos);
  EXPECT_NE(message(R"({"events": [{"type": "wait", "frames": 1}, {"type": "jump"}]})")
                .find("events.json: event 1: unknown type 'jump'"),
            std::string::npos);
  EXPECT_NE(message(R"({"events": [{"type": "key", "key": "ctrl+nokey"}]})").find("event 0: unknown key 'nokey'"),
            std::string::npos);
  EXPECT_NE(message(R"({"events": [{"type": "press", "button": "fourth", "x": 1, "y": 2}]})").find("unknown button"),
            std::string::npos);
  EXPECT_NE(message(R"({"events": [{"type": "move", "x": 1}]})").find("event 0"), std::string::npos);
  EXPECT_THROW(EventScript::load("/nonexistent/events.json"), Error);
}

// Counts are taken only as the integers they become: 4294967297 frames does not wrap to one, 2.9
// is not cut to 2, and a number beyond a double is named, not reported by the JSON library. Other
// numbers (a scroll's steps, positions) have their range, and a value of another type names its key.
TEST(EventScript, CountsOutsideTheirRangeAreRefused) {
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {R"({"events": [{"type": "wait", "frames": 4294967297}]})",
            "events.json: event 0: frames must be an integer from 0 to 1000000, got 4294967297"},
           {R"({"events": [{"type": "wait", "frames": 2.9}]})",
            "events.json: event 0: frames must be an integer from 0 to 1000000, got 2.9"},
           {R"({"events": [{"type": "drag", "from": [0, 0], "to": [1, 1], "steps": 4294967306}]})",
            "events.json: event 0: steps must be an integer from 0 to 10000, got 4294967306"},
           {R"({"events": [{"type": "scroll", "steps": 4294967297, "x": 1, "y": 1}]})",
            "events.json: event 0: steps must be a number from -1000 to 1000, got 4294967297"},
           {R"({"events": [{"type": "move", "x": "", "y": 1}]})",
            "events.json: event 0: x must be a number from -1000000 to 1000000, got a string"},
           {R"({"events": [{"type": "drag", "from": [0, true], "to": [1, 1]}]})",
            "events.json: event 0: from: y must be a number from -1000000 to 1000000, got a boolean"},
           {R"({"events": [{"type": "key", "key": 5}]})", "events.json: event 0: key must be a string, got 5"},
           {R"({"events": [{"type": "wait", "frames": 1e400}]})",
            "events.json: events[0].frames: a number beyond the range of a double"}}) {
    try {
      EventScript::parse(text, "events.json");
      ADD_FAILURE() << text << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), message);
      EXPECT_EQ(e.kind(), Error::Kind::usage);
    }
  }
}

TEST(EventScript, RecordedInputReplaysFrameByFrame) {
  std::vector<std::vector<InputEvent>> live(9);
  const auto mouse = [](Type t, float x, float y, int button = 0) {
    InputEvent e;
    e.type = t;
    e.position = {x, y};
    e.button = button;
    return e;
  };
  live[0] = {mouse(Type::move, 1.25f, 2.5f), mouse(Type::press, 1.25f, 2.5f, 1)};
  live[3] = {mouse(Type::move, 30, 40), mouse(Type::release, 30, 40, 1)};
  InputEvent key;
  key.type = Type::key_press;
  key.key = GLFW_KEY_F12;
  live[4] = {key};
  InputEvent text;
  text.type = Type::text;
  text.codepoint = 0x03C3;  // σ
  live[5] = {text};
  InputEvent drop;
  drop.type = Type::drop;
  drop.paths = {"a b.ply"};
  live[8] = {drop};
  EventRecorder recorder;
  for (const auto& f : live) recorder.record_frame(f);
  const test::TempDir dir;
  recorder.save(dir.file("rec.json"));
  const auto replayed = play_all(EventScript::load(dir.file("rec.json")));
  // Same events in the same order; frames with events keep their order relative to the waits.
  std::vector<InputEvent> flat_live, flat_replayed;
  for (const auto& f : live) flat_live.insert(flat_live.end(), f.begin(), f.end());
  for (const auto& f : replayed) flat_replayed.insert(flat_replayed.end(), f.begin(), f.end());
  ASSERT_EQ(flat_live.size(), flat_replayed.size());
  for (size_t i = 0; i < flat_live.size(); ++i) {
    EXPECT_EQ(flat_live[i].type, flat_replayed[i].type) << i;
    EXPECT_EQ(flat_live[i].position, flat_replayed[i].position) << i;
    EXPECT_EQ(flat_live[i].button, flat_replayed[i].button) << i;
    EXPECT_EQ(flat_live[i].key, flat_replayed[i].key) << i;
    EXPECT_EQ(flat_live[i].codepoint, flat_replayed[i].codepoint) << i;
    EXPECT_EQ(flat_live[i].paths, flat_replayed[i].paths) << i;
  }
  EXPECT_GE(replayed.size(), live.size() - 1);
}

TEST(InputQueue, APressAndItsReleaseNeverShareAFrame) {
  InputQueue q;
  InputEvent move, press, release;
  press.type = Type::press;
  release.type = Type::release;
  q.push(move);
  q.push(press);
  q.push(release);
  q.push(move);
  EXPECT_EQ(q.take_frame().size(), 2u);  // move, press
  EXPECT_EQ(q.take_frame().size(), 1u);  // release
  EXPECT_EQ(q.take_frame().size(), 1u);  // move
  EXPECT_TRUE(q.empty());
  InputState state;
  state.apply(press);
  EXPECT_TRUE(state.buttons[0]);
  state.apply(release);
  EXPECT_FALSE(state.buttons[0]);
}

}  // namespace
}  // namespace gps
