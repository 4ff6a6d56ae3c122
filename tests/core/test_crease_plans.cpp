// Plans of creased meshes evaluate the limit surface exactly: at every parameter the reference
// (OpenSubdiv's crease rules in 9D, deep enough for every semi-sharp crease to have decayed, then the
// limit) gives, inside patches as well as at their corners; along an infinitely sharp crease the two
// sides meet in one curve with a normal of their own each.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "core/evaluation/patch_eval.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::PlannedMesh;
using test::with_random_covariances;

CovarianceMesh creased(CovarianceMesh m, const std::vector<EdgeCrease>& creases,
                       const std::vector<std::pair<int, double>>& corners = {}) {
  for (const EdgeCrease& c : creases) m.sharpness.set_crease(c.a, c.b, c.sharpness);
  for (const auto& [v, s] : corners) m.sharpness.set_corner(v, s, int(m.n_vertices()));
  return m;
}

// The cube with its top face's four edges infinitely sharp.
CovarianceMesh cube_with_sharp_top() {
  return creased(test::cube_mesh(), {{4, 5, 10}, {5, 6, 10}, {6, 7, 10}, {4, 7, 10}});
}

struct Case {
  std::string name;
  CovarianceMesh mesh;
};

std::vector<Case> creased_quad_cases() {
  std::vector<Case> cases;
  cases.push_back({"cube, sharp top", with_random_covariances(cube_with_sharp_top(), 1)});
  cases.push_back(
      {"cube, mixed",
       with_random_covariances(
           creased(test::cube_mesh(), {{0, 1, 0.5}, {1, 2, 1.0}, {2, 3, 2.5}, {0, 3, 4.7}, {4, 5, 10}, {5, 6, 10}},
                   {{6, 10}, {7, 2.5}, {4, 10}}),
           2)});
  std::vector<EdgeCrease> all;
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{
           {0, 1}, {1, 2}, {2, 3}, {0, 3}, {4, 5}, {5, 6}, {6, 7}, {4, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}})
    all.push_back({a, b, 10});
  cases.push_back({"cube, all sharp", with_random_covariances(creased(test::cube_mesh(), all), 3)});
  // A 6 × 5 grid: a sharp line across it from boundary to boundary (regular crease patches in
  // between, corners where it meets the boundary), a semi-sharp line and a semi-sharp corner.
  std::vector<EdgeCrease> grid;
  for (int i = 0; i < 6; ++i) grid.push_back({2 * 7 + i, 2 * 7 + i + 1, 10});
  for (int j = 0; j < 4; ++j) grid.push_back({j * 7 + 4, (j + 1) * 7 + 4, 2.5});
  cases.push_back(
      {"grid, lines", with_random_covariances(creased(test::grid_mesh(6, 5), grid, {{4 * 7 + 3, 4.7}}), 4)});
  // The torus sample (24 × 12 quads) with its outer equator sharp (regular crease vertices all
  // along) and a semi-sharp edge elsewhere.
  std::vector<EdgeCrease> ring;
  for (int i = 0; i < 24; ++i) ring.push_back({i * 12, (i + 1) % 24 * 12, 10});
  ring.push_back({5 * 12 + 6, 5 * 12 + 7, 1.5});
  cases.push_back({"torus, ring", with_random_covariances(creased(make_sample("torus"), ring), 5)});
  return cases;
}

double error_against_reference(const CovarianceMesh& mesh, int levels) {
  return test::error_against_reference(PlannedMesh(mesh, PlanOptions{Scheme::catmull_clark}),
                                       {Scheme::catmull_clark, levels, true});
}

// How far the creased plans are from the smooth surface (the same mesh without sharpness), at most,
// over the bounding-box diagonal: the creases must matter for a test of them to mean anything.
double distance_from_smooth(const PlannedMesh& creased, Scheme scheme) {
  CovarianceMesh smooth = creased.mesh;
  smooth.sharpness = {};
  const auto ref = subdivide(smooth, {scheme, 3, true});
  double moved = 0;
  for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
    const PatchParam& pp = ref.vertex_params[k];
    const auto s = evaluate_patch(creased.tables.plans, creased.points, pp.patch, pp.u, pp.v);
    moved = std::max(moved, (s->position - ref.mesh.mean(k)).norm());
  }
  return moved / bounding_box_diagonal(smooth);
}

TEST(CreasePlans, EqualTheReferenceInsidePatches) {
  for (const Case& c : creased_quad_cases()) {
    const double error = error_against_reference(c.mesh, 5);
    std::printf("%-17s: %.1e of the diagonal\n", c.name.c_str(), error);
    EXPECT_LT(error, 1e-9) << c.name;
    EXPECT_GT(distance_from_smooth(PlannedMesh(c.mesh, PlanOptions{Scheme::catmull_clark}), Scheme::catmull_clark),
              1e-3)
        << c.name << ": the creases change the surface";
  }
}

// Loop: box splines folded along sharp lines of valence-6 vertices (three triangles a side), exact
// tables at crease vertices with other sectors, at corners and darts, semi-sharp creases refined.
std::vector<Case> creased_triangle_cases() {
  std::vector<Case> cases;
  std::vector<EdgeCrease> grid;
  for (int i = 0; i < 8; ++i) grid.push_back({3 * 9 + i, 3 * 9 + i + 1, 10});
  for (int j = 0; j < 3; ++j) grid.push_back({j * 9 + 5, (j + 1) * 9 + 5, 1.5});
  cases.push_back(
      {"triangle grid", with_random_covariances(creased(test::triangle_grid_mesh(8, 6), grid, {{5 * 9 + 3, 2.5}}), 7)});
  cases.push_back(
      {"icosahedron",
       with_random_covariances(
           creased(test::icosahedron_mesh(),
                   {{5, 11, 10}, {1, 5, 10}, {1, 7, 10}, {7, 10, 10}, {10, 11, 10}, {3, 9, 2.5}}, {{2, 10}, {6, 1.5}}),
           8)});
  std::vector<EdgeCrease> equator;
  for (int k = 0; k < 7; ++k) equator.push_back({2 + k, 2 + (k + 1) % 7, 10});
  cases.push_back({"bipyramid", with_random_covariances(creased(test::bipyramid_mesh(7), equator, {{0, 4.7}}), 9)});
  // Crease ends: a line from the boundary ending inside the grid (a dart of valence 6), a lone sharp
  // edge on the icosahedron (darts of valence 5).
  cases.push_back({"grid, crease end",
                   with_random_covariances(creased(test::triangle_grid_mesh(8, 6), {{2 * 9 + 4, 3 * 9 + 4, 10},
                                                                                    {3 * 9 + 4, 4 * 9 + 4, 10},
                                                                                    {0 * 9 + 4, 1 * 9 + 4, 10},
                                                                                    {1 * 9 + 4, 2 * 9 + 4, 10}}),
                                           10)});
  cases.push_back({"icosahedron, dart", with_random_covariances(creased(test::icosahedron_mesh(), {{7, 10, 10}}), 11)});
  return cases;
}

TEST(CreasePlans, LoopEqualsTheReferenceInsidePatches) {
  for (const Case& c : creased_triangle_cases()) {
    const PlannedMesh p(c.mesh, PlanOptions{Scheme::loop});
    const double error = test::error_against_reference(p, {Scheme::loop, 5, true});
    std::printf("%-17s: %.1e of the diagonal\n", c.name.c_str(), error);
    EXPECT_LT(error, 1e-9) << c.name;
    CovarianceMesh smooth = c.mesh;
    smooth.sharpness = {};
    EXPECT_GT(distance_from_smooth(p, Scheme::loop), 1e-3) << c.name << ": the creases change the surface";
  }
}

// At a dart (a vertex with one sharp edge) the plans equal the reference, whose limit step takes
// the dart's own mask there (core/reference/dart_masks.h), from any level.
TEST(CreasePlans, DartsEqualTheReference) {
  const CovarianceMesh cube = with_random_covariances(creased(test::cube_mesh(), {{4, 5, 10}, {1, 5, 10}}), 2);
  const CovarianceMesh torus =
      with_random_covariances(creased(make_sample("torus"), {{5 * 12 + 6, 5 * 12 + 7, 10}}), 5);
  for (const CovarianceMesh* mesh : std::vector<const CovarianceMesh*>{&cube, &torus})
    for (const int levels : {2, 4}) {
      const double error = error_against_reference(*mesh, levels);
      std::printf("darts: %.1e of the diagonal at level %d\n", error, levels);
      EXPECT_LT(error, 1e-9) << levels << " levels";
    }
}

// The reference's limit normals equal the plans' wherever it gives one: at darts (core/reference/
// dart_masks.h: the tangents of the dart's own step, not the smooth ones), at valences 3 to 6, on
// quads and on triangles, from any level. The largest angle between the two, in radians.
double normal_error_against_plans(const CovarianceMesh& mesh, Scheme scheme, int levels, int& compared) {
  const PlannedMesh p(mesh, PlanOptions{scheme});
  const SubdivisionResult ref = subdivide(mesh, {scheme, levels, true, LoopBeta::loop, true});
  double largest = 0;
  compared = 0;
  for (size_t k = 0; k < ref.mesh.n_vertices(); ++k) {
    if (ref.normals[k].isZero(0.0)) continue;
    const PatchParam& pp = ref.vertex_params[k];
    const auto s = evaluate_patch(p.tables.plans, p.points, pp.patch, pp.u, pp.v);
    if (!s) continue;
    largest = std::max(largest, std::atan2(s->normal.cross(ref.normals[k]).norm(), s->normal.dot(ref.normals[k])));
    ++compared;
  }
  return largest;
}

TEST(CreasePlans, DartNormalsEqualThePlans) {
  struct NormalCase {
    std::string name;
    CovarianceMesh mesh;
    Scheme scheme;
  };
  const auto file = [](const std::string& name) {
    return with_random_covariances(read_mesh(std::string(GPS_TEST_DATA_DIR) + "/infinite_creases/" + name + ".obj"),
                                   17);
  };
  std::vector<NormalCase> cases = {
      {"cube, darts", with_random_covariances(creased(test::cube_mesh(), {{4, 5, 10}, {1, 5, 10}}), 2),
       Scheme::catmull_clark},
      {"torus, one edge", with_random_covariances(creased(make_sample("torus"), {{5 * 12 + 6, 5 * 12 + 7, 10}}), 5),
       Scheme::catmull_clark},
      {"dart grid", file("dart_grid"), Scheme::catmull_clark},
      {"fan darts", file("fan_darts"), Scheme::catmull_clark},
      {"icosahedron, dart", with_random_covariances(creased(test::icosahedron_mesh(), {{7, 10, 10}}), 11),
       Scheme::loop},
  };
  for (const auto& c : creased_triangle_cases())
    if (c.name == "grid, crease end") cases.push_back({c.name, c.mesh, Scheme::loop});
  for (const NormalCase& c : cases)
    for (const int levels : {1, 3}) {
      int compared = 0;
      const double angle = normal_error_against_plans(c.mesh, c.scheme, levels, compared);
      std::printf("%-18s level %d: %.1e rad over %d normals\n", c.name.c_str(), levels, angle, compared);
      EXPECT_GT(compared, 0) << c.name;
      EXPECT_LT(angle, 1e-9) << c.name << ", " << levels << " levels";
    }
}

// Every configuration of infinitely sharp creases OpenSubdiv's rules give, one mesh each
// (tests/data/infinite_creases, with random anisotropic Gaussians): the plans equal the reference's
// limit at equal parameters, whether it projects after two levels or after five.
void expect_plans_equal_reference(const std::string& name) {
  const CovarianceMesh mesh =
      with_random_covariances(read_mesh(std::string(GPS_TEST_DATA_DIR) + "/infinite_creases/" + name + ".obj"), 17);
  for (const int levels : {2, 5}) {
    const double error = error_against_reference(mesh, levels);
    std::printf("%-15s: %.1e of the diagonal at level %d\n", name.c_str(), error, levels);
    EXPECT_LT(error, 1e-9) << name << ", " << levels << " levels";
  }
  EXPECT_GT(distance_from_smooth(PlannedMesh(mesh, PlanOptions{Scheme::catmull_clark}), Scheme::catmull_clark), 1e-3)
      << name << ": the creases change the surface";
}

TEST(CreasePlans, BoxWithSharpEdgesEqualsTheReference) { expect_plans_equal_reference("sharp_box"); }
TEST(CreasePlans, CreaseLoopsEqualTheReference) { expect_plans_equal_reference("crease_loop"); }
TEST(CreasePlans, CreaseEndsEqualTheReference) { expect_plans_equal_reference("dart_grid"); }
TEST(CreasePlans, CornersOfSeveralCreasesEqualTheReference) { expect_plans_equal_reference("corner_creases"); }
TEST(CreasePlans, DartsAtExtraordinaryVerticesEqualTheReference) { expect_plans_equal_reference("fan_darts"); }
TEST(CreasePlans, CreasesThroughExtraordinaryVerticesEqualTheReference) { expect_plans_equal_reference("fan_creases"); }
TEST(CreasePlans, CornersAtExtraordinaryVerticesEqualTheReference) { expect_plans_equal_reference("fan_corners"); }

TEST(CreasePlans, ZeroSharpnessGivesTheSmoothPlansBitForBit) {
  for (const char* name : {"cube", "icosphere"}) {
    CovarianceMesh smooth = with_random_covariances(make_sample(name), 6), zero = smooth;
    zero.sharpness.corners.assign(zero.n_vertices(), 0.0);
    const PlannedMesh a(smooth, PlanOptions{}), b(zero, PlanOptions{});
    EXPECT_EQ(a.tables.plans.nodes, b.tables.plans.nodes) << name;
    EXPECT_EQ(a.tables.plans.extraordinary_tables, b.tables.plans.extraordinary_tables) << name;
    EXPECT_EQ(a.tables.stencils.weights, b.tables.stencils.weights) << name;
  }
}

// Along the cube's sharp top rim the top patch and the side patch give the same point with
// normals of their own; without the crease they give one normal.
TEST(CreasePlans, NormalsAreOneSidedAlongASharpCrease) {
  for (const bool sharp : {true, false}) {
    const CovarianceMesh mesh = sharp ? cube_with_sharp_top() : test::cube_mesh();
    const PlannedMesh p(mesh, PlanOptions{Scheme::catmull_clark});
    // Face 1 = (4, 5, 6, 7): edge 4 → 5 at v = 0; face 2 = (0, 1, 5, 4): the same edge at v = 1.
    double smallest_angle = M_PI, largest_angle = 0.0;
    for (const double u : {0.1, 0.37, 0.5, 0.81}) {
      const auto top = evaluate_patch(p.tables.plans, p.points, 1, u, 0.0);
      const auto side = evaluate_patch(p.tables.plans, p.points, 2, u, 1.0);
      ASSERT_TRUE(top && side);
      EXPECT_LT((top->position - side->position).norm(), 1e-12);
      const double angle = std::acos(std::clamp(top->normal.dot(side->normal), -1.0, 1.0));
      smallest_angle = std::min(smallest_angle, angle);
      largest_angle = std::max(largest_angle, angle);
    }
    if (sharp)
      EXPECT_GT(smallest_angle, 0.5) << "the crease's two sides share a normal";
    else
      EXPECT_LT(largest_angle, 1e-6);
  }
}

}  // namespace
}  // namespace gps
