// Patch plans grow with the square of the valence: past their bound they are refused at once with a
// message naming the vertex or face, instead of running for minutes into gigabytes. (That the topology
// steps are linear in the valence and the face size is measured by gpsurf_bench_topology.)
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/support/error.h"
#include "core/modelling/shapes.h"
#include "core/plans/loop_plan_builder.h"
#include "core/plans/plan_builder.h"
#include "core/plans/surface_replanner.h"

namespace gps {
namespace {

CovarianceMesh mesh_of(const Shape& shape) {
  return make_covariance_mesh(shape.points, std::vector<Mat3>(shape.points.size(), Mat3::Identity()), shape.faces);
}

TEST(TopologyComplexity, PlansRefuseValencesBeyondTheirBoundAtOnce) {
  for (const auto& [shape, what] :
       {std::pair{cone_shape(100000, 1.0, 0.1, 0.0, false), std::string("vertex 0 has more than 256 faces")},
        std::pair{polygon_shape(300000, 1.0), std::string("face 0 has 300000 sides")}}) {
    const CovarianceMesh mesh = mesh_of(shape);
    // Counted from the faces, and from the faces at each vertex that a mesh's connectivity holds.
    const std::vector<std::function<void()>> builds = {
        [&] { build_plans(mesh.topology(), 2); }, [&] { SurfaceReplanner(mesh, PlanOptions{}); },
        [&] { SurfaceReplanner(mesh_of(cone_shape(64, 1.0, 0.1, 0.0, false)), PlanOptions{}).set_topology(mesh, {}); }};
    for (const auto& build : builds) {
      try {
        build();
        ADD_FAILURE() << "no error for " << what;
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_NO_THROW(build_plans(mesh_of(cone_shape(64, 1.0, 0.1, 0.0, false)).topology(), 2));
  EXPECT_NO_THROW(SurfaceReplanner(mesh_of(cone_shape(64, 1.0, 0.1, 0.0, false)), PlanOptions{}));
}

// A fan of triangles about vertex 0, a disc.
CovarianceMesh triangle_fan(int n) {
  std::vector<Vec3> points{Vec3::Zero()};
  std::vector<std::vector<int>> faces;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    points.emplace_back(std::cos(a), std::sin(a), 0.0);
    faces.push_back({0, 1 + i, 1 + (i + 1) % n});
  }
  return make_covariance_mesh(points, std::vector<Mat3>(points.size(), Mat3::Identity()), faces);
}

TEST(TopologyComplexity, LoopPlansRefuseAVertexOfTooManyFaces) {
  const CovarianceMesh fan = triangle_fan(kMaxLoopValence + 6);
  const std::string what = "vertex 0 has " + std::to_string(kMaxLoopValence + 6) + " faces; Loop patches take at most";
  PlanOptions loop;
  loop.scheme = Scheme::loop;
  const std::vector<std::function<void()>> builds = {
      [&] { build_loop_plans(fan.topology(), LoopBeta::loop); },
      [&] { build_loop_plans(fan.topology(), LoopBeta::loop, {}, &fan.connectivity()); },
      [&] { SurfaceReplanner(fan, loop); },
      [&] { SurfaceReplanner(triangle_fan(kMaxLoopValence), loop).set_topology(fan, {}); }};
  for (const auto& build : builds) {
    try {
      build();
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(SurfaceReplanner(triangle_fan(kMaxLoopValence), loop));
  // Left to choose, the plans take Catmull-Clark's past the bound, counted either way.
  EXPECT_EQ(scheme_for(fan.topology(), PlanOptions{}), Scheme::catmull_clark);
  EXPECT_EQ(scheme_for(fan.topology(), PlanOptions{}, &fan.connectivity()), Scheme::catmull_clark);
  EXPECT_EQ(SurfaceReplanner(fan, PlanOptions{}).scheme(), Scheme::catmull_clark);
  const CovarianceMesh bound = triangle_fan(kMaxLoopValence);
  EXPECT_EQ(scheme_for(bound.topology(), PlanOptions{}, &bound.connectivity()), Scheme::loop);
  EXPECT_EQ(SurfaceReplanner(bound, PlanOptions{}).scheme(), Scheme::loop);
}

}  // namespace
}  // namespace gps
