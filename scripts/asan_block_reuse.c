// Preloaded by scripts/sanitize.sh: C heap blocks over ASan's mmap threshold are kept for reuse
// instead of unmapped. ASan's allocator gives every block over 128 KiB a mapping of its own, and its
// realloc always moves, so llvmpipe, which mallocs and grows buffers of 130-260 KiB on every draw,
// faulted in and copied fresh pages some 20,000 times in one surface-cache test (48 s, most of it in
// the kernel, against 1.6 s without the sanitizer). Here such a block is taken from ASan rounded up
// to a power of two; freed, it is kept for the next request of its size; realloc grows in place
// where the block has room. Only C's malloc, calloc, realloc and free pass here (Mesa's): C++ new
// and delete are ASan's own. ASan's checks hold for these blocks too, reported as use-after-poison:
// - the bytes past a request, up to its block, are poisoned (an overflow);
// - a kept block is poisoned (a use after free), and freeing it again aborts (a double free);
// - the table of blocks in use holds their addresses inverted, so that LeakSanitizer does not take
//   it for a reference: a block leaked is reported, with its allocation's stack (the file is built
//   with frame pointers, so the stack goes on past it into the caller).
// A call passed on is a tail call (built with -O2): ASan then sees the caller's return address, by
// which LeakSanitizer leaves the dynamic linker's own allocations alone.
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

// ASan's, where the process has it. Weak: null in the processes around the tests (ctest, xvfb-run),
// which take the preload too and are given glibc's heap as it is.
#define ASAN_ENTRY __attribute__((weak))
ASAN_ENTRY void* __interceptor_malloc(size_t size);
ASAN_ENTRY void __interceptor_free(void* p);
ASAN_ENTRY void* __interceptor_calloc(size_t n, size_t size);
ASAN_ENTRY void* __interceptor_realloc(void* p, size_t size);
ASAN_ENTRY void __asan_poison_memory_region(void const volatile* p, size_t size);
ASAN_ENTRY void __asan_unpoison_memory_region(void const volatile* p, size_t size);
ASAN_ENTRY size_t __sanitizer_get_allocated_size(const void* p);
ASAN_ENTRY void __sanitizer_print_stack_trace(void);
void* __libc_malloc(size_t size);
void __libc_free(void* p);
void* __libc_calloc(size_t n, size_t size);
void* __libc_realloc(void* p, size_t size);

enum {
  kSmallestShift = 17,  // blocks over 128 KiB: ASan maps each of them
  kLargestShift = 26,   // up to 64 MiB
  kKeptPerSize = 8,
  kSlots = 1 << 12,  // blocks in use at once (a power of two)
};

struct Block {
  uintptr_t key;  // ~address; 0: an empty slot
  size_t size;    // asked for
  int shift;      // its capacity: 2^shift bytes
};

static struct Block in_use[kSlots];  // open addressing on the key
static void* kept[kLargestShift + 1][kKeptPerSize];
static int n_kept[kLargestShift + 1];

// A spin lock: ASan intercepts pthread_mutex_lock, and its interceptor is not set up yet when
// ASan's own start-up frees (in dlsym).
static int lock;
static void acquire(void) {
  while (__atomic_exchange_n(&lock, 1, __ATOMIC_ACQUIRE)) continue;
}
static void release(void) { __atomic_store_n(&lock, 0, __ATOMIC_RELEASE); }

static int handled(size_t size) { return size > ((size_t)1 << kSmallestShift) && size <= ((size_t)1 << kLargestShift); }

static int shift_of(size_t size) {
  int s = kSmallestShift + 1;
  while (((size_t)1 << s) < size) ++s;
  return s;
}

static uintptr_t key_of(const void* p) { return ~(uintptr_t)p; }

// The slot of p, or the empty slot where it would go; -1 when the table is full. Under the lock.
static long find(uintptr_t key) {
  size_t i = (size_t)((key >> 12) * 0x9E3779B97F4A7C15ull) & (kSlots - 1);
  for (int probe = 0; probe < kSlots; ++probe, i = (i + 1) & (kSlots - 1))
    if (in_use[i].key == key || in_use[i].key == 0) return (long)i;
  return -1;
}

// Empties slot i, moving back the entries after it that would no longer be found. Under the lock.
static void erase(size_t i) {
  in_use[i].key = 0;
  for (size_t j = (i + 1) & (kSlots - 1); in_use[j].key != 0; j = (j + 1) & (kSlots - 1)) {
    const struct Block b = in_use[j];
    in_use[j].key = 0;
    in_use[find(b.key)] = b;
  }
}

// The block in use at p; key 0 for any other pointer.
static struct Block block_at(const void* p) {
  acquire();
  const long i = find(key_of(p));
  const struct Block b = i >= 0 && in_use[i].key == key_of(p) ? in_use[i] : (struct Block){0, 0, 0};
  release();
  return b;
}

// Marks a block of capacity 2^shift as holding `size` bytes: the rest poisoned.
static void hold(void* p, size_t size, int shift) {
  __asan_unpoison_memory_region(p, size);
  __asan_poison_memory_region((char*)p + size, ((size_t)1 << shift) - size);
}

static int is_kept(const void* p) {
  for (int s = kSmallestShift + 1; s <= kLargestShift; ++s)
    for (int k = 0; k < n_kept[s]; ++k)
      if (kept[s][k] == p) return 1;
  return 0;
}

// A block of `size` bytes (handled()) from this file; NULL where its table is full (the caller then
// asks ASan).
static void* take(size_t size) {
  const int s = shift_of(size);
  acquire();
  void* p = n_kept[s] > 0 ? kept[s][--n_kept[s]] : NULL;
  release();
  if (p == NULL && (p = __interceptor_malloc((size_t)1 << s)) == NULL) return NULL;
  acquire();
  const long i = find(key_of(p));
  if (i >= 0) in_use[i] = (struct Block){key_of(p), size, s};
  release();
  if (i < 0) {
    __asan_unpoison_memory_region(p, (size_t)1 << s);
    __interceptor_free(p);
    return NULL;
  }
  hold(p, size, s);
  return p;
}

void* malloc(size_t size) {
  if (!__interceptor_malloc) return __libc_malloc(size);
  void* p = handled(size) ? take(size) : NULL;
  if (p != NULL) return p;
  return __interceptor_malloc(size);
}

void* calloc(size_t n, size_t size) {
  if (!__interceptor_calloc) return __libc_calloc(n, size);
  void* p = (size == 0 || n <= SIZE_MAX / size) && handled(n * size) ? take(n * size) : NULL;
  if (p == NULL) return __interceptor_calloc(n, size);
  return memset(p, 0, n * size);
}

void free(void* p) {
  if (!__interceptor_free) {
    __libc_free(p);
    return;
  }
  if (p == NULL) return;
  acquire();
  const long i = find(key_of(p));
  if (i < 0 || in_use[i].key != key_of(p)) {
    const int twice = is_kept(p);
    release();
    if (twice) {
      static const char message[] =
          "ERROR: AddressSanitizer (scripts/asan_block_reuse.c): attempting double-free of a kept block\n";
      (void)!write(2, message, sizeof message - 1);
      __sanitizer_print_stack_trace();
      abort();
    }
    __interceptor_free(p);
    return;
  }
  const int s = in_use[i].shift;
  erase((size_t)i);
  release();
  // Poisoned before it is listed: once listed, another thread may take it and unpoison it.
  __asan_poison_memory_region(p, (size_t)1 << s);
  acquire();
  const int keep = n_kept[s] < kKeptPerSize;
  if (keep) kept[s][n_kept[s]++] = p;
  release();
  if (!keep) {
    __asan_unpoison_memory_region(p, (size_t)1 << s);
    __interceptor_free(p);
  }
}

void* realloc(void* p, size_t size) {
  if (!__interceptor_realloc) return __libc_realloc(p, size);
  if (p == NULL) return malloc(size);
  if (size == 0) {
    free(p);
    return NULL;
  }
  const struct Block b = block_at(p);
  if (b.key == 0 && !handled(size)) return __interceptor_realloc(p, size);
  if (b.key != 0 && handled(size) && size <= ((size_t)1 << b.shift)) {  // room in its block
    acquire();
    in_use[find(b.key)].size = size;
    release();
    hold(p, size, b.shift);
    return p;
  }
  void* q = malloc(size);
  if (q == NULL) return NULL;
  const size_t old = b.key != 0 ? b.size : __sanitizer_get_allocated_size(p);
  memcpy(q, p, old < size ? old : size);
  free(p);
  return q;
}
