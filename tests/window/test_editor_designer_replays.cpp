// Designer replays in a real window under Xvfb: the tools chained into a part as a designer makes it,
// each saved file checked exactly against core's operations: a chisel from the cube, creased and
// bevelled; a knifed feature line on the cylinder, creased and sharpened; a mug with a bridged handle.
// (The mirrored bracket is in
// test_editor_mirror.cpp.) Screenshots kept in build/test-artefacts/EditorDesignerReplays/.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/io/mesh_io.h"
#include "core/modelling/bevel.h"
#include "core/modelling/bridge.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/extrude.h"
#include "core/modelling/inset.h"
#include "core/modelling/knife.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/samples.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/editor_tools_fixture.h"

namespace gps {
namespace {

using test::EditorTools;
using test::Events;
using test::pixel_of;

// The View panel's checkboxes "base mesh" and "G/S/R carry the Gaussians" at its first-use place.
const glm::vec2 kBaseMeshBox(692.0f, 441.0f), kCarryGaussiansBox(692.0f, 491.0f);

// The points of a mesh's limit surface (three Catmull-Clark levels projected to the limit).
std::vector<Vec3> limit_points(const CovarianceMesh& mesh) {
  SubdivisionOptions options;
  options.levels = 3;
  options.limit = true;
  const CovarianceMesh limit = subdivide(mesh, options).mesh;
  std::vector<Vec3> points;
  for (size_t v = 0; v < limit.n_vertices(); ++v) points.push_back(limit.mean(v));
  return points;
}

// A designer's chisel from the cube in 18 actions: the View panel's "carry the Gaussians" unticked
// (the wedge keeps round Gaussians), face mode, the top face clicked and S Z 0.2 Enter (a wedge);
// Ctrl+Shift+E and Shift+E 10 Enter (its sharp edges creased); the tip's two edges clicked (the
// second with Shift) and Ctrl+B, the wheel, 0.1, Enter (the working edges bevelled in 2 segments);
// the save. The file is core's scale, crease and bevel of the cube: closed and outward, each band's
// rims 0.1 inside the faces beside the tip edge and smooth, the other ten edges sharp; its limit
// surface stands on the flat base and is thin at the rounded tip.
TEST_F(EditorTools, DesignerReplayBevelledChisel) {
  const std::vector<int> top = {2, 3, 6, 7};
  CovarianceMesh wedge = original_;
  for (const int v : top) wedge.set_mean(size_t(v), original_.mean(size_t(v)).cwiseProduct(Vec3(1, 1, 0.2)));
  const auto edge_pixel = [&](int a, int b) {
    return pixel_of(view_, 0.5 * (wedge.mean(size_t(a)) + wedge.mean(size_t(b))));
  };
  Events chisel;
  chisel.click(kCarryGaussiansBox).wait();
  chisel.key("3").wait().click(pixel_at(top)).wait();
  chisel.key("s").wait().key("z").wait().text("0.2").wait().key("enter").wait();
  chisel.key("ctrl+shift+e").wait().key("shift+e").wait().text("10").wait().key("enter").wait();
  chisel.click(edge_pixel(6, 7)).wait().click(edge_pixel(2, 3), "shift").wait();
  chisel.key("ctrl+b").wait().scroll(edge_pixel(6, 7), 1.0f).wait().text("0.1").wait().key("enter").wait(3);
  const CovarianceMesh saved = play(chisel, "designer_chisel.png");

  const CovarianceMesh creased = crease_sharp_edges(wedge, 30.0, kInfiniteSharpness).mesh;
  EXPECT_TRUE(test::nearly_same_mesh(saved, bevel_edges(creased, {{2, 3}, {6, 7}}, width(0.1, 2)).mesh, 1e-12))
      << output_;
  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, 16);  // each tip edge's two ends replaced by three vertices each
  EXPECT_EQ(shape.faces, 10);     // two quads across each band
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_EQ(shape.euler(), 2);
  EXPECT_GT(test::signed_volume(saved), 0.0);

  // The rims: on the top face 0.1 from each tip edge (z = ±0.1), on each slope 0.1 down it from the
  // tip edge; the original tip edges' vertices are gone.
  const Vec3 down_front = Vec3(0, -2, 0.8).normalized(), down_back = Vec3(0, -2, -0.8).normalized();
  const std::vector<Vec3> rims = {Vec3(1, 1, 0.1),
                                  Vec3(-1, 1, 0.1),
                                  Vec3(1, 1, -0.1),
                                  Vec3(-1, 1, -0.1),
                                  Vec3(1, 1, 0.2) + 0.1 * down_front,
                                  Vec3(-1, 1, 0.2) + 0.1 * down_front,
                                  Vec3(1, 1, -0.2) + 0.1 * down_back,
                                  Vec3(-1, 1, -0.2) + 0.1 * down_back};
  std::vector<int> rim_vertices;
  for (const Vec3& r : rims) {
    int found = -1;
    for (size_t v = 0; v < saved.n_vertices(); ++v)
      if ((saved.mean(v) - r).norm() < 1e-9) found = int(v);
    EXPECT_GE(found, 0) << r.transpose();
    rim_vertices.push_back(found);
    EXPECT_LT((saved.covariance(size_t(std::max(found, 0))) - Mat3::Identity()).norm(), 1e-12) << "round Gaussians";
  }
  for (size_t v = 0; v < saved.n_vertices(); ++v)
    for (const int t : top) EXPECT_GT((saved.mean(v) - wedge.mean(size_t(t))).norm(), 0.01) << v;
  // The rims are smooth, the ten edges left of the wedge's twelve infinitely sharp.
  for (size_t k = 0; k + 1 < rim_vertices.size(); k += 2)
    EXPECT_EQ(saved.sharpness.crease(rim_vertices[k], rim_vertices[k + 1]), 0.0) << k;
  ASSERT_EQ(saved.sharpness.creases.size(), 10u);
  for (const EdgeCrease& c : saved.sharpness.creases) EXPECT_EQ(c.sharpness, kInfiniteSharpness);

  // The limit surface: inside the wedge's box, its flat base at y = −1, its tip rounded below the
  // control mesh's top and thin across z.
  const std::vector<Vec3> limit = limit_points(saved);
  double lowest = 1, highest = -1, tip_z = 0;
  for (const Vec3& p : limit) {
    EXPECT_LE(p.cwiseAbs().maxCoeff(), 1.0 + 1e-9) << p.transpose();
    lowest = std::min(lowest, p.y()), highest = std::max(highest, p.y());
  }
  for (const Vec3& p : limit)
    if (p.y() > highest - 0.05) tip_z = std::max(tip_z, std::abs(p.z()));
  EXPECT_NEAR(lowest, -1.0, 1e-9);
  EXPECT_LT(highest, 1.0);
  EXPECT_GT(highest, 0.9);
  EXPECT_LT(tip_z, 0.2);
}

// A designer's feature line on the cylinder in 16 actions: K, three clicks on the middles of the
// side's vertical edges facing the camera (upper row, lower row, upper row: a V across four faces),
// Enter; edge mode (2: the cut's edges), Shift+E 10 Enter (creased infinitely sharp); Ctrl+. and
// S 0.3 Enter (the line's Gaussians sharpened about their own means); Alt+A and the View panel's
// "base mesh" unticked to look at the surface; the save. The file is core's knife along those points,
// the cut's edges creased and its Gaussians scaled: 5 new vertices where the path crosses edges (the
// clicked middles and the middles of the ring edges between), 4 faces split, closed and outward, the
// four edges of the line sharp and no other.
TEST_F(EditorTools, DesignerReplayKnifeFeatureLine) {
  use_mesh(make_sample("cylinder"));  // rings of 8 at y = −1, 0, 1 (vertices 0–7, 8–15, 16–23)
  const Vec3 eye = to_vec(view_.camera.eye());
  int front = 0;  // the vertical edges' column nearest the camera
  for (int k = 1; k < 8; ++k)
    if ((original_.mean(size_t(8 + k)) - eye).norm() < (original_.mean(size_t(8 + front)) - eye).norm()) front = k;
  const auto middle = [&](int a, int b) -> Vec3 {
    return 0.5 * (original_.mean(size_t(a)) + original_.mean(size_t(b)));
  };
  const int left = (front + 7) % 8, right = (front + 1) % 8;
  const std::vector<Vec3> path = {middle(8 + left, 16 + left), middle(front, 8 + front), middle(8 + right, 16 + right)};
  Events line;
  line.move(pixel_of(view_, path[1])).wait().key("k").wait();
  for (const Vec3& p : path) line.click(pixel_of(view_, p)).wait();
  line.key("enter").wait().key("2").wait().key("shift+e").wait().text("10").wait().key("enter").wait();
  line.key("ctrl+period").wait().key("s").wait().text("0.3").wait().key("enter").wait();
  line.key("alt+a").wait().click(kBaseMeshBox).wait(3);
  const CovarianceMesh saved = play(line, "designer_knife_feature_line.png");
  EXPECT_NE(output_.find("knife: cut 4 faces along 3 points"), std::string::npos) << output_;

  const Modelled cut = knife(original_, path);
  ASSERT_EQ(cut.selection, (std::vector<int>{24, 25, 26, 27, 28}));
  const CovarianceMesh creased =
      set_crease(cut.mesh, {{24, 25}, {25, 26}, {26, 27}, {27, 28}}, kInfiniteSharpness).mesh;
  CovarianceMesh expected = creased;
  for (const int v : cut.selection) expected.set_covariance(size_t(v), 0.09 * creased.covariance(size_t(v)));
  EXPECT_TRUE(test::nearly_same_mesh(saved, expected, 1e-12)) << output_;
  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, 24 + 5);
  EXPECT_EQ(shape.faces, 18 + 4);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_GT(test::signed_volume(saved), 0.0);

  // The new vertices in the path's order, one on each edge the path crosses at its middle (the three
  // clicked, the two of the ring y = 0 between them): on the edge, at the 9D blend of its ends at
  // t = 0.5 (the crossing itself on the ring, whose ends have equal Gaussians), its Σ scaled by 0.3².
  const std::vector<std::array<int, 2>> crossed = {{8 + left, 16 + left},
                                                   {8 + left, 8 + front},
                                                   {front, 8 + front},
                                                   {8 + front, 8 + right},
                                                   {8 + right, 16 + right}};
  const MeshArrays arrays = arrays_of(original_);
  for (size_t k = 0; k < crossed.size(); ++k) {
    const auto [a, b] = crossed[k];
    const Gaussian blend = blend_gaussians(arrays, {{a, 0.5}, {b, 0.5}});
    const Vec3 p = saved.mean(24 + k), from = original_.mean(size_t(a)), along = original_.mean(size_t(b)) - from;
    EXPECT_LT((p - blend.mean).norm(), 1e-12) << k;
    EXPECT_LT((saved.covariance(24 + k) - 0.09 * blend.covariance).norm(), 1e-12) << k;
    EXPECT_LT((p - from).cross(along).norm() / along.norm(), 1e-12) << k << ": off its edge";
    if (k % 2 == 1) {
      EXPECT_LT((p - middle(a, b)).norm(), 1e-12) << k;
    }
  }
  ASSERT_EQ(saved.sharpness.creases.size(), 4u);
  for (int v = 24; v < 28; ++v) EXPECT_EQ(saved.sharpness.crease(v, v + 1), kInfiniteSharpness) << v;
}

// The centre of a face's corners.
Vec3 face_centre(const CovarianceMesh& mesh, int f) {
  Vec3 c = Vec3::Zero();
  for (const int v : mesh.face(size_t(f))) c += mesh.mean(size_t(v)) / double(mesh.face_size(size_t(f)));
  return c;
}

// Of the faces whose centres lie on the cylinder's outer wall (radius past 0.85) between heights lo
// and hi, the one whose centre is nearest `near`.
int wall_face_nearest(const CovarianceMesh& mesh, double lo, double hi, const Vec3& near) {
  int best = -1;
  for (int f = 0; f < int(mesh.n_faces()); ++f) {
    const Vec3 c = face_centre(mesh, f);
    if (c.y() < lo || c.y() > hi || Vec3(c.x(), 0, c.z()).norm() < 0.85) continue;
    if (best < 0 || (c - near).norm() < (face_centre(mesh, best) - near).norm()) best = f;
  }
  return best;
}

// A designer's mug from the cylinder in 9 actions (Blender about 28): a box around the top cap,
// I 0.2 Enter, E −1.5 Enter (the cup hollowed); face mode (3); Ctrl+R 2 on the upper row's front
// vertical edge, its slide 0 (that row cut in three); the top strip's front face clicked, E 0.6 Enter
// (the handle's upper stub); Shift+click on the lower row's face below it, Ctrl+E (the stub's end and
// that face bridged and deleted: the handle); the save. (Alt+A, the View panel's "base mesh" and Home
// only show it.) The file is core's operations in that order:
// closed, outward, one part of genus 1, the handle standing out from the wall in front.
TEST_F(EditorTools, DesignerReplayMugWithABridgedHandle) {
  use_mesh(make_sample("cylinder"));  // rings of 8 at y = −1, 0, 1 (vertices 0–7, 8–15, 16–23); top cap 16
  const Vec3 eye = to_vec(view_.camera.eye());
  int front = 0;  // the vertical edges' column nearest the camera
  for (int k = 1; k < 8; ++k)
    if ((original_.mean(size_t(8 + k)) - eye).norm() < (original_.mean(size_t(8 + front)) - eye).norm()) front = k;
  // The same operations in core, for the faces to click and the file to expect.
  const Modelled inset = inset_faces(original_, {16}, 0.2);
  const Modelled hollow = extrude_faces(inset.mesh, faces_within(inset.mesh, inset.selection), -1.5);
  const Modelled rows = loop_cut(hollow.mesh, 8 + front, 16 + front, 2);
  const int top = wall_face_nearest(rows.mesh, 0.67, 1.0, eye);
  const Modelled stub = extrude_faces(rows.mesh, {top}, 0.6);
  const std::vector<int> stub_end = faces_within(stub.mesh, stub.selection);
  ASSERT_EQ(stub_end.size(), 1u);
  const Vec3 above = face_centre(rows.mesh, top);
  const int below = wall_face_nearest(stub.mesh, -1.0, 0.0, Vec3(above.x(), -0.5, above.z()));
  const Modelled mug = bridge_faces(stub.mesh, {stub_end[0], below});

  Events e;
  glm::vec2 lo(1e9f), hi(-1e9f);
  for (int v = 16; v < 24; ++v) {
    lo = glm::min(lo, pixel_of(view_, original_.mean(size_t(v))));
    hi = glm::max(hi, pixel_of(view_, original_.mean(size_t(v))));
  }
  e.drag(lo - 10.0f, hi + 10.0f, 8).wait();
  e.key("i").wait().text("0.2").wait().key("enter").wait();
  e.key("e").wait().text("-1.5").wait().key("enter").wait();
  e.key("3").wait();
  const glm::vec2 edge =
      pixel_of(view_, 0.5 * (hollow.mesh.mean(size_t(8 + front)) + hollow.mesh.mean(size_t(16 + front))));
  e.key("ctrl+r").move(edge).wait().text("2").wait().click(edge).wait().text("0").wait().key("enter").wait();
  e.click(pixel_of(view_, above)).wait().key("e").wait().text("0.6").wait().key("enter").wait();
  e.click(pixel_of(view_, face_centre(stub.mesh, below)), "shift").wait().key("ctrl+e").wait();
  e.key("alt+a").wait().click(kBaseMeshBox).wait().key("home").wait(3);  // to look at it: the surface alone
  const CovarianceMesh saved = play(e, "designer_mug.png");
  EXPECT_NE(output_.find("bridged two loops of 4 vertices"), std::string::npos) << output_;

  EXPECT_TRUE(test::nearly_same_mesh(saved, mug.mesh, 1e-9)) << output_;
  const test::Shape shape = test::shape_of(saved);
  EXPECT_EQ(shape.vertices, 24 + 8 + 8 + 16 + 4);
  EXPECT_EQ(shape.faces, 18 + 8 + 8 + 16 + 4 - 2 + 4);
  EXPECT_EQ(shape.boundary_edges, 0);
  EXPECT_TRUE(shape.oriented);
  EXPECT_EQ(shape.euler(), 0) << "genus 1: the handle";
  EXPECT_GT(test::signed_volume(saved), 0.0);
  // Hollow to 0.5 above the base; the handle stands out of the wall by the stub's 0.6.
  double deepest = 1, farthest = 0;
  for (size_t v = 0; v < saved.n_vertices(); ++v) {
    const Vec3 p = saved.mean(v);
    if (Vec3(p.x(), 0, p.z()).norm() < 0.9) deepest = std::min(deepest, p.y());
    farthest = std::max(farthest, Vec3(p.x(), 0, p.z()).norm());
  }
  EXPECT_NEAR(deepest, -0.5, 1e-9);
  EXPECT_GT(farthest, 1.4);
}

}  // namespace
}  // namespace gps
