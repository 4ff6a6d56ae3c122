#include "render/cache/exclusive_scan.h"

#include <glad/gl.h>

#include <algorithm>
#include <vector>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "shaders/embedded_shaders.h"

namespace gps {

namespace {

constexpr long long kTile = 64;  // shaders/scan_comp.glsl's kScanTile

// Where each level starts in the buffer and how many values it has: the values, then their tiles'
// totals, up to a level of one (the grand total).
struct Level {
  long long first, length;
};

std::vector<Level> levels_of(long long count) {
  std::vector<Level> levels{{0, count}};
  do {
    const Level l = levels.back();
    levels.push_back({l.first + l.length, (l.length + kTile - 1) / kTile});
  } while (levels.back().length > 1);
  return levels;
}

}  // namespace

ExclusiveScan::ExclusiveScan()
    : scan_tiles_("scan_tiles", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::scan_comp}}}),
      add_tile_offsets_(
          "add_tile_offsets",
          {{GL_COMPUTE_SHADER, {shaders::gpu_layout, "#define ADD_TILE_OFFSETS\n", shaders::scan_comp}}}) {}

unsigned ExclusiveScan::bind(long long count) {
  const Level last = levels_of(std::max(count, 1ll)).back();
  const long long needed = last.first + last.length;
  if (needed > capacity_ || 4 * needed < capacity_) {
    capacity_ = needed;
    glNamedBufferData(values_, GLsizeiptr(capacity_ * 4), nullptr, GL_DYNAMIC_COPY);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingScanValues, values_);
  return values_;
}

void ExclusiveScan::run(long long count) {
  if (count <= 0) return;
  const std::vector<Level> levels = levels_of(count);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingScanValues, values_);
  // Up: each level's tiles scanned, their totals the next level's values.
  for (size_t k = 0; k + 1 < levels.size(); ++k) {
    scan_tiles_.use();
    scan_tiles_.set("u_level", int(levels[k].first));
    scan_tiles_.set("u_length", int(levels[k].length));
    scan_tiles_.set("u_totals", int(levels[k + 1].first));
    run_compute_pass(scan_tiles_, int(levels[k + 1].length), false, 0);
  }
  // Down: each level's values add their tile's sum before it, from the scanned level above.
  for (size_t k = levels.size() - 1; k-- > 0;) {
    if (levels[k].length <= kTile) continue;  // one tile: its sum before is 0
    add_tile_offsets_.use();
    add_tile_offsets_.set("u_level", int(levels[k].first));
    add_tile_offsets_.set("u_length", int(levels[k].length));
    add_tile_offsets_.set("u_totals", int(levels[k + 1].first));
    run_compute_pass(add_tile_offsets_, int(levels[k].length), false, 0);
  }
  check_gl_errors("summing on the GPU");
}

}  // namespace gps
