// Outputs sized before the work (core/support/memory_budget.h, core/reference/subdivision_size.h,
// core/evaluation/tessellation_size.h): the estimates against what subdivide() and tessellate()
// make, the budget from the environment, and refusals with the figures.
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <optional>
#include <string>

#include "core/evaluation/tessellation_size.h"
#include "core/evaluation/tessellator.h"
#include "core/support/error.h"
#include "core/reference/subdivision_size.h"
#include "core/support/memory_budget.h"
#include "tests/support/plan_fixture.h"

namespace gps {
namespace {

// Sets GPSURF_MEMORY_LIMIT_BYTES (or unsets it) for the life of the guard.
class MemoryLimit {
public:
  explicit MemoryLimit(const char* value) {
    if (const char* old = std::getenv(kMemoryLimitVariable)) old_ = old;
    if (value)
      ::setenv(kMemoryLimitVariable, value, 1);
    else
      ::unsetenv(kMemoryLimitVariable);
  }
  ~MemoryLimit() {
    if (old_)
      ::setenv(kMemoryLimitVariable, old_->c_str(), 1);
    else
      ::unsetenv(kMemoryLimitVariable);
  }

private:
  std::optional<std::string> old_;
};

// The usage error `f` throws, or "" where it throws none.
std::string usage_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::usage) << e.what();
    return e.what();
  }
  return "";
}

TEST(OutputSize, SubdivisionCountsAreExact) {
  struct Case {
    const char* sample;
    Scheme scheme;
  };
  // The cylinder's octagons and the pawn's triangles: n-gons into n quads on the first level.
  for (const auto& [sample, scheme] : {Case{"cylinder", Scheme::catmull_clark}, Case{"pawn", Scheme::catmull_clark},
                                       Case{"grid", Scheme::catmull_clark}, Case{"icosphere", Scheme::loop}}) {
    const CovarianceMesh mesh = make_sample(sample);
    for (int levels = 0; levels <= 3; ++levels) {
      SubdivisionOptions options;
      options.scheme = scheme;
      options.levels = levels;
      const OutputSize size = subdivision_size(mesh, options);
      const SubdivisionResult result = subdivide(mesh, options);
      EXPECT_EQ(size.vertices, double(result.mesh.n_vertices())) << sample << " " << levels;
      EXPECT_EQ(size.faces, double(result.mesh.n_faces())) << sample << " " << levels;
      EXPECT_GT(size.bytes, 100.0 * size.vertices) << sample << " " << levels;
    }
  }
}

TEST(OutputSize, TessellationEstimatesBoundWhatIsMade) {
  for (const char* sample : {"cube", "cylinder", "pawn", "icosphere"}) {  // quads, split n-gons, Loop
    const test::PlannedMesh planned(make_sample(sample), PlanOptions{});
    for (const int level : {1, 2, 3, 8}) {
      const OutputSize size = tessellation_size(planned.tables.plans, level);
      const TriangleMesh t = tessellate(planned.tables.plans, planned.points, level);
      // Upper bounds, close at the levels where memory matters.
      EXPECT_GE(size.vertices, double(t.positions.size())) << sample << " " << level;
      EXPECT_GE(size.faces, double(t.triangles.size())) << sample << " " << level;
      if (level == 8) {
        EXPECT_LE(size.vertices, 1.5 * double(t.positions.size())) << sample;
        EXPECT_LE(size.faces, 1.1 * double(t.triangles.size())) << sample;
      }
    }
  }
}

TEST(OutputSize, TheBudgetComesFromTheEnvironmentOrHalfThePhysicalMemory) {
  {
    const MemoryLimit unset(nullptr);
    const size_t half = memory_limit_bytes();
    EXPECT_GT(half, size_t(1) << 26);
  }
  {
    const MemoryLimit set("123456");
    EXPECT_EQ(memory_limit_bytes(), 123456u);
  }
  for (const char* bad : {"", "0", "-5", "12x", "1e9", "99999999999999999999999"}) {
    const MemoryLimit set(bad);
    const std::string message = usage_error_of([] { memory_limit_bytes(); });
    EXPECT_NE(message.find("GPSURF_MEMORY_LIMIT_BYTES: expected a positive whole number of bytes"), std::string::npos)
        << bad << ": " << message;
  }
}

// Beyond the budget, subdivide() and tessellate() refuse before any work with the figures; within it
// they run.
TEST(OutputSize, SubdivideAndTessellateRefuseWhatExceedsTheBudget) {
  const CovarianceMesh cube = make_sample("cube");
  SubdivisionOptions options;
  options.levels = 4;  // 6 · 4⁴ = 1536 quads
  const test::PlannedMesh planned(make_sample("cube"), PlanOptions{});
  {
    const MemoryLimit tight("100000");
    EXPECT_EQ(usage_error_of([&] { subdivide(cube, options); }),
              "4 levels of Catmull-Clark subdivision would make about 1,538 vertices and 1,536 faces and hold about "
              "720.3 KiB, more than the 97.7 KiB allowed (set by GPSURF_MEMORY_LIMIT_BYTES); use fewer levels");
    const std::string message = usage_error_of([&] { tessellate(planned.tables.plans, planned.points, 32); });
    EXPECT_EQ(message.rfind("tessellating 6 patches at level 32 would make about 6,534 vertices and 12,288 triangles "
                            "and hold about ",
                            0),
              0u)
        << message;
    EXPECT_NE(message.find("more than the 97.7 KiB allowed"), std::string::npos) << message;
    EXPECT_EQ(usage_error_of([&] { tessellate(planned.tables.plans, planned.points, 4); }), "");
  }
  {
    const MemoryLimit roomy("100000000");
    EXPECT_EQ(subdivide(cube, options).mesh.n_faces(), 1536u);
  }
  // Counts that no int indexes are refused whatever the budget.
  const MemoryLimit huge("1000000000000000000");
  options.levels = 8;
  const CovarianceMesh sphere = make_sample("sphere", 40000);
  EXPECT_NE(usage_error_of([&] { subdivide(sphere, options); }).find("more than the 2,147,483,647 a mesh can index"),
            std::string::npos);
}

}  // namespace
}  // namespace gps
