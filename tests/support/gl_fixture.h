#pragma once
// One OSMesa GL 4.5 context for a whole test suite: `using MySuite = test::GlTest;` (or derive from
// it) and write TEST_F(MySuite, ...). The context is made current before the suite's first test and
// destroyed after its last.
#include <gtest/gtest.h>

#include <memory>

#include "render/gl_context.h"

namespace gps::test {

class GlTest : public ::testing::Test {
protected:
  static void SetUpTestSuite() { context_ = create_offscreen_context(ContextKind::osmesa); }
  static void TearDownTestSuite() { context_.reset(); }

private:
  inline static std::unique_ptr<GlContext> context_;
};

}  // namespace gps::test
