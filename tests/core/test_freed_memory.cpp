// core/support/freed_memory.h: after keep_freed_memory(), a large block comes from the heap, not from a
// mapping of its own, and stays in the process when freed (ctest runs each test in its own process).
#include <gtest/gtest.h>

#include <climits>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "core/support/freed_memory.h"
#include "tests/support/sanitized_build.h"

#if defined(__GLIBC__) && !defined(GPS_SANITIZED)
#include <malloc.h>

namespace gps {
namespace {

constexpr size_t kLarge = size_t(64) << 20;  // past glibc's largest mmap threshold (32 MiB)

// Mapped blocks and the heap's bytes while a large block is held.
struct Held {
  size_t mapped_blocks, heap_bytes;
};

char* volatile g_block;  // through a volatile, so that the compiler keeps the allocation

Held while_holding_a_large_block() {
  g_block = static_cast<char*>(std::malloc(kLarge));
  std::memset(g_block, 1, kLarge);
  const struct mallinfo2 info = mallinfo2();
  std::free(g_block);
  return {info.hblks, info.arena};
}

TEST(FreedMemory, LargeBlocksComeFromTheHeapAndStayInTheProcess) {
  EXPECT_GE(while_holding_a_large_block().mapped_blocks, 1u);  // glibc's default: a mapping of its own
  keep_freed_memory();
  const Held held = while_holding_a_large_block();
  EXPECT_EQ(held.mapped_blocks, 0u);
  EXPECT_GE(held.heap_bytes, kLarge);
  EXPECT_GE(mallinfo2().arena, kLarge);  // freed, still the process's
}

// A library that asks to keep less (a GL context: 64 MiB for the driver's frames) after the program
// kept everything leaves it so: a freed block of 256 MiB stays the process's.
TEST(FreedMemory, ALaterSmallerKeptTopKeepsTheLarger) {
  keep_freed_memory();
  keep_freed_heap_top(64 << 20);
  constexpr size_t kHuge = 4 * kLarge;
  g_block = static_cast<char*>(std::malloc(kHuge));
  std::memset(g_block, 1, kHuge);
  std::free(g_block);
  EXPECT_GE(mallinfo2().arena, kHuge);
}

// The heap bytes of every arena while a thread other than the main one holds `blocks` blocks of 40 MiB,
// and after it freed them. Together they need more than one of the thread's 64 MiB heaps.
std::pair<size_t, size_t> a_threads_heaps(int blocks) {
  std::pair<size_t, size_t> bytes;
  std::thread([&] {
    constexpr size_t kBlock = size_t(40) << 20;
    std::vector<char*> held;
    for (int b = 0; b < blocks; ++b) {
      held.push_back(static_cast<char*>(std::malloc(kBlock)));
      std::memset(held.back(), 1, kBlock);
    }
    bytes.first = mallinfo2().arena;
    for (char* block : held) std::free(block);
    bytes.second = mallinfo2().arena;
  }).join();
  return bytes;
}

// glibc unmaps a thread's heap once it is empty, whatever the trim threshold, unless the top pad
// covers a heap (with its default pad, the heap of the third block goes back to the system):
// keep_freed_memory keeps them, and a GL context's smaller pad after it does not undo that.
TEST(FreedMemory, AThreadsFreedHeapsStayInTheProcess) {
  keep_freed_memory();
  pad_heap_top(16 << 20);
  const auto [held, freed] = a_threads_heaps(3);
  EXPECT_EQ(freed, held);
}

// The tunable glibc reads at a program's start, for the program run next.
TEST(FreedMemory, TheNextProgramIsAskedForHugePages) {
  unsetenv("GLIBC_TUNABLES");
  huge_page_heap_for_next_program();
  EXPECT_STREQ(std::getenv("GLIBC_TUNABLES"), "glibc.malloc.hugetlb=1");
  setenv("GLIBC_TUNABLES", "glibc.malloc.check=0", 1);
  huge_page_heap_for_next_program();
  EXPECT_STREQ(std::getenv("GLIBC_TUNABLES"), "glibc.malloc.check=0:glibc.malloc.hugetlb=1");
  setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=0", 1);  // the user's own choice stays
  huge_page_heap_for_next_program();
  EXPECT_STREQ(std::getenv("GLIBC_TUNABLES"), "glibc.malloc.hugetlb=0");
}

}  // namespace
}  // namespace gps
#else
TEST(FreedMemory, LargeBlocksComeFromTheHeapAndStayInTheProcess) { GTEST_SKIP() << "glibc's own malloc only"; }
#endif
