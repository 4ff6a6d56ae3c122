#pragma once
// What a test built with AddressSanitizer does otherwise. GPS_SANITIZED: defined where this test is built with AddressSanitizer, as gcc (__SANITIZE_ADDRESS__)
// and clang (__has_feature) each say it. Memory bounds and address-space limits hold in the plain
// build only: ASan's redzones, quarantine and shadow memory take more.
#if defined(__SANITIZE_ADDRESS__)
#define GPS_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GPS_SANITIZED 1
#endif
#endif

#include <vector>

namespace gps::test {

/// The valences `from`..`to` a test of the arithmetic goes through: all of them, or where ASan makes
/// that arithmetic many times slower (and every valence takes the same code paths), the first, the
/// last and every third between.
inline std::vector<int> valences(int from, int to) {
  std::vector<int> out;
  for (int n = from; n <= to; ++n) {
#ifdef GPS_SANITIZED
    if (n != from && n != to && (n - from) % 3 != 0) continue;
#endif
    out.push_back(n);
  }
  return out;
}

}  // namespace gps::test
