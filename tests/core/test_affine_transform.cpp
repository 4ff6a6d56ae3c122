// Affine transforms of vertices: GPS commutes with affine maps, so transforming every vertex moves
// the exact limit surface with the map (means and covariances); a partial transform touches only its
// vertices; a mirror reverses the faces it moves whole so that they stay outward; a scale of 0 (S Z 0)
// flattens the positions exactly and holds the Gaussians at the flatness floor; malformed maps are
// refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/modelling/samples.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/operation_list.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::signed_volume;

using test::error_of;

// A rotation, a non-uniform scale and a shear together, and a translation.
AffineMap skewed_map() {
  const Mat3 rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  Mat3 shear = Mat3::Identity();
  shear(0, 1) = 0.6;
  shear(2, 0) = -0.3;
  const Mat3 scale = Vec3(2.5, 0.4, 1.3).asDiagonal();
  return AffineMap{rotation * scale * shear, Vec3(3, -1, 7.5)};
}

SubdivisionResult limit_of(const CovarianceMesh& m, Scheme scheme) {
  SubdivisionOptions o;
  o.scheme = scheme;
  o.levels = 2;
  o.limit = true;
  return subdivide(m, o);
}

void expect_limit_moves_with_the_map(const CovarianceMesh& m, Scheme scheme) {
  const AffineMap map = skewed_map();
  const Modelled moved = transform_vertices(m, {}, map);
  ASSERT_EQ(moved.selection.size(), m.n_vertices());
  for (size_t v = 0; v < m.n_vertices(); ++v) {
    const Mat3 want = map.linear * m.covariance(v) * map.linear.transpose();
    EXPECT_LE((moved.mesh.covariance(v) - want).norm(), 1e-15 * want.norm());
    EXPECT_LE((moved.mesh.mean(v) - map.apply(m.mean(v))).norm(), 1e-15 * (1 + moved.mesh.mean(v).norm()));
  }
  const SubdivisionResult before = limit_of(m, scheme), after = limit_of(moved.mesh, scheme);
  ASSERT_EQ(before.mesh.n_vertices(), after.mesh.n_vertices());
  const double diagonal = bounding_box_diagonal(after.mesh);
  double worst_mean = 0, worst_covariance = 0;
  for (size_t v = 0; v < before.mesh.n_vertices(); ++v) {
    worst_mean = std::max(worst_mean, (after.mesh.mean(v) - map.apply(before.mesh.mean(v))).norm());
    const Mat3 want = map.linear * before.mesh.covariance(v) * map.linear.transpose();
    worst_covariance = std::max(worst_covariance, (after.mesh.covariance(v) - want).norm() / want.norm());
  }
  EXPECT_LE(worst_mean, 1e-12 * diagonal);
  EXPECT_LE(worst_covariance, 1e-9);
}

TEST(AffineTransform, CatmullClarkLimitMovesWithTheMap) {
  expect_limit_moves_with_the_map(test::with_random_covariances(make_sample("cylinder"), 21), Scheme::catmull_clark);
  expect_limit_moves_with_the_map(test::with_random_covariances(test::grid_mesh(4, 3), 22), Scheme::catmull_clark);
}

TEST(AffineTransform, LoopLimitMovesWithTheMap) {
  expect_limit_moves_with_the_map(test::with_random_covariances(make_sample("icosphere", 80), 23), Scheme::loop);
}

TEST(AffineTransform, PartialTransformChangesOnlyItsVertices) {
  const CovarianceMesh m = test::with_random_covariances(make_sample("cube"), 24);
  const Modelled r = transform_vertices(m, {6, 1, 6}, skewed_map());
  EXPECT_EQ(r.selection, (std::vector<int>{1, 6}));
  EXPECT_EQ(r.summary, "transformed 2 vertices");
  for (size_t v = 0; v < m.n_vertices(); ++v) {
    if (v == 1 || v == 6) {
      EXPECT_NE(r.mesh.mean(v), m.mean(v));
      EXPECT_LE((r.mesh.mean(v) - skewed_map().apply(m.mean(v))).norm(), 1e-14);
    } else {
      EXPECT_EQ(r.mesh.mean(v), m.mean(v)) << "vertex " << v;
      EXPECT_EQ(r.mesh.covariance(v), m.covariance(v)) << "vertex " << v;
    }
  }
  EXPECT_EQ(arrays_of(r.mesh).faces, arrays_of(m).faces);
}

TEST(AffineTransform, AboutKeepsThePivotAndFromRowsReadsRowMajor) {
  const Vec3 pivot(1, 2, 3);
  const AffineMap about = AffineMap::about(pivot, skewed_map().linear);
  EXPECT_LE((about.apply(pivot) - pivot).norm(), 1e-14);
  const AffineMap rows = AffineMap::from_rows({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 11, 0, 0, 0, 1});
  EXPECT_EQ(rows.apply(Vec3(1, 0, 0)), Vec3(5, 13, 20));
  EXPECT_EQ(rows.translation, Vec3(4, 8, 11));
}

// A mirror (negative determinant) reverses the faces with the positions, as Blender does, so that
// the surface stays outward: the signed volume keeps its sign, here its value too.
TEST(AffineTransform, AMirrorKeepsTheSurfaceOutward) {
  const CovarianceMesh cube = test::with_random_covariances(make_sample("cube"), 25);
  const double volume = signed_volume(arrays_of(cube));
  ASSERT_GT(volume, 0);
  for (const Mat3& mirror : {Mat3(Vec3(-1, 1, 1).asDiagonal()), Mat3(-skewed_map().linear)}) {
    const Modelled r = transform_vertices(cube, {}, AffineMap{mirror, Vec3(1, 2, 3)});
    EXPECT_NEAR(signed_volume(arrays_of(r.mesh)), volume * std::abs(mirror.determinant()), 1e-12 * volume);
    EXPECT_EQ(r.summary, "transformed 8 vertices (mirrored: 6 faces reversed to stay outward)");
    const MeshArrays before = arrays_of(cube), after = arrays_of(r.mesh);
    ASSERT_EQ(after.faces.size(), before.faces.size());
    for (size_t f = 0; f < before.faces.size(); ++f) {
      std::vector<int> reversed = before.faces[f];
      std::reverse(reversed.begin() + 1, reversed.end());
      EXPECT_EQ(after.faces[f], reversed) << "face " << f;
    }
  }
}

// A mirror of some of a part's vertices turns no part inside out: nothing is reversed, and the
// summary says so.
TEST(AffineTransform, AMirrorOfPartOfAPartReversesNothingAndSaysSo) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled r = transform_vertices(cube, {0, 1, 2}, AffineMap{Mat3(Vec3(-1, 1, 1).asDiagonal()), Vec3(3, 0, 0)});
  EXPECT_EQ(r.summary, "transformed 3 vertices (mirrored in part: no part moved whole, no face reversed)");
  EXPECT_EQ(arrays_of(r.mesh).faces, arrays_of(cube).faces);
}

// Only the parts a mirror moves whole are reversed: the part it leaves keeps its faces as they were.
TEST(AffineTransform, AMirrorReversesOnlyThePartsItMovesWhole) {
  MeshArrays two = arrays_of(make_sample("cube"));
  const MeshArrays one = two;
  for (const std::vector<int>& face : one.faces) {
    std::vector<int> shifted = face;
    for (int& v : shifted) v += one.n_vertices();
    two.faces.push_back(shifted);
  }
  for (int v = 0; v < one.n_vertices(); ++v)
    two.add_vertex({one.means[size_t(v)] + Vec3(5, 0, 0), one.covariances[size_t(v)]});
  const CovarianceMesh mesh = build_mesh(two);
  std::vector<int> second;
  for (int v = one.n_vertices(); v < two.n_vertices(); ++v) second.push_back(v);
  const Modelled r = transform_vertices(mesh, second, AffineMap::about(Vec3(5, 0, 0), Vec3(1, -1, 1).asDiagonal()));
  const MeshArrays after = arrays_of(r.mesh);
  for (size_t f = 0; f < one.faces.size(); ++f) EXPECT_EQ(after.faces[f], two.faces[f]) << "face " << f;
  MeshArrays first_part = after, second_part = after;
  first_part.faces.resize(one.faces.size());
  second_part.faces.erase(second_part.faces.begin(), second_part.faces.begin() + long(one.faces.size()));
  EXPECT_NEAR(signed_volume(first_part), signed_volume(one), 1e-12);
  EXPECT_NEAR(signed_volume(second_part), signed_volume(one), 1e-12);
}

TEST(AffineTransform, RefusalsChangeNothing) {
  const CovarianceMesh m = make_sample("cube");
  EXPECT_EQ(error_of([] {
              AffineMap::from_rows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0});
            }),
            "the matrix has 15 numbers (16 needed: a row-major 4×4 affine map)");
  EXPECT_EQ(error_of([] {
              AffineMap::from_rows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1});
            }),
            "the matrix's last row must be 0 0 0 1 (an affine map)");
  EXPECT_EQ(
      error_of([] {
        AffineMap::from_rows({1, 0, 0, std::numeric_limits<double>::infinity(), 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
      }),
      "the matrix has a number that is not finite");
  EXPECT_EQ(
      error_of([&] {
        transform_vertices(m, {}, AffineMap{Mat3::Constant(std::numeric_limits<double>::quiet_NaN()), Vec3::Zero()});
      }),
      "the map has a number that is not finite");
  EXPECT_EQ(error_of([&] { transform_vertices(m, {2, 8}, skewed_map()); }), "vertex 8 is not in the mesh (8 vertices)");
  // A huge uniform scale is not singular: its results are out of range, and that is what is said.
  EXPECT_EQ(error_of([&] {
              transform_vertices(m, {}, AffineMap{1e200 * Mat3::Identity(), Vec3::Zero()});
            }),
            "the result would not be a valid mesh: vertex 0 has a coordinate 1e+200 beyond ±1e+100 (its products "
            "would overflow)");
  const CovarianceMesh fresh = make_sample("cube");
  for (size_t v = 0; v < m.n_vertices(); ++v) EXPECT_EQ(m.mean(v), fresh.mean(v));
}

// The cube with vertex `raised` of its top face lifted by 0.5, and its top face's vertices.
CovarianceMesh cube_with_a_raised_corner(std::vector<int>& top) {
  MeshArrays a = arrays_of(test::cube_mesh());
  top = {4, 5, 6, 7};  // z = 1
  a.means[6].z() += 0.5;
  return build_mesh(a);
}

// S Z 0 about the median of the vertices (Blender's way to flatten them), as an op list.
OperationList flatten_along_z(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  double z = 0;
  for (int v : vertices) z += mesh.mean(size_t(v)).z();
  z /= double(vertices.size());
  char matrix[160];
  std::snprintf(matrix, sizeof matrix, "[1,0,0,0, 0,1,0,0, 0,0,0,%.17g, 0,0,0,1]", z);
  std::string list;
  for (int v : vertices) list += (list.empty() ? "" : ",") + std::to_string(v);
  return OperationList::parse(
      "[{\"op\":\"transform\",\"vertices\":[" + list + "],\"matrix\":" + std::string(matrix) + "}]", "ops.json");
}

TEST(AffineTransform, ScaleZeroFlattensThePositionsAndHoldsTheGaussiansAtTheFloor) {
  std::vector<int> top;
  const CovarianceMesh cube = cube_with_a_raised_corner(top);
  std::vector<std::string> summaries;
  const Modelled r = flatten_along_z(cube, top).apply(cube, &summaries);
  ASSERT_EQ(summaries.size(), 1u);
  EXPECT_EQ(summaries[0],
            "transformed 4 vertices, 4 Gaussians held at the flatness floor (0.001 of the map's "
            "strongest stretch)");
  for (int v : top) {
    EXPECT_EQ(r.mesh.mean(size_t(v)).z(), 1.125) << v;  // exactly on the median's plane
    EXPECT_EQ(r.mesh.mean(size_t(v)).head<2>(), cube.mean(size_t(v)).head<2>()) << v;
    const Mat3& c = r.mesh.covariance(size_t(v));
    EXPECT_TRUE(covariance_problem(c).empty()) << v << ": " << covariance_problem(c);
    // Flat along z: its thinnest axis at the floor, 1e-6 of the cube's 0.09 and pointing up.
    const Eigen::SelfAdjointEigenSolver<Mat3> e(c);
    EXPECT_NEAR(e.eigenvalues()[0], 1e-6 * 0.09, 1e-18) << v;
    EXPECT_NEAR(std::abs(e.eigenvectors().col(0).z()), 1.0, 1e-12) << v;
    EXPECT_NEAR(e.eigenvalues()[1], 0.09, 1e-15) << v;
  }
  for (int v = 0; v < 4; ++v) {
    EXPECT_EQ(r.mesh.mean(size_t(v)), cube.mean(size_t(v)));
    EXPECT_EQ(r.mesh.covariance(size_t(v)), cube.covariance(size_t(v)));
  }
  // The limit surface stays finite, and its top comes down to the flattened plane.
  SubdivisionOptions o;
  o.levels = 3;
  o.limit = true;
  const SubdivisionResult limit = subdivide(r.mesh, o);
  double highest = -INFINITY;
  for (size_t v = 0; v < limit.mesh.n_vertices(); ++v) {
    ASSERT_TRUE(limit.mesh.mean(v).allFinite()) << v;
    ASSERT_TRUE(limit.mesh.covariance(v).allFinite()) << v;
    highest = std::max(highest, limit.mesh.mean(v).z());
  }
  EXPECT_LE(highest, 1.125 + 1e-9);
  EXPECT_GT(highest, 1.0);  // not collapsed towards the bottom
}

// Whether the carried covariance's least eigenvalue, as the solver finds it, is below the floor of
// the rule (the header's definition): what decides between AΣAᵀ as it is and the clamp.
bool solved_below_floor(const AffineMap& map, const Gaussian& g) {
  const double thinnest = Eigen::SelfAdjointEigenSolver<Mat3>(g.covariance, Eigen::EigenvaluesOnly).eigenvalues()[0];
  const double strongest = strongest_stretch(map);
  const double stretch = kFlattestStretch * (strongest > 0 ? strongest : 1.0);
  const Mat3 carried = map.apply(g).covariance;
  return Eigen::SelfAdjointEigenSolver<Mat3>(carried, Eigen::EigenvaluesOnly).eigenvalues()[0] <
         stretch * stretch * thinnest;
}

// Gaussians round, flat and needle-thin (condition up to 1e14), turned every way, under maps whose
// weakest stretch lies on either side of the floor's ratio and right at it: held at the floor exactly
// where the solved eigenvalue is below it, else AΣAᵀ bit for bit, whether the solves were spared or not.
TEST(AffineTransform, CarriedGaussiansAreTheRuleOfTheirEigenvaluesBitForBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto rotation = [&] {
    return Mat3(Eigen::AngleAxisd(3.0 * unit(rng), Vec3(unit(rng), unit(rng), unit(rng) + 2.0).normalized()));
  };
  int clamped = 0, carried = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const double thin = std::pow(10.0, -14.0 * std::abs(unit(rng)));
    const Vec3 axes(1.0, trial % 3 == 0 ? 1.0 : std::sqrt(thin), thin);
    // Every fourth along the axes, where the eigenvalues are the diagonal's and land on the floor.
    const bool aligned = trial % 4 == 1;
    const Mat3 r = aligned ? Mat3::Identity() : rotation();
    const Gaussian g{Vec3(unit(rng), unit(rng), unit(rng)), 0.01 * r * axes.asDiagonal() * r.transpose()};
    // The weakest stretch: 1e-3 of the strongest times 10^[-1, 1], exactly at it, or next to it.
    const double weakest = trial % 5 == 0   ? kFlattestStretch
                           : trial % 5 == 1 ? kFlattestStretch * (1.0 + 1e-9 * unit(rng))
                                            : kFlattestStretch * std::pow(10.0, unit(rng));
    const Vec3 stretches(trial % 2 == 0 ? 1.0 : 1.0 + std::abs(unit(rng)), 0.5 + std::abs(unit(rng)), weakest);
    const Mat3 a =
        aligned ? Mat3(Vec3(stretches[0], std::max(stretches[0], stretches[1]), weakest * stretches[0]).asDiagonal())
                : Mat3(rotation() * stretches.asDiagonal() * rotation());
    const AffineMap map{trial % 7 == 0 ? Mat3(1.01 * Mat3::Identity()) : a, Vec3(unit(rng), 0.5, 2.0)};
    const CarriedGaussian got = carried_gaussian(map, g);
    ASSERT_EQ(got.clamped, solved_below_floor(map, g)) << "trial " << trial;
    ASSERT_EQ(got.gaussian.mean, map.apply(g).mean) << "trial " << trial;
    if (!got.clamped) ASSERT_EQ(got.gaussian.covariance, map.apply(g).covariance) << "trial " << trial;
    (got.clamped ? clamped : carried) += 1;
  }
  EXPECT_GT(clamped, 500);
  EXPECT_GT(carried, 500);
}

TEST(AffineTransform, MapsWithinTheFloorAreCarriedExactly) {
  const CovarianceMesh cube = test::cube_mesh();
  // Squeezed 100 times along z (within 1e-3): AΣAᵀ exactly; 1e4 times: held at the floor.
  const AffineMap squeeze{Vec3(2, 2, 0.02).asDiagonal(), Vec3(0.5, 0, 0)};
  const Modelled within = transform_vertices(cube, {}, squeeze);
  EXPECT_EQ(within.summary, "transformed 8 vertices");
  for (size_t v = 0; v < 8; ++v) {
    const Gaussian g = squeeze.apply(Gaussian{cube.mean(v), cube.covariance(v)});
    EXPECT_EQ(within.mesh.mean(v), g.mean);
    EXPECT_EQ(within.mesh.covariance(v), g.covariance);
  }
  const CarriedGaussian past = carried_gaussian(AffineMap{Vec3(2, 2, 2e-4).asDiagonal(), Vec3::Zero()},
                                                Gaussian{Vec3(1, 1, 1), 0.09 * Mat3::Identity()});
  EXPECT_TRUE(past.clamped);
  EXPECT_NEAR(past.gaussian.covariance(2, 2), 4e-6 * 0.09, 1e-18);
  EXPECT_EQ(past.gaussian.mean, Vec3(2, 2, 2e-4));
  // The zero map puts every vertex on one point, each Gaussian a sphere at the floor.
  const Modelled point = transform_vertices(cube, {}, AffineMap{Mat3::Zero(), Vec3(1, 2, 3)});
  for (size_t v = 0; v < 8; ++v) {
    EXPECT_EQ(point.mesh.mean(v), Vec3(1, 2, 3));
    EXPECT_LT((point.mesh.covariance(v) - 1e-6 * 0.09 * Mat3::Identity()).norm(), 1e-20);
  }
}

}  // namespace
}  // namespace gps
