// A change's Gaussians found and written in place (render/gl/gaussians_change.h) against
// changed_gaussians, which frames every vertex anew: the same changed vertices and the same Gaussians
// held, bit for bit, for old vertices changed or not, new vertices changed or equal to their origin's
// (also where that origin changed), and a change that removes vertices.
#include "render/gl/gaussians_change.h"

#include <gtest/gtest.h>

#include "core/modelling/extrude.h"
#include "core/modelling/samples.h"

namespace gps {
namespace {

void expect_same_gaussians(const FramedGaussians& a, const FramedGaussians& b, const std::string& where) {
  ASSERT_EQ(a.n_vertices(), b.n_vertices()) << where;
  for (size_t v = 0; v < a.n_vertices(); ++v) {
    EXPECT_TRUE(a.means[v] == b.means[v]) << where << ": vertex " << v << "'s mean";
    EXPECT_TRUE(a.covariances[v] == b.covariances[v]) << where << ": vertex " << v << "'s covariance";
  }
}

// The change from `before` (in `frame`) to `mesh` both ways: listed and written in place, and framed anew.
void expect_as_framed_anew(const FramedGaussians& before, const CovarianceMesh& mesh, const NormalisedFrame& frame,
                           const std::vector<int>& origin, const std::string& where) {
  ASSERT_TRUE(keeps_vertex_numbers(origin, before.n_vertices(), mesh.n_vertices())) << where;
  FramedGaussians expected;
  const std::vector<int> expected_changed = changed_gaussians(before, mesh, frame, origin, expected);
  const GaussiansChange change = gaussians_change(before, mesh, frame, origin);
  EXPECT_EQ(change.changed, expected_changed) << where;
  FramedGaussians held = before;
  apply_gaussians_change(change, origin, held);
  expect_same_gaussians(held, expected, where);
}

TEST(GaussiansChange, WrittenInPlaceEqualsFramedAnew) {
  const CovarianceMesh sphere = make_sample("sphere", 400);
  const NormalisedFrame frame = NormalisedFrame::of(sphere);
  const FramedGaussians before = frame.gaussians_in_frame(sphere);
  const Modelled extruded = extrude_faces(sphere, {3, 4}, 0.1);
  const size_t n_old = sphere.n_vertices(), n = extruded.mesh.n_vertices();
  ASSERT_GT(n, n_old + 4);
  // The new vertices come from old ones: the first equal to its origin's Gaussian, the second equal to
  // its origin's as it was while that origin changes, the others moved; and two old vertices changed.
  std::vector<int> origin(n);
  for (size_t v = 0; v < n; ++v) origin[v] = v < n_old ? int(v) : int(v - n_old) * 7 % int(n_old);
  CovarianceMesh mesh = extruded.mesh;
  for (const size_t v : {n_old, n_old + 1}) {
    mesh.set_mean(v, sphere.mean(size_t(origin[v])));
    mesh.set_covariance(v, sphere.covariance(size_t(origin[v])));
  }
  const size_t moved_origin = size_t(origin[n_old + 1]);
  mesh.set_mean(moved_origin, sphere.mean(moved_origin) + Vec3(0.0, 0.0, 0.01));
  mesh.set_covariance(5, 2.0 * sphere.covariance(5));
  expect_as_framed_anew(before, mesh, frame, origin, "extruded, new vertices from old ones");
  // New vertices of no origin, and no vertex changed but those.
  std::vector<int> fresh(n, -1);
  for (size_t v = 0; v < n_old; ++v) fresh[v] = int(v);
  expect_as_framed_anew(before, extruded.mesh, frame, fresh, "extruded");
  // And back: the new vertices removed, the old ones kept.
  const FramedGaussians after = frame.gaussians_in_frame(extruded.mesh);
  std::vector<int> back(n_old);
  for (size_t v = 0; v < n_old; ++v) back[v] = int(v);
  expect_as_framed_anew(after, sphere, frame, back, "undone");
  expect_as_framed_anew(before, sphere, frame, {}, "the same mesh");
}

TEST(GaussiansChange, OnlyAChangeThatKeepsEveryNumberIsOne) {
  EXPECT_TRUE(keeps_vertex_numbers({}, 5, 5));
  EXPECT_FALSE(keeps_vertex_numbers({}, 5, 6));
  EXPECT_TRUE(keeps_vertex_numbers({0, 1, 2, -1, 0}, 3, 5));
  EXPECT_TRUE(keeps_vertex_numbers({0, 1}, 3, 2));
  EXPECT_FALSE(keeps_vertex_numbers({0, 2, 1}, 3, 3));
  EXPECT_FALSE(keeps_vertex_numbers({0, 1}, 3, 3));
}

}  // namespace
}  // namespace gps
