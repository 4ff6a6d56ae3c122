#include "core/modelling/mesh_queries.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "core/modelling/mesh_arrays.h"
#include "core/modelling/primitives.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using test::error_of;
using V = std::vector<int>;

V range(int begin, int end, int step = 1) {
  V v;
  for (int k = begin; k < end; k += step) v.push_back(k);
  return v;
}

TEST(MeshQueries, EdgeLoopOnTheCubeIsTheFaceOnTheLeftOfTheEdge) {
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(edge_loop(cube, 0, 1), (V{0, 1, 4, 5}));  // face {0, 1, 5, 4}
  EXPECT_EQ(edge_loop(cube, 1, 0), (V{0, 1, 2, 3}));  // face {0, 3, 2, 1}
}

TEST(MeshQueries, EdgeLoopOnAGridIsARowOrAColumn) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);  // vertex j·5 + i
  EXPECT_EQ(edge_loop(grid, 11, 12), range(10, 15));
  EXPECT_EQ(edge_loop(grid, 13, 12), range(10, 15));
  EXPECT_EQ(edge_loop(grid, 7, 12), range(2, 25, 5));
  // A boundary edge gives the whole boundary loop: 16 vertices around the 4 × 4 grid.
  const V boundary = edge_loop(grid, 0, 1);
  EXPECT_EQ(boundary.size(), 16u);
  EXPECT_EQ(std::count(boundary.begin(), boundary.end(), 12), 0);
}

TEST(MeshQueries, EdgeLoopClosesAroundTheTorusAndStopsAtPoles) {
  const CovarianceMesh torus = make_sample("torus");  // 24 × 12, vertex i·12 + j
  EXPECT_EQ(edge_loop(torus, 0, 1), range(0, 12));
  EXPECT_EQ(edge_loop(torus, 12, 0), range(0, 288, 12));
  const CovarianceMesh cylinder = make_sample("cylinder");  // the middle ring has valence 4
  EXPECT_EQ(edge_loop(cylinder, 9, 8), range(8, 16));
  // Up the side: ring 0 and ring 2 are on the caps' corners (valence 3), where the loop stops.
  EXPECT_EQ(edge_loop(cylinder, 8, 16), (V{0, 8, 16}));
}

// The loop's edges are the ones walked: on a grid's row only the row's edges, though the rows'
// vertices are joined by nothing else; around the torus the ring closes; on the cube the face's rim.
TEST(MeshQueries, EdgeLoopEdgesAreTheEdgesWalked) {
  using E = std::vector<std::array<int, 2>>;
  const CovarianceMesh grid = test::grid_mesh(4, 4);  // vertex j·5 + i
  EXPECT_EQ(edge_loop_edges(grid, 13, 12), (E{{10, 11}, {11, 12}, {12, 13}, {13, 14}}));
  EXPECT_EQ(edge_loop_edges(grid, 7, 12), (E{{2, 7}, {7, 12}, {12, 17}, {17, 22}}));
  EXPECT_EQ(edge_loop_edges(grid, 0, 1).size(), 16u);  // the boundary
  const CovarianceMesh torus = make_sample("torus");   // 24 × 12, vertex i·12 + j
  E ring;
  for (int j = 0; j < 12; ++j) ring.push_back({std::min(j, (j + 1) % 12), std::max(j, (j + 1) % 12)});
  std::sort(ring.begin(), ring.end());
  EXPECT_EQ(edge_loop_edges(torus, 0, 1), ring);
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(edge_loop_edges(cube, 0, 1), (E{{0, 1}, {0, 4}, {1, 5}, {4, 5}}));  // face {0, 1, 5, 4}
  const CovarianceMesh cylinder = make_sample("cylinder");
  EXPECT_EQ(edge_loop_edges(cylinder, 8, 16), (E{{0, 8}, {8, 16}}));  // stops at the caps' corners
  EXPECT_EQ(edge_loop_edges(cylinder, 1, 0).size(), 8u);              // a cap's rim
  EXPECT_NE(error_of([&] { edge_loop_edges(cube, 0, 6); }).find("edge 0–6 is not in the mesh"), std::string::npos);
}

// An edge of a cap's rim, whose ends have valence 3, gives the whole rim (the octagon), from either
// direction, not the corners of the side quad next to it.
TEST(MeshQueries, EdgeLoopOnACapRimSelectsTheRim) {
  const CovarianceMesh cylinder = make_sample("cylinder");
  EXPECT_EQ(edge_loop(cylinder, 0, 1), range(0, 8));
  EXPECT_EQ(edge_loop(cylinder, 1, 0), range(0, 8));
  EXPECT_EQ(edge_loop(cylinder, 17, 16), range(16, 24));
}

TEST(MeshQueries, EdgeLoopRefusesWhatIsNotAnEdge) {
  const CovarianceMesh cube = make_sample("cube");
  EXPECT_EQ(error_of([&] { edge_loop(cube, 0, 6); }), "edge 0–6 is not in the mesh");
  EXPECT_EQ(error_of([&] { edge_loop(cube, 0, 8); }), "vertex 8 is not in the mesh (8 vertices)");
}

TEST(MeshQueries, LinkedVerticesStayInTheirPart) {
  const Modelled two = add_primitive(make_sample("cube"), Primitive::cube, Vec3(5, 0, 0), 1);
  EXPECT_EQ(linked_vertices(two.mesh, {2}), range(0, 8));
  EXPECT_EQ(linked_vertices(two.mesh, {9}), range(8, 16));
  EXPECT_EQ(linked_vertices(two.mesh, {0, 15}), range(0, 16));
  EXPECT_TRUE(linked_vertices(two.mesh, {}).empty());
}

TEST(MeshQueries, GrowAndShrinkByFaces) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  const V block = {6, 7, 8, 11, 12, 13, 16, 17, 18};
  EXPECT_EQ(grow_selection(grid, {12}), block);
  EXPECT_EQ(shrink_selection(grid, block), V{12});
  EXPECT_TRUE(shrink_selection(grid, {12}).empty());
  EXPECT_EQ(grow_selection(grid, {0}), (V{0, 1, 5, 6}));
  EXPECT_EQ(grow_selection(grid, block).size(), 25u);
  EXPECT_EQ(shrink_selection(grid, range(0, 25)), range(0, 25));  // nothing unselected around
}

TEST(MeshQueries, FacesAndEdgesWithin) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  const V block = {6, 7, 8, 11, 12, 13, 16, 17, 18};
  EXPECT_EQ(faces_within(grid, block), (V{5, 6, 9, 10}));
  const auto edges = edges_within(grid, block);
  EXPECT_EQ(edges.size(), 12u);
  EXPECT_EQ(edges.front(), (std::array<int, 2>{6, 7}));
  for (const auto& e : edges) EXPECT_LT(e[0], e[1]);
  EXPECT_TRUE(faces_within(grid, {6, 7, 11}).empty());
  EXPECT_EQ(edges_within(grid, {6, 7, 11}).size(), 2u);
}

// On meshes with vertices of many valences, every edge with both ends among a scattered set of
// vertices, each once, ends ascending, the edges sorted.
TEST(MeshQueries, EdgesWithinAreEveryEdgeBetweenTheVerticesInOrder) {
  for (const char* name : {"pawn", "icosphere", "grid"}) {
    const CovarianceMesh mesh = make_sample(name);
    V chosen;
    for (int v = 0; v < int(mesh.n_vertices()); ++v)
      if ((v * 7919) % 5 != 0) chosen.push_back(v);
    const std::set<int> in(chosen.begin(), chosen.end());
    std::vector<std::array<int, 2>> expected;
    for (size_t e = 0; e < mesh.n_edges(); ++e)
      if (in.count(mesh.edge(e)[0]) && in.count(mesh.edge(e)[1])) expected.push_back(mesh.edge(e));
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(edges_within(mesh, chosen), expected) << name;
  }
}

TEST(MeshQueries, BoundaryLoopsRunAlongTheFacesEdges) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  const auto loops = boundary_loops(grid);
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].size(), 16u);
  EXPECT_EQ(loops[0].front(), 0);
  const DirectedEdges edges = directed_edges(arrays_of(grid));
  for (size_t k = 0; k < loops[0].size(); ++k) {
    const int a = loops[0][k], b = loops[0][(k + 1) % loops[0].size()];
    EXPECT_TRUE(edges.count(directed_key(a, b))) << a << "→" << b;
    EXPECT_TRUE(is_boundary_edge(edges, a, b)) << a << "–" << b;
  }
  EXPECT_TRUE(boundary_loops(make_sample("cube")).empty());
  // The open cone: one loop, its base ring.
  const auto cone = boundary_loops(test::cone_mesh());
  ASSERT_EQ(cone.size(), 1u);
  EXPECT_EQ(std::set<int>(cone[0].begin(), cone[0].end()), std::set<int>({1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST(MeshQueries, LargeMeshesAnswerInOnePass) {
  const CovarianceMesh grid = make_sample("grid", 102400);  // 320 × 320 quads
  EXPECT_EQ(boundary_loops(grid)[0].size(), 4u * 320u);
  EXPECT_EQ(edge_loop(grid, 321 * 160, 321 * 160 + 1).size(), 321u);
  EXPECT_EQ(linked_vertices(grid, {0}).size(), 321u * 321u);
  const V all = linked_vertices(grid, {0});
  EXPECT_EQ(faces_within(grid, all).size(), 320u * 320u);
  EXPECT_EQ(shrink_selection(grid, grow_selection(grid, {321 * 160 + 160})), V{321 * 160 + 160});
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

TEST(MeshQueries, ChainOfEdgesOrdersAPathOrALoop) {
  EXPECT_EQ(chain_of_edges({{5, 9}, {2, 5}, {9, 4}}), (std::vector<int>{2, 5, 9, 4}));  // from the lower end
  EXPECT_EQ(chain_of_edges({{3, 1}}), (std::vector<int>{1, 3}));
  EXPECT_EQ(chain_of_edges({{7, 3}, {1, 7}, {3, 1}}), (std::vector<int>{1, 7, 3, 1}));  // closed: 1 again
  const auto refusal = [](const std::vector<std::array<int, 2>>& edges) {
    return test::error_of([&] { chain_of_edges(edges); });
  };
  EXPECT_EQ(refusal({{0, 1}, {1, 2}, {1, 3}}), "the edges branch at vertex 1: select one chain");
  EXPECT_EQ(refusal({{0, 1}, {2, 3}}), "the selected edges are not one connected chain");
  EXPECT_EQ(refusal({{0, 1}, {1, 2}, {2, 0}, {4, 5}}), "the selected edges are not one connected chain");
  EXPECT_NE(refusal({}), "");
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

// On a 4 × 4 grid (vertex j·5 + i) from corner 0 to vertex 12 (i = 2, j = 2): a path of four edges,
// each a step to a neighbour, as short as the grid allows; on the cube from a corner to the opposite
// one, three edges; a vertex to itself is itself.
TEST(MeshQueries, ShortestPathFollowsTheEdges) {
  const CovarianceMesh grid = test::grid_mesh(4, 4);
  const std::vector<int> path = shortest_path(grid, 0, 12);
  ASSERT_EQ(path.size(), 5u);
  EXPECT_EQ(path.front(), 0);
  EXPECT_EQ(path.back(), 12);
  const auto edges = edges_within(grid, path);
  for (size_t k = 0; k + 1 < path.size(); ++k) {
    const std::array<int, 2> e{std::min(path[k], path[k + 1]), std::max(path[k], path[k + 1])};
    EXPECT_NE(std::find(edges.begin(), edges.end(), e), edges.end()) << path[k] << "-" << path[k + 1];
  }
  const CovarianceMesh cube = make_sample("cube");
  int opposite = 0;
  for (size_t v = 0; v < cube.n_vertices(); ++v)
    if ((cube.mean(v) + cube.mean(0)).norm() < 1e-12) opposite = int(v);
  EXPECT_EQ(shortest_path(cube, 0, opposite).size(), 4u);
  EXPECT_EQ(shortest_path(cube, 3, 3), (std::vector<int>{3}));
  EXPECT_EQ(test::error_of([&] { shortest_path(cube, 0, 8); }), "vertex 8 is not in the mesh");
}

// On a 4 × 4 grid of faces (face j·4 + i) from the corner face 0 to the opposite corner face 15: seven
// faces, each sharing an edge with the next; hidden faces are gone round, or the path refused where
// they cut the way; on the cube a face to the opposite one crosses one side.
TEST(MeshQueries, ShortestFacePathCrossesNeighbouringFaces) {
  const CovarianceMesh grid = test::grid_mesh(4, 4, 0.3, true);
  const auto shares_an_edge = [&](int f, int g) {  // two quads sharing an edge have two corners alike
    int alike = 0;
    for (const int v : grid.face(size_t(f)))
      for (const int w : grid.face(size_t(g))) alike += v == w;
    return alike == 2;
  };
  const V path = shortest_face_path(grid, 0, 15);
  ASSERT_EQ(path.size(), 7u);
  EXPECT_EQ(path.front(), 0);
  EXPECT_EQ(path.back(), 15);
  for (size_t k = 0; k + 1 < path.size(); ++k) EXPECT_TRUE(shares_an_edge(path[k], path[k + 1])) << k;
  // A wall of hidden faces along x = 1 but for the top row: the path goes round through face 13.
  std::vector<char> hidden(16, 0);
  for (const int f : {1, 5, 9}) hidden[size_t(f)] = 1;
  const V round = shortest_face_path(grid, 0, 3, &hidden);
  EXPECT_EQ(round.size(), 10u);
  EXPECT_NE(std::find(round.begin(), round.end(), 13), round.end());
  for (const int f : round) EXPECT_FALSE(hidden[size_t(f)]) << f;
  hidden[13] = 1;
  EXPECT_EQ(error_of([&] { shortest_face_path(grid, 0, 3, &hidden); }), "no edges join face 0 to face 3");
  EXPECT_EQ(shortest_face_path(grid, 6, 6), V{6});
  EXPECT_EQ(error_of([&] { shortest_face_path(grid, 0, 16); }), "face 16 is not in the mesh");
  const CovarianceMesh cube = test::cube_mesh();
  EXPECT_EQ(shortest_face_path(cube, 0, 1).size(), 3u);  // bottom to top
}

// Alt+click in face mode: the row of quads across the clicked edge, both ways, stopping at the
// boundary; round the cube it closes after four faces; on a cone's side the triangles end it at once.
TEST(MeshQueries, FaceLoopCrossesTheQuadsBesideTheEdge) {
  const CovarianceMesh grid = test::grid_mesh(3, 3);
  EXPECT_EQ(face_loop(grid, 1, 5), (V{0, 1, 2}));  // the edge x = 1 of the first row
  EXPECT_EQ(face_loop(grid, 4, 5), (V{0, 3, 6}));  // the edge y = 1 of the first column
  const CovarianceMesh cube = test::cube_mesh();
  EXPECT_EQ(face_loop(cube, 0, 1), (V{0, 1, 2, 3}));  // the edge along x: round through bottom, −y, top, +y
  EXPECT_TRUE(face_loop(test::cone_mesh(), 0, 1).empty());
  EXPECT_EQ(error_of([&] { face_loop(grid, 0, 5); }), "edge 0–5 is not in the mesh");
}

}  // namespace
}  // namespace gps
