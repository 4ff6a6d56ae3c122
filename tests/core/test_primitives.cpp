#include "core/modelling/primitives.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "tests/support/error_of.h"
#include "tests/support/mesh_checks.h"

namespace gps {
namespace {

using test::error_of;

using test::boundary_edges_of_oriented;

// Σ over faces of the fan triangles' signed volumes about `origin`, and of their area vectors.
void volume_and_area(const CovarianceMesh& m, const Vec3& origin, double& volume, Vec3& area) {
  const MeshArrays a = arrays_of(m);
  volume = 0;
  area = Vec3::Zero();
  for (const auto& f : a.faces)
    for (size_t k = 1; k + 1 < f.size(); ++k) {
      const Vec3 p = a.means[size_t(f[0])] - origin, q = a.means[size_t(f[k])] - origin,
                 r = a.means[size_t(f[k + 1])] - origin;
      volume += p.dot(q.cross(r)) / 6;
      area += (q - p).cross(r - p) / 2;
    }
}

struct Expected {
  Primitive primitive;
  size_t vertices, faces;
  bool closed;
};

TEST(Primitives, EachIsValidOrientedOutwardCentredAndSized) {
  const std::vector<Expected> all = {{Primitive::plane, 9, 4, false},     {Primitive::cube, 8, 6, true},
                                     {Primitive::cylinder, 16, 10, true}, {Primitive::cone, 9, 9, true},
                                     {Primitive::sphere, 26, 24, true},   {Primitive::torus, 48, 48, true}};
  const Vec3 center(1, -2, 3);
  for (const Expected& e : all) {
    const std::string name = primitive_names()[size_t(e.primitive)];
    const Modelled r = add_primitive(CovarianceMesh{}, e.primitive, center, 2.5);
    EXPECT_EQ(r.mesh.n_vertices(), e.vertices) << name;
    EXPECT_EQ(r.mesh.n_faces(), e.faces) << name;
    EXPECT_EQ(r.selection.size(), e.vertices) << name;
    EXPECT_EQ(r.selection.back(), int(e.vertices) - 1) << name;
    EXPECT_EQ(r.summary, "added a " + name + ": " + std::to_string(e.vertices) + " vertices, " +
                             std::to_string(e.faces) + " faces");
    const int boundary = boundary_edges_of_oriented(r.mesh);
    EXPECT_EQ(boundary == 0, e.closed) << name;
    double volume;
    Vec3 area;
    volume_and_area(r.mesh, center, volume, area);
    if (e.closed) {
      EXPECT_GT(volume, 0.1) << name << " is not oriented outward";
      EXPECT_NEAR(area.norm(), 0, 1e-12) << name;
    } else {
      EXPECT_EQ(boundary, 8) << name;
      EXPECT_NEAR(area.y(), 2.5 * 2.5, 1e-12) << name << " faces +y";
    }
    Vec3 lo, hi;
    bounding_box(r.mesh, lo, hi);
    EXPECT_TRUE((0.5 * (lo + hi)).isApprox(center, 1e-14)) << name;
    EXPECT_NEAR((hi - lo).maxCoeff(), 2.5, 1e-12) << name;
    // Isotropic, σ half the mean edge length, the same at every vertex.
    const MeshArrays a = arrays_of(r.mesh);
    double total = 0;
    int count = 0;
    for (const auto& f : a.faces)
      for (size_t k = 0; k < f.size(); ++k, ++count)
        total += (a.means[size_t(f[k])] - a.means[size_t(f[(k + 1) % f.size()])]).norm();
    const double sigma = 0.5 * total / count;
    for (size_t v = 0; v < r.mesh.n_vertices(); ++v)
      EXPECT_TRUE(r.mesh.covariance(v).isApprox(sigma * sigma * Mat3::Identity(), 1e-12)) << name << " vertex " << v;
  }
}

TEST(Primitives, TheCubeIsTheSampleCube) {
  const Modelled r = add_primitive(CovarianceMesh{}, Primitive::cube, Vec3::Zero(), 2);
  const CovarianceMesh sample = make_sample("cube");
  ASSERT_EQ(r.mesh.n_vertices(), sample.n_vertices());
  for (size_t v = 0; v < sample.n_vertices(); ++v) {
    EXPECT_TRUE(r.mesh.mean(v).isApprox(sample.mean(v), 1e-15));
    EXPECT_TRUE(r.mesh.covariance(v).isApprox(sample.covariance(v), 1e-12));
  }
}

TEST(Primitives, AppendedAsANewPart) {
  const CovarianceMesh cube = make_sample("cube");
  const Modelled r = add_primitive(cube, Primitive::torus, Vec3(5, 0, 0), 1);
  EXPECT_EQ(r.mesh.n_vertices(), 56u);
  EXPECT_EQ(r.mesh.n_faces(), 54u);
  EXPECT_EQ(r.selection.front(), 8);
  EXPECT_EQ(r.selection.back(), 55);
  for (size_t v = 0; v < 8; ++v) {
    EXPECT_EQ(r.mesh.mean(v), cube.mean(v));
    EXPECT_EQ(r.mesh.covariance(v), cube.covariance(v));
  }
  EXPECT_EQ(arrays_of(r.mesh).faces[0], arrays_of(cube).faces[0]);
  EXPECT_EQ(boundary_edges_of_oriented(r.mesh), 0);
}

// With nothing selected the Add menu's primitive lands beside the mesh, clear of its bounding box and
// of a size near the mesh's, never hidden inside its surface; with a selection, at its centre.
TEST(Primitives, PlacedBesideTheMeshWhenNothingIsSelected) {
  const CovarianceMesh sphere = make_sample("sphere", 96);
  Vec3 lo = sphere.mean(0), hi = lo;
  for (size_t v = 0; v < sphere.n_vertices(); ++v) lo = lo.cwiseMin(sphere.mean(v)), hi = hi.cwiseMax(sphere.mean(v));
  const double extent = (hi - lo).maxCoeff();
  const PrimitivePlacement beside = primitive_placement(sphere, {});
  EXPECT_DOUBLE_EQ(beside.size, 0.5 * extent);
  const Modelled added = add_primitive(sphere, Primitive::cube, beside.center, beside.size);
  for (const int v : added.selection) {
    EXPECT_GT(added.mesh.mean(size_t(v)).x(), hi.x() + 0.1 * extent) << "vertex " << v << " clear of the mesh";
    EXPECT_GT(added.mesh.mean(size_t(v)).y(), lo.y() - 1e-12);
    EXPECT_LT(added.mesh.mean(size_t(v)).y(), hi.y() + 1e-12);
  }
  const PrimitivePlacement at_selection = primitive_placement(sphere, {0, 1});
  EXPECT_TRUE(at_selection.center.isApprox(0.5 * (sphere.mean(0) + sphere.mean(1)), 1e-15));
  EXPECT_DOUBLE_EQ(at_selection.size, 0.25 * (hi - lo).norm());
  const PrimitivePlacement empty = primitive_placement(CovarianceMesh{}, {});
  EXPECT_EQ(empty.center, Vec3::Zero());
  EXPECT_EQ(empty.size, 2.0);
}

TEST(Primitives, NamesAndRefusals) {
  const auto names = primitive_names();
  ASSERT_EQ(names.size(), 6u);
  for (const auto& name : names) EXPECT_EQ(primitive_names()[size_t(*primitive_named(name))], name);
  EXPECT_FALSE(primitive_named("teapot"));
  EXPECT_EQ(error_of([] { add_primitive(CovarianceMesh{}, Primitive::cube, Vec3::Zero(), 0); }),
            "the size must be positive and finite (got 0)");
  EXPECT_EQ(error_of([] { add_primitive(CovarianceMesh{}, Primitive::cube, Vec3::Zero(), -2); }),
            "the size must be positive and finite (got -2)");
  EXPECT_EQ(error_of([] { add_primitive(CovarianceMesh{}, Primitive::sphere, Vec3(0, NAN, 0), 1); }),
            "the centre must be finite");
}

}  // namespace
}  // namespace gps
