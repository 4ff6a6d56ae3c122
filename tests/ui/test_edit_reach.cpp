// The reach of an edit: the selection, the vertices within the proportional radius weighted by the
// falloff of their distance to the nearest selected vertex, and the mirror partners.
#include "ui/editing/edit_reach.h"

#include <gtest/gtest.h>

#include <map>

#include "core/modelling/samples.h"

namespace gps {
namespace {

TEST(EditReach, FalloffCurves) {
  for (const Falloff f : {Falloff::smooth, Falloff::linear, Falloff::sharp}) {
    EXPECT_EQ(falloff_weight(f, 0.0), 1.0);
    EXPECT_EQ(falloff_weight(f, 1.0), 0.0);
    EXPECT_GT(falloff_weight(f, 0.4), falloff_weight(f, 0.6));
  }
  EXPECT_EQ(falloff_weight(Falloff::linear, 0.25), 0.75);
  EXPECT_EQ(falloff_weight(Falloff::constant, 0.9), 1.0);
}

TEST(EditReach, ProportionalWeightsFollowTheNearestSelectedVertex) {
  const CovarianceMesh mesh = make_sample("grid", 400);
  std::vector<Vec3> means;
  for (size_t v = 0; v < mesh.n_vertices(); ++v) means.push_back(mesh.mean(v));
  const std::vector<int> selected = {10, 200};
  ReachOptions options;
  options.proportional = true;
  options.radius = 0.2 * bounding_box_diagonal(mesh);
  options.falloff = Falloff::linear;
  const std::vector<ReachedVertex> reach = edit_reach(means, selected, options);
  std::map<int, ReachedVertex> by_vertex;
  for (const ReachedVertex& r : reach)
    EXPECT_TRUE(by_vertex.emplace(r.vertex, r).second) << "reached twice: " << r.vertex;
  for (size_t v = 0; v < means.size(); ++v) {
    const double d0 = (means[v] - means[10]).norm(), d1 = (means[v] - means[200]).norm();
    const double d = std::min(d0, d1);
    const auto it = by_vertex.find(int(v));
    if (d >= options.radius) {
      EXPECT_EQ(it, by_vertex.end()) << v;
      continue;
    }
    ASSERT_NE(it, by_vertex.end()) << v;
    EXPECT_NEAR(it->second.weight, 1.0 - d / options.radius, 1e-12);
    EXPECT_EQ(it->second.source, d0 <= d1 ? 0u : 1u);
  }
  EXPECT_EQ(by_vertex.at(10).weight, 1.0);
}

TEST(EditReach, MirrorPartnersAreMatchedByPosition) {
  const CovarianceMesh mesh = make_sample("cube");  // corners at ±1
  std::vector<Vec3> means;
  for (size_t v = 0; v < mesh.n_vertices(); ++v) means.push_back(mesh.mean(v));
  ReachOptions options;
  options.mirror = true;
  for (int axis = 0; axis < 3; ++axis) {
    options.mirror_axis = axis;
    const std::vector<ReachedVertex> reach = edit_reach(means, {6}, options);
    ASSERT_EQ(reach.size(), 2u);
    Vec3 image = means[6];
    image[axis] = -image[axis];
    EXPECT_TRUE(reach[1].mirrored);
    EXPECT_LT((means[size_t(reach[1].vertex)] - image).norm(), 1e-12);
  }
  // A selection that holds both partners edits each once, neither mirrored.
  options.mirror_axis = 0;
  int partner = -1;
  for (size_t v = 0; v < means.size(); ++v)
    if ((means[v] - Vec3(-means[6].x(), means[6].y(), means[6].z())).norm() < 1e-12) partner = int(v);
  EXPECT_EQ(edit_reach(means, {6, partner}, options).size(), 2u);
}

// Hidden vertices (the editor's H) are neither in the proportional reach nor mirror partners; the
// others are reached as without them.
TEST(EditReach, HiddenVerticesAreNeverReached) {
  const CovarianceMesh mesh = make_sample("grid", 400);
  std::vector<Vec3> means;
  for (size_t v = 0; v < mesh.n_vertices(); ++v) means.push_back(mesh.mean(v));
  ReachOptions options;
  options.proportional = true;
  options.radius = 0.2 * bounding_box_diagonal(mesh);
  const std::vector<ReachedVertex> all = edit_reach(means, {10}, options);
  ASSERT_GT(all.size(), 3u);
  std::vector<char> hidden(means.size(), 0);
  hidden[size_t(all[1].vertex)] = hidden[size_t(all[2].vertex)] = 1;
  const std::vector<ReachedVertex> shown = edit_reach(means, {10}, options, &hidden);
  ASSERT_EQ(shown.size(), all.size() - 2);
  for (size_t k = 0, r = 0; k < all.size(); ++k) {
    if (hidden[size_t(all[k].vertex)]) continue;
    EXPECT_EQ(shown[r].vertex, all[k].vertex);
    EXPECT_EQ(shown[r++].weight, all[k].weight);
  }

  const CovarianceMesh cube = make_sample("cube");
  std::vector<Vec3> corners;
  for (size_t v = 0; v < cube.n_vertices(); ++v) corners.push_back(cube.mean(v));
  ReachOptions mirror;
  mirror.mirror = true;
  const std::vector<ReachedVertex> pair = edit_reach(corners, {6}, mirror);
  ASSERT_EQ(pair.size(), 2u);
  std::vector<char> partner_hidden(corners.size(), 0);
  partner_hidden[size_t(pair[1].vertex)] = 1;
  EXPECT_EQ(edit_reach(corners, {6}, mirror, &partner_hidden).size(), 1u);
}

}  // namespace
}  // namespace gps
