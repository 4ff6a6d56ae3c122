#include "core/support/memory_budget.h"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <string_view>

#include "core/support/quoted_text.h"
#include "core/support/error.h"

namespace gps {

namespace {

size_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::numeric_limits<size_t>::max();  // unknown: no limit of ours
  return size_t(pages) * size_t(page);
}

// "1,234,567" for a count; beyond what a long long carries, in scientific notation.
std::string count_text(double count) {
  if (!(count < 1e18)) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", count);
    return text;
  }
  const std::string digits = std::to_string(std::llround(count));
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// "3.2 GiB", "512.0 KiB", "800 bytes".
std::string bytes_text(double bytes) {
  static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return count_text(bytes) + " bytes";
  int unit = -1;
  while (bytes >= 1024 && unit + 1 < int(std::size(kUnits))) bytes /= 1024, ++unit;
  char text[48];
  std::snprintf(text, sizeof text, "%.1f %s", bytes, kUnits[unit]);
  return text;
}

}  // namespace

size_t memory_limit_bytes() {
  if (const char* value = std::getenv(kMemoryLimitVariable)) {
    const std::string_view text(value);
    char* end = nullptr;
    errno = 0;
    const unsigned long long bytes = std::strtoull(value, &end, 10);
    if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos || errno != 0 || bytes == 0)
      throw usage_error(std::string(kMemoryLimitVariable) + ": expected a positive whole number of bytes, got " +
                        quoted_token(text));
    return size_t(bytes);
  }
  return physical_memory_bytes() / 2;
}

void check_output_size(const OutputSize& size, const std::string& what, const std::string& faces_word,
                       const std::string& advice) {
  const size_t limit = memory_limit_bytes();
  constexpr double kMaxIndex = double(std::numeric_limits<int>::max());
  const bool too_many = size.vertices > kMaxIndex || size.faces > kMaxIndex;
  if (!too_many && size.bytes <= double(limit)) return;
  const std::string figures = what + " would make about " + count_text(size.vertices) + " vertices and " +
                              count_text(size.faces) + " " + faces_word + " and hold about " + bytes_text(size.bytes);
  if (too_many)
    throw usage_error(figures + ", more than the " + count_text(kMaxIndex) + " a mesh can index; " + advice);
  const std::string budget = std::getenv(kMemoryLimitVariable)
                                 ? std::string("set by ") + kMemoryLimitVariable
                                 : "half of this machine's " + bytes_text(double(physical_memory_bytes())) + "; " +
                                       kMemoryLimitVariable + " sets another";
  throw usage_error(figures + ", more than the " + bytes_text(double(limit)) + " allowed (" + budget + "); " + advice);
}

}  // namespace gps
