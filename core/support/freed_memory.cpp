#include "core/support/freed_memory.h"

#include <climits>  // also defines __GLIBC__ where it is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace gps {

void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_MAX, 0);              // no block from its own mapping (glibc still maps one if the heap cannot grow)
  mallopt(M_TRIM_THRESHOLD, INT_MAX);  // the heap's free top goes back to the system past 2 GiB only
#endif
}

}  // namespace gps
