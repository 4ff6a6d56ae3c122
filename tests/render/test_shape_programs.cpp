// A pass's programs by patch shape and precision are compiled when first used: the other shape's
// never, a new precision's first program when it is chosen (so that a driver's refusal comes then,
// the previous precision kept), and none twice.
#include "render/gl/shape_programs.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "core/support/error.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

using ShapeProgramsTest = test::GlTest;
using Key = std::pair<PatchShape, PointPrecision>;

// Programs that do nothing, counted as they are built; the double ones are refused where `refuse_double`.
ShapePrograms::Build counted(std::map<Key, int>& builds, bool refuse_double = false) {
  return [&builds, refuse_double](PatchShape shape, PointPrecision precision) {
    if (refuse_double && precision == PointPrecision::double_float) throw Error("no doubles here");
    ++builds[{shape, precision}];
    return ShaderProgram("empty", {{GL_COMPUTE_SHADER, {"layout(local_size_x = 1) in;\nvoid main() {}\n"}}});
  };
}

TEST_F(ShapeProgramsTest, EachIsBuiltAtItsFirstUseOnly) {
  std::map<Key, int> builds;
  const ShapePrograms programs(counted(builds));
  EXPECT_TRUE(builds.empty()) << "nothing is built before it is used";
  EXPECT_FALSE(programs.built(PatchShape::quad));
  const unsigned quads = programs(PatchShape::quad).id();
  EXPECT_NE(quads, 0u);
  EXPECT_EQ(programs(PatchShape::quad).id(), quads) << "the same program, not another";
  EXPECT_TRUE(programs.built(PatchShape::quad));
  EXPECT_FALSE(programs.built(PatchShape::triangle)) << "a mesh of quads compiles no triangle program";
  EXPECT_EQ(builds, (std::map<Key, int>{{{PatchShape::quad, PointPrecision::single_float}, 1}}));
}

TEST_F(ShapeProgramsTest, ANewPrecisionIsCheckedWhenChosen) {
  std::map<Key, int> builds;
  ShapePrograms programs(counted(builds));
  programs(PatchShape::triangle);
  programs.set_precision(PointPrecision::double_float);
  EXPECT_EQ(builds[Key(PatchShape::quad, PointPrecision::double_float)], 1) << "built as the check";
  EXPECT_EQ(programs.precision(), PointPrecision::double_float);
  programs(PatchShape::quad);
  programs.set_precision(PointPrecision::single_float);  // its triangles were built: nothing to check
  programs.set_precision(PointPrecision::double_float);
  programs(PatchShape::quad);
  EXPECT_EQ(builds, (std::map<Key, int>{{{PatchShape::triangle, PointPrecision::single_float}, 1},
                                        {{PatchShape::quad, PointPrecision::double_float}, 1}}));
  programs.set_precision(PointPrecision::single_float, false);
  EXPECT_EQ(programs.precision(), PointPrecision::single_float);
}

TEST_F(ShapeProgramsTest, ARefusedPrecisionKeepsThePreviousOne) {
  std::map<Key, int> builds;
  ShapePrograms programs(counted(builds, true));
  EXPECT_THROW(programs.set_precision(PointPrecision::double_float), Error);
  EXPECT_EQ(programs.precision(), PointPrecision::single_float);
  EXPECT_NE(programs(PatchShape::quad).id(), 0u);
  // Unchecked, the refusal comes at the first use instead.
  programs.set_precision(PointPrecision::double_float, false);
  EXPECT_THROW(programs(PatchShape::triangle), Error);
}

}  // namespace
}  // namespace gps
