// File → Simplify… and Fit to…'s work (ui/panels/mesh_jobs.h), without a window: the settings each
// refuses in words, what each makes and says it made, and a Cancel honoured.
#include "ui/panels/mesh_jobs.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/support/error.h"
#include "core/support/progress.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

std::string refusal_of(const std::function<void()>& start) {
  try {
    start();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

const ProgressReport kGoOn = [](double) { return true; };

TEST(MeshJobs, SimplifyRefusesSettingsItCannotUseAndMakesTheMeshItSays) {
  const auto sphere = std::make_shared<const CovarianceMesh>(make_sample("sphere", 384));
  const int n = int(sphere->n_vertices());
  EXPECT_EQ(refusal_of([&] { MeshJobs::simplify_work(sphere, {3, 0.05}); }), "keep at least 4 vertices");
  EXPECT_EQ(refusal_of([&] {
              MeshJobs::simplify_work(sphere, {n, 0.05});
            }),
            "keep fewer than the " + std::to_string(n) + " vertices there are");
  EXPECT_EQ(refusal_of([&] { MeshJobs::simplify_work(sphere, {100, 0.0}); }), "the bias must be positive");

  const Modelled made = MeshJobs::simplify_work(sphere, {100, 0.05})(kGoOn);
  EXPECT_EQ(made.mesh.n_vertices(), 100u);
  EXPECT_EQ(made.summary.rfind("simplified " + std::to_string(n) + " to 100 vertices; the input lies", 0), 0u)
      << made.summary;

  const ProgressReport stop = [](double) { return false; };
  EXPECT_THROW(MeshJobs::simplify_work(sphere, {100, 0.05})(stop), Cancelled);
}

TEST(MeshJobs, FitRefusesSettingsItCannotUseAndFitsTheFileNamed) {
  const test::TempDir dir;
  const auto coarse = std::make_shared<const CovarianceMesh>(make_sample("cube"));
  EXPECT_EQ(refusal_of([&] { MeshJobs::fit_work(coarse, {"", 3, false}); }), "name the mesh to fit to");
  for (const int iterations : {0, 1001})
    EXPECT_EQ(refusal_of([&] {
                MeshJobs::fit_work(coarse, {"x.ply", iterations, false});
              }),
              "iterations must be 1 to 1000");
  const std::string missing = dir.file("missing.ply");
  EXPECT_NE(refusal_of([&] {
              MeshJobs::fit_work(coarse, {missing, 3, false})(kGoOn);
            }).find(missing),
            std::string::npos);

  const std::string target = dir.file("sphere.ply");
  write_mesh(target, make_sample("sphere", 600));
  const Modelled fitted = MeshJobs::fit_work(coarse, {target, 2, false})(kGoOn);
  EXPECT_EQ(fitted.mesh.n_vertices(), coarse->n_vertices());
  EXPECT_NE(fitted.summary.find(" points of " + target + " in 2 iterations: rms "), std::string::npos)
      << fitted.summary;
}

}  // namespace
}  // namespace gps
