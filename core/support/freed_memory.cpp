#include "core/support/freed_memory.h"

#include <atomic>
#include <climits>  // also defines __GLIBC__ where it is glibc
#include <cstdlib>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace gps {

namespace {
// The largest byte counts asked for so far (0: glibc's own).
std::atomic<int> kept_heap_top{0}, heap_top_pad{0};
// glibc serves a thread other than the main one from heaps of this size (64-bit HEAP_MAX_SIZE), and
// unmaps a heap as soon as it is empty, whatever the trim threshold, unless the top pad would keep at
// least this much (malloc/arena.c, heap_trim): every call of a worker thread would otherwise fault its
// tens of MB in again.
constexpr int kThreadHeapBytes = 64 << 20;

// Sets glibc's malloc option to `bytes` unless an earlier call asked for more (`largest`).
void raise_malloc_option([[maybe_unused]] int option, std::atomic<int>& largest, int bytes) {
  if (largest.load() >= bytes) return;
  largest = bytes;
#if defined(__GLIBC__)
  mallopt(option, bytes);
#endif
}

#if !defined(__GLIBC__)
constexpr int M_TRIM_THRESHOLD = 0, M_TOP_PAD = 0;  // not read: no such settings
#endif
}  // namespace

void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);  // no block from its own mapping (glibc still maps one if the heap cannot grow)
#endif
  keep_freed_heap_top(INT_MAX);  // the heap's free top goes back to the system past 2 GiB only
  pad_heap_top(kThreadHeapBytes);
}

void keep_freed_heap_top(int bytes) { raise_malloc_option(M_TRIM_THRESHOLD, kept_heap_top, bytes); }

void pad_heap_top(int bytes) { raise_malloc_option(M_TOP_PAD, heap_top_pad, bytes); }

void huge_page_heap_for_next_program() {
#if defined(__GLIBC__)
  const char* set = std::getenv("GLIBC_TUNABLES");
  const std::string tunables = set ? set : "";
  if (tunables.find("glibc.malloc.hugetlb") != std::string::npos) return;
  const std::string wanted = (tunables.empty() ? "" : tunables + ":") + "glibc.malloc.hugetlb=1";
  setenv("GLIBC_TUNABLES", wanted.c_str(), 1);
#endif
}

}  // namespace gps
