// Preloaded by scripts/sanitize.sh: dlclose does nothing, so the libraries Mesa's loaders open
// (libEGL_mesa, libGLX_mesa, the DRI driver) stay mapped until the process exits. LeakSanitizer
// checks at exit; a library unloaded before then takes its globals with it, and what they pointed to
// looks leaked, with only "<unknown module>" in its stack, which no suppression can name. Kept
// loaded, those allocations stay reachable, as they are in every run without the sanitizer.
int dlclose(void* handle) {
  (void)handle;
  return 0;
}
