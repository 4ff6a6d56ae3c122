#pragma once
// One GL 4.5 context for a whole test suite: `using MySuite = test::GlTest;` (or derive from it) and
// write TEST_F(MySuite, ...). The context is made current before the suite's first test and destroyed
// after its last. OSMesa unless GPSURF_TEST_CONTEXT=egl (the same tests on a GPU driver).
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string_view>

#include "render/gl/gl_context.h"

namespace gps::test {

class GlTest : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    const char* kind = std::getenv("GPSURF_TEST_CONTEXT");
    context_ =
        create_offscreen_context(kind && std::string_view(kind) == "egl" ? ContextKind::egl : ContextKind::osmesa);
  }
  static void TearDownTestSuite() { context_.reset(); }

private:
  inline static std::unique_ptr<GlContext> context_;
};

}  // namespace gps::test
