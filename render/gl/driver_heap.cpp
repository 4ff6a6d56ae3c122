#include "render/gl/driver_heap.h"

#include <malloc.h>

#include <mutex>

namespace gps {

void retain_freed_heap() {
  static std::once_flag once;
  std::call_once(once, [] {
    // Up to 64 MiB free at the heap's top stays mapped; each growth asks for 16 MiB more than needed.
    mallopt(M_TRIM_THRESHOLD, 64 << 20);
    mallopt(M_TOP_PAD, 16 << 20);
  });
}

}  // namespace gps
