// The GPU's exclusive prefix sum (render/cache/exclusive_scan.h) against std::exclusive_scan, at the
// sizes where its levels change: one tile, one more than a tile, tiles of tiles, and many levels.
#include "render/cache/exclusive_scan.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

using ExclusiveScanTest = test::GlTest;

std::vector<GLuint> scanned_on_gpu(ExclusiveScan& scan, const std::vector<GLuint>& values) {
  const long long n = (long long)values.size();
  const unsigned buffer = scan.bind(n);
  glNamedBufferSubData(buffer, 0, GLsizeiptr(values.size() * sizeof(GLuint)), values.data());
  scan.run(n);
  std::vector<GLuint> sums(values.size());
  glGetNamedBufferSubData(buffer, 0, GLsizeiptr(sums.size() * sizeof(GLuint)), sums.data());
  check_gl_errors("reading the sums");
  return sums;
}

TEST_F(ExclusiveScanTest, EqualsTheSerialSum) {
  ExclusiveScan scan;
  std::mt19937 random(7);
  for (const int n : {1, 2, 63, 64, 65, 4095, 4096, 4097, 64 * 64 * 64 + 1, 1000003}) {
    std::vector<GLuint> values(static_cast<size_t>(n));
    for (GLuint& v : values) v = random() % 3;  // the weld's flags are 0 or 1; 2 for carries
    std::vector<GLuint> expected(values.size());
    std::exclusive_scan(values.begin(), values.end(), expected.begin(), GLuint(0));
    const std::vector<GLuint> sums = scanned_on_gpu(scan, values);
    size_t first_wrong = 0;
    while (first_wrong < sums.size() && sums[first_wrong] == expected[first_wrong]) ++first_wrong;
    EXPECT_EQ(first_wrong, sums.size()) << n << " values: the sum before value " << first_wrong << " is "
                                        << sums[std::min(first_wrong, sums.size() - 1)];
  }
}

}  // namespace
}  // namespace gps
