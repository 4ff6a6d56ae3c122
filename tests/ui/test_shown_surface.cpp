// The editor's shown surface (ui/display/shown_surface.h) on an OSMesa context: every change of what is
// shown counts a revision, a new mesh a topology revision too, so that each follower sees each change
// once; the mirror modifier shows the half with its image and an edit on both sides; a preview stands
// in for the document until cleared; the target points' layer measures again after a change; the
// hidden faces' patches are left out and follow a new mesh.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <thread>

#include "core/io/mesh_io.h"
#include "core/modelling/bisect.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/samples.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/settled_target_points.h"
#include "tests/support/temp_dir.h"
#include "ui/editing/selection.h"
#include "ui/display/hidden_view.h"
#include "ui/display/shown_surface.h"
#include "ui/display/target_points_layer.h"

namespace gps {
namespace {

using ShownSurfaceTest = test::GlTest;
using test::settle;

// The cube's x ≥ 0 half, cut at x = 0: the mirror modifier's mesh.
CovarianceMesh half_cube() {
  const CovarianceMesh cut = bisect(make_sample("cube"), Vec3::Zero(), Vec3(1, 0, 0)).mesh;
  std::vector<int> left;
  for (size_t v = 0; v < cut.n_vertices(); ++v)
    if (cut.mean(v).x() < 0) left.push_back(int(v));
  return delete_vertices(cut, left).mesh;
}

TEST_F(ShownSurfaceTest, EachFollowerSeesEachChangeOnceAndANewMeshAsATopologyChange) {
  ShownSurface shown;
  std::uint64_t surface_seen = 0, topology_seen = 0, late_seen = 0;
  EXPECT_FALSE(shown.changed_since(surface_seen));

  CovarianceMesh mesh = make_sample("cube");
  EXPECT_TRUE(shown.show(mesh, PlanOptions{}).empty());
  EXPECT_EQ(shown.renderer().tables().plans.n_patches(), 6);
  EXPECT_TRUE(shown.changed_since(surface_seen));
  EXPECT_FALSE(shown.changed_since(surface_seen));  // seen once
  EXPECT_TRUE(shown.topology_changed_since(topology_seen));

  mesh.set_mean(0, mesh.mean(0) + Vec3(0.1, 0, 0));
  EXPECT_TRUE(shown.show_edit(mesh, {0}, PlanOptions{}).empty());
  EXPECT_TRUE(shown.changed_since(surface_seen));
  EXPECT_FALSE(shown.topology_changed_since(topology_seen));  // the same mesh, its Gaussians edited

  // A follower that looks after several changes sees them as one.
  EXPECT_TRUE(shown.changed_since(late_seen));
  EXPECT_FALSE(shown.changed_since(late_seen));
}

TEST_F(ShownSurfaceTest, TheMirrorModifierShowsTheHalfWithItsImageAndAnEditOnBothSides) {
  ShownSurface shown;
  CovarianceMesh half = half_cube();
  MirrorSettings on;
  on.enabled = true;
  shown.set_mirror_settings(on);
  EXPECT_TRUE(shown.show(half, PlanOptions{}).empty());
  ASSERT_TRUE(shown.mirror().mirroring());
  EXPECT_EQ(shown.drawn(half).n_faces(), 2 * half.n_faces());
  EXPECT_EQ(shown.renderer().tables().plans.n_patches(), int(2 * half.n_faces()));

  int off_plane = -1;
  for (size_t v = 0; v < half.n_vertices() && off_plane < 0; ++v)
    if (half.mean(v).x() > 0) off_plane = int(v);
  ASSERT_GE(off_plane, 0);
  half.set_mean(size_t(off_plane), half.mean(size_t(off_plane)) + Vec3(0, 0.25, 0));
  std::uint64_t topology_seen = shown.topology_revision();
  EXPECT_TRUE(shown.show_edit(half, {off_plane}, PlanOptions{}).empty());
  EXPECT_FALSE(shown.topology_changed_since(topology_seen));
  // The image of the moved vertex moved with it: some other vertex of the mirror lies at its mirror point.
  const Vec3 moved = half.mean(size_t(off_plane)), image(-moved.x(), moved.y(), moved.z());
  bool found = false;
  for (size_t v = 0; v < shown.drawn(half).n_vertices(); ++v) found |= shown.drawn(half).mean(v) == image;
  EXPECT_TRUE(found);

  shown.set_mirror_settings(MirrorSettings{});
  EXPECT_TRUE(shown.show(half, PlanOptions{}).empty());
  EXPECT_FALSE(shown.mirror().mirroring());
  EXPECT_EQ(&shown.drawn(half), &half);
}

TEST_F(ShownSurfaceTest, APreviewStandsInForTheDocumentUntilCleared) {
  ShownSurface shown;
  const CovarianceMesh document = make_sample("cube");
  EXPECT_EQ(&shown.edited(document), &document);
  auto preview = std::make_shared<const CovarianceMesh>(make_sample("cube"));
  shown.show(*preview, PlanOptions{});
  shown.set_preview(preview, {1, 2});
  EXPECT_EQ(&shown.edited(document), preview.get());
  EXPECT_EQ(shown.preview_selection(), (std::vector<int>{1, 2}));
  shown.clear_preview();
  EXPECT_EQ(&shown.edited(document), &document);
  EXPECT_TRUE(shown.preview_selection().empty());
}

// The target points follow the shown surface's revisions: measured once loaded, and again after an
// edit of the surface (not before the layer sees it).
TEST_F(ShownSurfaceTest, TheTargetPointsAreMeasuredAgainAfterEachChangeOfTheSurface) {
  const test::TempDir dir;
  CovarianceMesh mesh = make_sample("cube");
  write_mesh(dir.file("target.ply"), mesh);
  ShownSurface shown;
  shown.show(mesh, PlanOptions{});
  TargetPointsLayer layer;
  layer.points().load(dir.file("target.ply"));
  TargetPointsView view;
  auto now = TargetPointsLayer::Clock::now();
  settle(layer, shown, mesh, view, now);
  EXPECT_EQ(view.count, 8u);
  EXPECT_EQ(view.name, "target.ply");
  const double before = view.rms;
  EXPECT_GT(before, 0.0);  // the limit surface lies inside the cube's corners

  mesh.set_mean(0, 1.5 * mesh.mean(0));
  shown.show_edit(mesh, {0}, PlanOptions{});
  layer.update(shown, mesh, PlanOptions{}, view, now);
  EXPECT_TRUE(view.measuring);
  settle(layer, shown, mesh, view, now);
  EXPECT_NE(view.rms, before);
}

// Hiding two neighbouring faces of the cube leaves their patches and the edge between them out of the
// frame and their corners out of picking; a preview is drawn whole; a new mesh shown is followed by
// its topology revision (the same hidden face, its patch numbered as the new mesh's plans number it).
TEST_F(ShownSurfaceTest, TheHiddenViewLeavesOutTheHiddenFacesPatchesAndFollowsANewMesh) {
  ShownSurface shown;
  const CovarianceMesh cube = make_sample("cube");
  shown.show(cube, PlanOptions{});
  HiddenView hidden;
  EXPECT_EQ(hidden.follow(cube, shown), "");
  EXPECT_TRUE(hidden.patches().empty());
  EXPECT_TRUE(hidden.vertex_mask().empty());

  Selection selection;
  std::vector<int> corners(cube.face(0).begin(), cube.face(0).end());
  corners.insert(corners.end(), cube.face(2).begin(), cube.face(2).end());
  selection.select(corners, false);
  selection.hold_faces(cube);
  EXPECT_EQ(hidden.elements().hide(cube, selection, SelectMode::face, false), 2u);
  EXPECT_EQ(hidden.refresh(cube, shown), "");
  EXPECT_EQ(hidden.patches(), (std::vector<int>{0, 2}));  // one patch per quad, in face order
  EXPECT_EQ(hidden.face_mask(), (std::vector<char>{1, 0, 1, 0, 0, 0}));
  int cage_edges = 0;
  for (const char e : hidden.cage_edges()) cage_edges += e;
  EXPECT_EQ(cage_edges, 1);                   // the edge between them; the others border faces still shown
  EXPECT_EQ(hidden.follow(cube, shown), "");  // nothing new: kept
  EXPECT_EQ(hidden.patches(), (std::vector<int>{0, 2}));

  // The cube's faces in reverse order, shown anew: the hidden face's patch is now the last.
  std::vector<std::vector<int>> reversed;
  for (size_t f = cube.n_faces(); f-- > 0;) reversed.emplace_back(cube.face(f).begin(), cube.face(f).end());
  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  for (size_t v = 0; v < cube.n_vertices(); ++v)
    means.push_back(cube.mean(v)), covariances.push_back(cube.covariance(v));
  const CovarianceMesh turned = make_covariance_mesh(means, covariances, reversed, "turned");
  hidden.elements().clear();
  selection.select(std::vector<int>(turned.face(5).begin(), turned.face(5).end()), false);
  selection.hold_faces(turned);
  hidden.elements().hide(turned, selection, SelectMode::face, false);
  shown.show(turned, PlanOptions{});
  EXPECT_EQ(hidden.follow(turned, shown), "");
  EXPECT_EQ(hidden.patches(), std::vector<int>{5});

  shown.set_preview(std::make_shared<const CovarianceMesh>(turned), {});
  EXPECT_EQ(hidden.refresh(turned, shown), "");
  EXPECT_TRUE(hidden.patches().empty());  // a preview is drawn whole
  EXPECT_FALSE(hidden.vertex_mask().empty());
}

}  // namespace
}  // namespace gps
