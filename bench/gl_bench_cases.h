#pragma once
// What the Google Benchmarks of GL frames share (bench_frames.cpp, bench_plan_depth.cpp): the
// context, a sample by name and size and the names of tessellation settings.

#include <memory>
#include <string>

#include "render/gl/gl_context.h"

namespace gps::bench {

/// A sample mesh: NAME, or NAME:FACES where `faces` is not 0.
struct MeshCase {
  std::string name;
  int faces;
  std::string id() const { return name + (faces ? ":" + std::to_string(faces) : ""); }
};

/// One context for the whole run: the GPU's EGL device where there is one, else OSMesa.
inline GlContext& context() {
  static const std::unique_ptr<GlContext> c = create_offscreen_context(ContextKind::automatic);
  return *c;
}

/// "levelN" for a uniform level N, "adaptive6px" for 0 (adaptive levels of 6-pixel edges).
inline std::string setting_name(int level) { return level ? "level" + std::to_string(level) : "adaptive6px"; }

}  // namespace gps::bench
