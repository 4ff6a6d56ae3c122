// Patch plans grow with the square of the valence: past their bound they are refused at once with a
// message naming the vertex or face, instead of running for minutes into gigabytes. (That the topology
// steps are linear in the valence and the face size is measured by gpsurf_bench_topology.)
#include <gtest/gtest.h>

#include "core/support/error.h"
#include "core/modelling/shapes.h"
#include "core/plans/plan_builder.h"

namespace gps {
namespace {

CovarianceMesh mesh_of(const Shape& shape) {
  return make_covariance_mesh(shape.points, std::vector<Mat3>(shape.points.size(), Mat3::Identity()), shape.faces);
}

TEST(TopologyComplexity, PlansRefuseValencesBeyondTheirBoundAtOnce) {
  for (const auto& [shape, what] :
       {std::pair{cone_shape(100000, 1.0, 0.1, 0.0, false), std::string("vertex 0 has more than 256 faces")},
        std::pair{polygon_shape(300000, 1.0), std::string("face 0 has 300000 sides")}}) {
    try {
      build_plans(mesh_of(shape).topology(), 2);
      ADD_FAILURE() << "no error for " << what;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(build_plans(mesh_of(cone_shape(64, 1.0, 0.1, 0.0, false)).topology(), 2));
}

}  // namespace
}  // namespace gps
