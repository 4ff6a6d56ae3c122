#include "core/reference/catmull_clark_connectivity.h"

#include <gtest/gtest.h>

#include "core/reference/catmull_clark.h"
#include "core/modelling/samples.h"
#include "tests/support/connectivity_equal.h"

namespace gps {
namespace {

using test::expect_equal;

// Every sample (quads, triangles, n-gons, boundaries, corners, high valence), two steps deep, and a
// mesh large enough for the parallel loops: the refined connectivity is connectivity_of's exactly.
TEST(CatmullClarkConnectivity, EqualsConnectivityOfTheRefinedTopology) {
  for (const std::string& name : sample_names()) {
    SCOPED_TRACE(name);
    PolygonTopology t = make_sample(name, 0).topology();
    MeshConnectivity c = connectivity_of(t);
    for (int level = 0; level < 2; ++level) {
      MeshConnectivity refined = catmull_clark_connectivity(t, c);
      t = catmull_clark_topology(t, c);
      expect_equal(refined, connectivity_of(t));
      c = std::move(refined);
    }
  }
  const PolygonTopology t = make_sample("grid", 3 * kParallelFaces).topology();
  const MeshConnectivity c = connectivity_of(t);
  expect_equal(catmull_clark_connectivity(t, c), connectivity_of(catmull_clark_topology(t, c)));
}

TEST(CatmullClarkConnectivity, IsolatedVerticesKeepNoEdges) {
  PolygonTopology t;
  t.n_vertices = 6;  // vertices 2 and 5 belong to no face
  t.verts = {0, 1, 3, 4};
  t.offsets = {0, 4};
  const MeshConnectivity c = connectivity_of(t);
  expect_equal(catmull_clark_connectivity(t, c), connectivity_of(catmull_clark_topology(t, c)));
}

}  // namespace
}  // namespace gps
