// Linked into every executable of the `asan` preset only
// (cmake/sanitizer_support.cmake). LeakSanitizer reports at exit and
// attributes each allocation to the module that made it; by then the Vulkan
// loader has dlclose()d the validation layer (and lavapipe), so their leaks
// appear as "<unknown module>", match no line of lsan.supp and fail the test.
// This dlclose keeps every module mapped until the process ends, so their
// leaks are named and suppressed, and nothing else changes: a module opened
// again gets the same handle.
extern "C" int dlclose(void*) {
  return 0;
}
