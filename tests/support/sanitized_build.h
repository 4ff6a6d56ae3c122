#pragma once
// GPS_SANITIZED: defined where this test is built with AddressSanitizer, as gcc (__SANITIZE_ADDRESS__)
// and clang (__has_feature) each say it. Memory bounds and address-space limits hold in the plain
// build only: ASan's redzones, quarantine and shadow memory take more.
#if defined(__SANITIZE_ADDRESS__)
#define GPS_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GPS_SANITIZED 1
#endif
#endif
