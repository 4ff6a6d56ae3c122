// Which patches' triangles a change of topology changes (render/pipeline/kept_surface_triangles.h),
// after random operations of every kind on quad, mixed and triangle meshes, against its rule checked
// patch by patch: a patch not kept, one whose corner output is evaluated again, or one with an edge
// neighbour or a corner owner among these. The function looks only around the patches evaluated
// again; this test looks at every patch.
#include "render/pipeline/kept_surface_triangles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/plans/patch_faces.h"
#include "core/plans/surface_replanner.h"
#include "core/support/error.h"
#include "tests/support/plan_tables.h"
#include "tests/support/random_operations.h"

namespace gps {
namespace {

std::vector<char> changed_by_the_rule(const PatchPlans& after, const std::vector<char>& evaluated) {
  std::vector<char> changed(evaluated);
  for (int p = 0; p < after.n_patches(); ++p)
    for (int k = 0; k < after.corners(); ++k) {
      const size_t slot = size_t(after.corners() * p + k);
      for (const int32_t q :
           {after.patch_neighbours[4 * slot], after.patch_neighbours[4 * slot + 2], after.corner_owners[2 * slot]})
        if (q >= 0 && evaluated[size_t(q)]) changed[size_t(p)] = 1;
    }
  return changed;
}

TEST(KeptSurfaceTriangles, RandomOperationsChangeThePatchesTheRuleNames) {
  int looked_around = 0;
  for (const test::RandomOperationCase& c : test::random_operation_cases()) {
    PlanOptions options;
    options.scheme = c.scheme;
    CovarianceMesh mesh = c.mesh;
    SurfaceReplanner replanner(mesh.topology(), options, mesh.sharpness, test::kSmallRanges);
    std::mt19937 random(23);
    for (int step = 0; step < 3 * c.operations; ++step) {
      const int n_before = replanner.tables().plans.n_patches();
      Modelled result;
      try {
        result = test::random_operation(mesh, random);
        replanner.set_topology(result.mesh, result.vertex_origin);
      } catch (const Error&) {
        continue;
      }
      const PatchPlans& after = replanner.tables().plans;
      const std::vector<KeptPatches>& kept = replanner.last_change().kept;
      // A few kept patches whose corner output is evaluated again, as for a Gaussian changed there.
      std::vector<char> evaluated(size_t(after.n_patches()), 1);
      for (const KeptPatches& run : kept) std::fill_n(evaluated.begin() + run.first, run.count, 0);
      std::vector<int> stale;
      for (int p = 0; p < after.n_patches(); ++p)
        if (!evaluated[size_t(p)] && random() % 97 == 0) stale.push_back(p);
      for (const int p : stale) evaluated[size_t(p)] = 1;
      const KeptTriangles triangles =
          kept_triangles(result.mesh, after, first_patches(result.mesh.topology(), after), n_before, kept, stale);
      const std::string where = c.name + ", step " + std::to_string(step) + " (" + result.summary + ")";
      const std::vector<char> expected = changed_by_the_rule(after, evaluated);
      ASSERT_EQ(triangles.changed.size(), expected.size()) << where;
      const auto wrong = std::mismatch(expected.begin(), expected.end(), triangles.changed.begin()).first;
      EXPECT_TRUE(wrong == expected.end()) << where << ": patch " << (wrong - expected.begin()) << " of "
                                           << expected.size() << " should " << (*wrong ? "" : "not ") << "change";
      std::vector<int> new_number(size_t(n_before), -1);
      for (const KeptPatches& run : kept)
        for (int i = 0; i < run.count; ++i) new_number[size_t(run.old_first + i)] = run.first + i;
      EXPECT_EQ(triangles.new_number, new_number) << where;
      const long long n_evaluated = std::count(evaluated.begin(), evaluated.end(), 1);
      looked_around += 4 * n_evaluated <= after.n_patches();
      mesh = std::move(result.mesh);
    }
  }
  EXPECT_GE(looked_around, 10) << "changes small enough that only the patches around them are looked at";
}

}  // namespace
}  // namespace gps
