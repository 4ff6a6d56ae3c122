// The renumbering of the surface cache's captured vertices (render/cache/stored_patch_renumbering.h),
// both ways (the compute pass, and the CPU in mapped memory), against the rule written out here: the
// patch word (the 10th of 12) becomes the patch's number now, −(number + 1) for a crease's edge point,
// and every other word stays as it was, bit for bit; copied runs land where they now lie.
#include "render/cache/stored_patch_renumbering.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "render/gl/gl_context.h"
#include "render/gl/gl_object.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

using StoredPatchRenumberingTest = test::GlTest;

constexpr int kWords = 12, kPatchWord = 9;

struct Case {
  std::vector<float> vertices;  // kWords a vertex
  std::vector<int> new_number;
};

// Vertices of random words, each naming a patch before (or its edge point) among `patches`, some of
// which have no number now (−1: their −(−1 + 1) is −0).
Case random_case(int n_vertices, int patches, unsigned seed) {
  std::mt19937 random(seed);
  Case c;
  c.new_number.resize(size_t(patches));
  for (int& n : c.new_number) n = random() % 5 == 0 ? -1 : int(random() % 100000);
  std::uniform_real_distribution<float> word(-10.0f, 10.0f);
  c.vertices.resize(size_t(n_vertices) * kWords);
  for (float& w : c.vertices) w = word(random);
  for (int v = 0; v < n_vertices; ++v) {
    const int patch = int(random() % unsigned(patches));
    c.vertices[size_t(v) * kWords + kPatchWord] = random() % 3 == 0 ? -float(patch + 1) : float(patch);
  }
  return c;
}

std::vector<float> renumbered(std::vector<float> vertices, const std::vector<int>& new_number) {
  for (size_t at = kPatchWord; at < vertices.size(); at += kWords) {
    const float p = vertices[at];
    vertices[at] = p >= 0.0f ? float(new_number[size_t(p)]) : -float(new_number[size_t(-p) - 1] + 1);
  }
  return vertices;
}

GlBuffer buffer_of(const std::vector<float>& words) {
  GlBuffer b;
  glNamedBufferData(b, GLsizeiptr(words.size() * sizeof(float)), words.data(), GL_DYNAMIC_DRAW);
  return b;
}

std::vector<float> read_back(unsigned buffer, size_t words) {
  std::vector<float> out(words);
  glGetNamedBufferSubData(buffer, 0, GLsizeiptr(words * sizeof(float)), out.data());
  check_gl_errors("reading the renumbered vertices");
  return out;
}

bool same_bytes(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST_F(StoredPatchRenumberingTest, InPlaceBothWaysFollowTheRule) {
  const Case c = random_case(50000, 3000, 3);  // past the CPU's parallel threshold
  const std::vector<float> expected = renumbered(c.vertices, c.new_number);
  for (const bool on_the_cpu : {false, true}) {
    StoredPatchRenumbering renumbering(on_the_cpu);
    const GlBuffer vertices = buffer_of(c.vertices);
    renumbering.run(vertices, 50000, c.new_number);
    EXPECT_TRUE(same_bytes(read_back(vertices, c.vertices.size()), expected)) << "on the CPU: " << on_the_cpu;
  }
}

TEST_F(StoredPatchRenumberingTest, CopiedRunsLandRenumberedWhereTheyNowLie) {
  // Triangles [0, 10) stay, [14, 40) move down by 4 (a deleted patch's), [40, 41) is dropped, and
  // [41, 60) follows [14, 40) as one run would.
  const Case c = random_case(3 * 60, 200, 5);
  const std::vector<SurfaceBlocks::Moved> runs = {{0, 0, 2, 0, 0, 10}, {3, 2, 5, 14, 10, 26}, {9, 7, 4, 41, 36, 19}};
  std::vector<float> moved;
  for (const SurfaceBlocks::Moved& m : runs)
    moved.insert(moved.end(), c.vertices.begin() + ptrdiff_t(m.old_first_triangle * 3 * kWords),
                 c.vertices.begin() + ptrdiff_t((m.old_first_triangle + m.triangles) * 3 * kWords));
  const std::vector<float> expected = renumbered(moved, c.new_number);
  for (const bool on_the_cpu : {false, true}) {
    StoredPatchRenumbering renumbering(on_the_cpu);
    const GlBuffer from = buffer_of(c.vertices), to = buffer_of(std::vector<float>(c.vertices.size(), 7.0f));
    renumbering.copy(from, to, runs, c.new_number);
    EXPECT_TRUE(same_bytes(read_back(to, expected.size()), expected)) << "on the CPU: " << on_the_cpu;
    EXPECT_TRUE(same_bytes(read_back(from, c.vertices.size()), c.vertices)) << "the source is left as it was";
  }
}

}  // namespace
}  // namespace gps
