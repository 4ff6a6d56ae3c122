#pragma once
// An exclusive prefix sum of unsigned values on the GPU (shaders/scan_comp.glsl): the values lie in
// a storage buffer at binding kBindingScanValues, written there by an earlier pass, and become
// their exclusive sums in place. Tiles of 64 values are summed serially, their totals scanned one
// level up the same way, and added back: levels of n, n/64, n/64², ... values.
#include "render/gl/gl_object.h"
#include "render/gl/shader_program.h"

namespace gps {

class ExclusiveScan {
public:
  /// Needs a current GL context.
  ExclusiveScan();
  ExclusiveScan(const ExclusiveScan&) = delete;
  ExclusiveScan& operator=(const ExclusiveScan&) = delete;

  /// Sizes the values' buffer for `count` values and their levels, binds it at kBindingScanValues
  /// (values 0 to count − 1 for a pass to write) and returns it.
  unsigned bind(long long count);
  /// Replaces values 0 to count − 1 of the bound buffer by their exclusive sums, after a storage
  /// barrier (the writer's barrier orders them before).
  void run(long long count);
  size_t bytes() const { return size_t(capacity_) * 4; }

private:
  ShaderProgram scan_tiles_, add_tile_offsets_;
  GlBuffer values_;
  long long capacity_ = 0;  // values the buffer holds
};

}  // namespace gps
