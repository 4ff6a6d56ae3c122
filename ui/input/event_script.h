#pragma once
// Recorded input for scripted editor sessions (gpsurf-editor --play EVENTS.json, --record).
//
// The file is {"events": [ ... ]}, played in order, one frame after another:
//   {"type": "move", "x": X, "y": Y}                       cursor to window pixel (X, Y)
//   {"type": "press" | "release", "button": "left"|"right"|"middle", "x": X, "y": Y}
//   {"type": "click", "button": B, "x": X, "y": Y, "mods": "shift"}     move, press, release
//   {"type": "drag", "button": B, "from": [X, Y], "to": [X, Y], "steps": N, "mods": "ctrl"}
//                                                          press, N moves one frame each, release
//   {"type": "scroll", "steps": S, "x": X, "y": Y}          wheel steps at (X, Y)
//   {"type": "key", "key": "ctrl+shift+z"}                  modifiers down, key down and up, modifiers up
//   {"type": "key_press" | "key_release", "key": "z"}
//   {"type": "text", "text": "0.25"}                        characters typed
//   {"type": "drop", "paths": ["mesh.ply"]}                 files dropped on the window
//   {"type": "wait", "frames": N}                           N frames without input
// Coordinates are window pixels (origin top-left) and may be fractional. A frame takes events up
// to the first press, release or drop (see InputQueue), so playback does not depend on timing.
#include <string>
#include <vector>

#include "ui/input/input_events.h"

namespace gps {

class EventScript {
public:
  /// Reads an events file; throws gps::Error naming the file and the event on anything malformed.
  static EventScript load(const std::string& path);
  /// Parses events JSON text; `source` names it in errors.
  static EventScript parse(const std::string& text, const std::string& source);

  /// The events of the next frame (none while waiting).
  std::vector<InputEvent> next_frame();
  bool done() const { return next_ >= steps_.size(); }

private:
  struct Step {
    InputEvent event;
    int wait_frames = 0;    // > 0: a pause instead of an event
    bool boundary = false;  // ends the frame that has events (a drag's moves go one per frame)
  };
  std::vector<Step> steps_;
  size_t next_ = 0;
  int waited_ = 0;
};

/// Collects live input frame by frame and writes it as an events file that --play replays.
class EventRecorder {
public:
  void record_frame(const std::vector<InputEvent>& events);
  /// Writes the file atomically; throws gps::Error naming it.
  void save(const std::string& path) const;

private:
  std::vector<std::string> lines_;  // one JSON object per event
  int idle_frames_ = 0;
  void flush_wait(std::vector<std::string>& lines) const;
};

}  // namespace gps
