// A covariance mesh's connectivity: built once when the mesh is made, which refuses what is not a
// manifold surface naming the element, and the corner links that walks across faces use.
#include "core/mesh/mesh_connectivity.h"

#include <gtest/gtest.h>

#include "core/mesh/covariance_mesh.h"
#include "core/modelling/samples.h"
#include "core/support/error.h"
#include "tests/support/connectivity_equal.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using test::error_of;

CovarianceMesh mesh_of(int n_vertices, const std::vector<std::vector<int>>& faces) {
  std::vector<Vec3> means;
  for (int i = 0; i < n_vertices; ++i) means.emplace_back(double(i), double(i * i % 7), double(i % 3));
  return make_covariance_mesh(means, {}, faces, "m");
}

// Every sample: the mesh holds connectivity_of's arrays, and each corner's twin runs its edge the
// other way in the face across it, exactly where the edge is not a boundary.
TEST(MeshConnectivity, AMeshHoldsItsConnectivityAndCornersLinkAcrossEdges) {
  for (const std::string& name : sample_names()) {
    SCOPED_TRACE(name);
    const CovarianceMesh m = make_sample(name, 0);
    const PolygonTopology& t = m.topology();
    const MeshConnectivity& c = m.connectivity();
    test::expect_equal(c, connectivity_of(t));
    const CornerLinks links = corner_links(t, c);
    for (int f = 0; f < t.n_faces(); ++f)
      for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) {
        ASSERT_EQ(links.faces[size_t(k)], f);
        EXPECT_EQ(links.previous(t, links.next(t, k)), k);
        const int twin = links.twins[size_t(k)];
        EXPECT_EQ(twin < 0, c.is_boundary_edge(c.face_edges[size_t(k)]));
        if (twin < 0) continue;
        EXPECT_EQ(links.twins[size_t(twin)], k);
        EXPECT_NE(links.faces[size_t(twin)], f);
        EXPECT_EQ(t.verts[size_t(twin)], t.verts[size_t(links.next(t, k))]);
        EXPECT_EQ(t.verts[size_t(links.next(t, twin))], t.verts[size_t(k)]);
      }
  }
}

// Each way a set of faces fails to be a manifold surface is refused naming the element that breaks it.
TEST(MeshConnectivity, WhatIsNotAManifoldIsRefusedNamingTheElement) {
  // Three triangles on the edge 0–1: the third is named.
  EXPECT_EQ(error_of([] {
              mesh_of(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
            }),
            "m: face 2 makes the mesh non-manifold (an edge with more than two faces or a flipped face)");
  // Two triangles running their shared edge the same way: the later one is flipped.
  EXPECT_EQ(error_of([] {
              mesh_of(4, {{0, 1, 2}, {0, 1, 3}});
            }),
            "m: face 1 makes the mesh non-manifold (an edge with more than two faces or a flipped face)");
  // A bow tie: two triangles meeting at vertex 0 alone.
  EXPECT_EQ(error_of([] {
              mesh_of(5, {{0, 1, 2}, {0, 3, 4}});
            }),
            "m: vertex 0 is non-manifold (its faces do not form one fan)");
  // Two closed cones whose apexes are one vertex: no boundary at all, two fans at vertex 0.
  const std::vector<std::vector<int>> cones = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2},
                                               {0, 4, 5}, {0, 5, 6}, {0, 6, 4}, {4, 6, 5}};
  EXPECT_EQ(error_of([&] { mesh_of(7, cones); }), "m: vertex 0 is non-manifold (its faces do not form one fan)");
  // A closed cone and an open fan at the same vertex.
  EXPECT_EQ(error_of([] {
              mesh_of(7, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}, {0, 4, 5}});
            }),
            "m: vertex 0 is non-manifold (its faces do not form one fan)");
  // Two faces sharing all their edges.
  EXPECT_EQ(error_of([] {
              mesh_of(3, {{0, 1, 2}, {0, 2, 1}});
            }),
            "m: face 0 and face 1 share all their edges (a closed pillow of two faces, which no subdivision can "
            "refine)");
  // What is a manifold passes: a square of two triangles, and one long face.
  EXPECT_NO_THROW(mesh_of(4, {{0, 1, 2}, {0, 2, 3}}));
  std::vector<int> long_face;
  for (int i = 0; i < 1000; ++i) long_face.push_back(i);
  EXPECT_EQ(mesh_of(1000, {long_face}).n_edges(), 1000u);
}

}  // namespace
}  // namespace gps
