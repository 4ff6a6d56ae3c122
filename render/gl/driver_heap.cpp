#include "render/gl/driver_heap.h"

#include <mutex>

#include "core/support/freed_memory.h"

namespace gps {

void retain_freed_heap() {
  static std::once_flag once;
  std::call_once(once, [] {
    // At least 64 MiB free at the heap's top stays mapped; each growth asks for 16 MiB more than needed.
    keep_freed_heap_top(64 << 20);
    pad_heap_top(16 << 20);
  });
}

}  // namespace gps
