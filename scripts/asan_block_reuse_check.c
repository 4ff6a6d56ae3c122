// scripts/sanitize.sh runs this under ASan with scripts/asan_block_reuse.c preloaded, once per
// case, and expects the case's report: the reuse of large blocks must not hide what ASan finds.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kLarge = 200000 };  // over ASan's mmap threshold (128 KiB)

static char* large(void) {
  char* p = malloc(kLarge);
  memset(p, 1, kLarge);
  return p;
}

int main(int argc, char** argv) {
  const char* c = argc > 1 ? argv[1] : "";
  volatile char sink;
  if (!strcmp(c, "reused")) {  // no report; the preload is in effect: a freed block comes back
    char* p = large();
    free(p);
    char* q = malloc(kLarge);
    const int reused = p == q;
    free(q);
    return reused ? 0 : 1;
  }
  if (!strcmp(c, "overflow")) {
    char* p = large();
    sink = p[kLarge];
  } else if (!strcmp(c, "use-after-free")) {
    char* p = large();
    free(p);
    sink = p[10];
  } else if (!strcmp(c, "overflow-after-realloc")) {
    char* p = realloc(large(), kLarge + 1000);
    sink = p[kLarge + 1000];
  } else if (!strcmp(c, "double-free")) {
    char* p = large();
    free(p);
    free(p);
  } else if (!strcmp(c, "leak")) {
    sink = large()[0];
    return 0;
  }
  (void)sink;
  fprintf(stderr, "no report for case '%s'\n", c);
  return 0;
}
