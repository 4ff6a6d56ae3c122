#pragma once
// Lowers a renderer's device limits on work groups per compute dispatch and on storage block bytes
// (0: the device's own), so that tests reach the dispatch split and the size refusal with meshes of
// test size. Applies from the next set_mesh / update_vertices.
#include "render/pipeline/surface_renderer.h"

namespace gps {

struct DeviceLimitsForTests {
  static void lower(SurfaceRenderer& renderer, int max_groups, long long max_storage_bytes) {
    renderer.group_limit_ = max_groups;
    renderer.storage_limit_ = max_storage_bytes;
  }
};

}  // namespace gps
