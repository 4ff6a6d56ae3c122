#pragma once
// The memory a computation may plan to hold, and the check of an output's estimated size against it,
// made before the work starts, so that what cannot fit is refused with its figures instead of
// growing until the allocator or the kernel ends the process.
#include <cstddef>
#include <string>

namespace gps {

/// The environment variable that sets the budget in bytes (tests, shared machines); read in
/// memory_limit_bytes() only.
inline constexpr const char* kMemoryLimitVariable = "GPSURF_MEMORY_LIMIT_BYTES";

/// What a computation will make and hold, estimated before it starts. Doubles: an estimate may
/// exceed every integer type.
struct OutputSize {
  double vertices = 0;
  double faces = 0;
  double bytes = 0;  ///< held at the peak
};

/// The bytes a computation may plan to hold: $GPSURF_MEMORY_LIMIT_BYTES where set, else half the
/// machine's physical memory. Throws a usage error where the variable is not a positive whole number.
size_t memory_limit_bytes();

/// Throws a usage error giving the figures where `size` exceeds memory_limit_bytes() or its counts
/// exceed what an int indexes: "<what> would make about V vertices and F <faces_word> and hold about
/// B, more than the L allowed (...); <advice>".
void check_output_size(const OutputSize& size, const std::string& what, const std::string& faces_word,
                       const std::string& advice);

}  // namespace gps
