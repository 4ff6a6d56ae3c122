// The target points' file read and distances measured in the background (ui/overlays/target_points.h): they
// are core's distances from the limit surface, measured again for a changed surface once it settles;
// a file that does not read is reported naming it, the target shown kept.
#include "ui/overlays/target_points.h"

#include <gtest/gtest.h>

#include <fstream>
#include <thread>

#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using Clock = TargetPoints::Clock;

// Polls until the background is done (every poll a settle period later), collecting what it took.
TargetPoints::Taken settle(TargetPoints& target, const CovarianceMesh& mesh) {
  TargetPoints::Taken all;
  const auto surface = [&mesh] { return std::make_shared<const CovarianceMesh>(mesh); };
  Clock::time_point now = Clock::now();
  while (target.busy()) {
    now += TargetPoints::kSettle;
    const TargetPoints::Taken t = target.poll(now, surface, {});
    all.points |= t.points;
    all.distances |= t.distances;
    if (!t.error.empty()) all.error = t.error;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return all;
}

std::vector<double> core_distances(const CovarianceMesh& mesh, const std::vector<Vec3>& points) {
  const LimitTriangles limit = limit_surface_triangles(mesh, TargetPoints::kLevel, {}, TargetPoints::kMaxTriangles);
  return SurfaceDistance(limit.triangles).distances(points);
}

class TargetPointsTest : public ::testing::Test {
protected:
  void SetUp() override {
    mesh_ = make_sample("icosphere", 80);
    dense_ = make_sample("icosphere", 1280);
    write_mesh(dir_.file("dense.ply"), dense_);
  }
  test::TempDir dir_;
  CovarianceMesh mesh_, dense_;
};

TEST_F(TargetPointsTest, TheDistancesAreCoresFromTheLimitSurface) {
  TargetPoints target;
  EXPECT_FALSE(target.loaded());
  target.load(dir_.file("dense.ply"));
  EXPECT_TRUE(target.busy());
  const TargetPoints::Taken taken = settle(target, mesh_);
  EXPECT_TRUE(taken.points);
  EXPECT_TRUE(taken.distances);
  EXPECT_EQ(taken.error, "");
  ASSERT_TRUE(target.current());
  EXPECT_EQ(target.path(), dir_.file("dense.ply"));
  const std::vector<Vec3> points = vertex_means(dense_);
  ASSERT_EQ(target.points(), points);
  const std::vector<double> expected = core_distances(mesh_, points);
  ASSERT_EQ(target.distances().size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_FLOAT_EQ(target.distances()[i], float(expected[i])) << i;
  EXPECT_DOUBLE_EQ(target.summary().max, *std::max_element(expected.begin(), expected.end()));
  EXPECT_GT(target.summary().percentile_99, 0.0);
}

TEST_F(TargetPointsTest, AChangedSurfaceIsMeasuredAgainOnceSettled) {
  TargetPoints target;
  target.load(dir_.file("dense.ply"));
  settle(target, mesh_);
  CovarianceMesh moved = mesh_;
  moved.set_mean(0, 1.5 * moved.mean(0));
  const Clock::time_point changed = Clock::now();
  target.surface_changed(changed);
  EXPECT_TRUE(target.busy());
  EXPECT_FALSE(target.current());
  // Within the settle period nothing starts: the distances stay those of the old surface.
  const auto surface = [&moved] { return std::make_shared<const CovarianceMesh>(moved); };
  EXPECT_FALSE(target.poll(changed, surface, {}).distances);
  const std::vector<float> before = target.distances();
  const TargetPoints::Taken taken = settle(target, moved);
  EXPECT_TRUE(taken.distances);
  EXPECT_FALSE(taken.points);
  const std::vector<double> expected = core_distances(moved, target.points());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_FLOAT_EQ(target.distances()[i], float(expected[i])) << i;
  EXPECT_NE(target.distances(), before);
}

TEST_F(TargetPointsTest, AFileThatDoesNotReadIsNamedAndTheTargetKept) {
  TargetPoints target;
  target.load(dir_.file("dense.ply"));
  settle(target, mesh_);
  target.load(dir_.file("missing.ply"));
  const TargetPoints::Taken taken = settle(target, mesh_);
  EXPECT_NE(taken.error.find("missing.ply"), std::string::npos) << taken.error;
  EXPECT_FALSE(taken.points);
  EXPECT_EQ(target.path(), dir_.file("dense.ply"));
  EXPECT_EQ(target.points().size(), dense_.n_vertices());
}

TEST_F(TargetPointsTest, ClearedTheTargetIsGoneAndItsMeasurementDropped) {
  TargetPoints target;
  target.load(dir_.file("dense.ply"));
  const auto surface = [this] { return std::make_shared<const CovarianceMesh>(mesh_); };
  target.poll(Clock::now(), surface, {});  // started
  target.clear();
  settle(target, mesh_);
  EXPECT_FALSE(target.loaded());
  EXPECT_TRUE(target.distances().empty());
}

}  // namespace
}  // namespace gps
