#include "core/reference/loop_connectivity.h"

#include <gtest/gtest.h>

#include "core/reference/loop.h"
#include "core/modelling/samples.h"
#include "tests/support/connectivity_equal.h"

namespace gps {
namespace {

using test::expect_equal;

// Every triangle sample (closed, open, high valence), two steps deep, and a mesh large enough for
// the parallel loops: the refined connectivity is connectivity_of's exactly.
TEST(LoopConnectivity, EqualsConnectivityOfTheRefinedTopology) {
  int meshes = 0;
  for (const std::string& name : sample_names()) {
    PolygonTopology t = make_sample(name, 0).topology();
    bool triangles = true;
    for (int f = 0; f < t.n_faces(); ++f) triangles = triangles && t.face_size(f) == 3;
    if (!triangles) continue;
    SCOPED_TRACE(name);
    ++meshes;
    MeshConnectivity c = connectivity_of(t);
    for (int level = 0; level < 2; ++level) {
      MeshConnectivity refined = loop_connectivity(t, c);
      t = loop_topology(t, c);
      expect_equal(refined, connectivity_of(t));
      c = std::move(refined);
    }
  }
  EXPECT_GE(meshes, 4);
  const PolygonTopology t = make_sample("icosphere", 3 * kParallelFaces).topology();
  const MeshConnectivity c = connectivity_of(t);
  expect_equal(loop_connectivity(t, c), connectivity_of(loop_topology(t, c)));
}

// Two triangles on the same three vertices, a closed mesh: each pair of edge points is an inner
// edge of both faces, two refined edges on the same two vertices.
TEST(LoopConnectivity, TwoFacesOnTheSameVertices) {
  PolygonTopology t;
  t.n_vertices = 3;
  t.verts = {0, 1, 2, 0, 2, 1};
  t.offsets = {0, 3, 6};
  const MeshConnectivity c = connectivity_of(t);
  expect_equal(loop_connectivity(t, c), connectivity_of(loop_topology(t, c)));
}

}  // namespace
}  // namespace gps
