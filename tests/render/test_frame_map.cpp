// A frame's map for passes over many vertices (render/gl/normalised_frame.h, FrameMap) against the
// frame's own mean_in_frame and covariance_in_frame: the same doubles, bit for bit, in the frame of a
// mesh near the origin, of one far from it, and in a frame turned with a mesh rotated whole.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstring>

#include "core/modelling/samples.h"
#include "render/gl/normalised_frame.h"

namespace gps {
namespace {

void expect_map_as_frame(const NormalisedFrame& frame, const CovarianceMesh& mesh, const std::string& where) {
  const FrameMap map(frame);
  for (size_t v = 0; v < mesh.n_vertices(); ++v) {
    const Vec3 mean = frame.mean_in_frame(mesh.mean(v)), mapped_mean = map.mean(mesh.mean(v));
    const Mat3 covariance = frame.covariance_in_frame(mesh.covariance(v));
    const Mat3 mapped_covariance = map.covariance(mesh.covariance(v));
    EXPECT_EQ(std::memcmp(&mean, &mapped_mean, sizeof mean), 0) << where << ": vertex " << v << "'s mean";
    EXPECT_EQ(std::memcmp(&covariance, &mapped_covariance, sizeof covariance), 0)
        << where << ": vertex " << v << "'s covariance";
  }
}

TEST(FrameMap, MapsAsTheFrameDoesBitForBit) {
  CovarianceMesh pawn = make_sample("pawn");
  NormalisedFrame frame = NormalisedFrame::of(pawn);
  ASSERT_FALSE(frame.turned());
  expect_map_as_frame(frame, pawn, "the pawn's frame");

  // Far from the origin and scaled: a centre and unit whose digits the map must round as the frame does.
  CovarianceMesh far = pawn;
  for (size_t v = 0; v < far.n_vertices(); ++v) {
    far.set_mean(v, 3.7e5 * far.mean(v) + Vec3(1.23456789e7, -9.87654321e6, 4.2e5));
    far.set_covariance(v, 3.7e5 * 3.7e5 * far.covariance(v));
  }
  expect_map_as_frame(NormalisedFrame::of(far), far, "far from the origin");

  // A frame turned with the mesh: the map takes the frame's own rotation.
  const Mat3 turn = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) frame.rotation[c][k] = turn(k, c);
  ASSERT_TRUE(frame.turned());
  expect_map_as_frame(frame, pawn, "a turned frame");
}

}  // namespace
}  // namespace gps
