// Repair of polygon soups (core/io/mesh_repair.h): one soup per defect class, built here, with the
// counts of the report, and the result a manifold, consistently oriented mesh (every interior edge
// once each way), closed where it should be.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "core/io/mesh_repair.h"
#include "core/support/error.h"

namespace gps {
namespace {

PolygonSoup soup_of(const std::vector<Vec3>& positions, const std::vector<std::vector<int>>& faces) {
  PolygonSoup s;
  s.positions = positions;
  for (const auto& face : faces) {
    s.faces.verts.insert(s.faces.verts.end(), face.begin(), face.end());
    s.faces.offsets.push_back(int(s.faces.verts.size()));
  }
  return s;
}

std::vector<std::vector<int>> faces_of(const PolygonSoup& s) {
  std::vector<std::vector<int>> out;
  for (int f = 0; f < s.faces.n_faces(); ++f)
    out.emplace_back(s.faces.verts.begin() + s.faces.offsets[size_t(f)],
                     s.faces.verts.begin() + s.faces.offsets[size_t(f) + 1]);
  return out;
}

// Boundary edges of a repaired soup, after checking that it builds (manifold) and that each directed
// edge is used once, an interior edge once each way.
int boundary_edges(const PolygonSoup& s) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& face : faces_of(s))
    for (size_t k = 0; k < face.size(); ++k) ++directed[{face[k], face[(k + 1) % face.size()]}];
  int boundary = 0;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    boundary += directed.count({edge.second, edge.first}) == 0;
  }
  PolygonSoup copy = s;
  EXPECT_NO_THROW(mesh_of_soup(std::move(copy), "repaired"));
  return boundary;
}

Vec3 corner(int i) { return Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); }
const std::vector<std::vector<int>> kCubeFaces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                  {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

std::vector<Vec3> cube_positions() {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.push_back(corner(i));
  return p;
}

// A tetrahedron on vertices base .. base + 3, oriented outwards, placed at `offset`.
void add_tetrahedron(std::vector<Vec3>& p, std::vector<std::vector<int>>& faces, const Vec3& offset, int apex = -1) {
  const int base = int(p.size());
  const int a = apex >= 0 ? apex : base;
  if (apex < 0) p.push_back(offset);
  const int b = int(p.size()), c = b + 1, d = b + 2;
  p.push_back(offset + Vec3(1, 0, 0));
  p.push_back(offset + Vec3(0, 1, 0));
  p.push_back(offset + Vec3(0, 0, 1));
  if (apex >= 0) {  // mirrored through the shared apex: the same orientation rule holds
    p[size_t(b)] = p[size_t(a)] - Vec3(1, 0, 0);
    p[size_t(c)] = p[size_t(a)] - Vec3(0, 1, 0);
    p[size_t(d)] = p[size_t(a)] - Vec3(0, 0, 1);
  }
  faces.insert(faces.end(), {{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}});
}

TEST(MeshRepair, CleanMeshIsLeftAsItIs) {
  PolygonSoup s = soup_of(cube_positions(), kCubeFaces);
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_FALSE(r.changed());
  EXPECT_TRUE(r.lines().empty());
  EXPECT_EQ(faces_of(s), kCubeFaces);
  EXPECT_EQ(r.parts, 1);
  EXPECT_EQ(r.boundary_loops, 0);
}

TEST(MeshRepair, UnweldedCubeIsWeldedClosed) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> faces;
  for (const auto& face : kCubeFaces) {  // each face its own four vertices
    std::vector<int> own;
    for (const int v : face) {
      own.push_back(int(p.size()));
      p.push_back(corner(v) + Vec3(1e-9, 0, 0) * double(own.size()));  // within the tolerance
    }
    faces.push_back(own);
  }
  PolygonSoup s = soup_of(p, faces);
  s.covariances.assign(24, Mat3::Identity());
  for (int v = 0; v < 24; ++v) s.covariances[size_t(v)] *= double(v + 1);
  EXPECT_EQ(diagnose_polygon_soup(s).count(Defect::coincident_vertices), 24);
  EXPECT_EQ(s.positions.size(), 24u) << "diagnosis leaves the soup as it is";
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::coincident_vertices), 24);
  EXPECT_EQ(r.welded_groups, 8);
  ASSERT_EQ(r.lines().size(), 1u);
  EXPECT_EQ(r.lines()[0], "welded 24 coincident vertices into 8");
  EXPECT_EQ(s.positions.size(), 8u);
  EXPECT_EQ(s.faces.n_faces(), 6);
  EXPECT_EQ(boundary_edges(s), 0);
  EXPECT_EQ(r.boundary_loops, 0);
  EXPECT_EQ(r.parts, 1);
  // The welded vertex keeps the Gaussian of its group's lowest index: vertex 0 (file vertex 0).
  ASSERT_EQ(s.covariances.size(), 8u);
  EXPECT_EQ(s.covariances[0](0, 0), 1.0);
  EXPECT_EQ(s.positions[0], corner(0) + Vec3(1e-9, 0, 0));
}

TEST(MeshRepair, ReportsProgressAfterEachStepAndStopsWhenAsked) {
  std::vector<std::vector<int>> faces(kCubeFaces.begin(), kCubeFaces.end());
  faces.push_back(faces[0]);  // a duplicate face for the repair to drop
  const PolygonSoup input = soup_of(cube_positions(), faces);
  PolygonSoup plain = input, watched = input;
  std::vector<double> fractions;
  RepairOptions options;
  options.progress = [&](double f) {
    fractions.push_back(f);
    return true;
  };
  const RepairReport r = repair_polygon_soup(watched, options);
  EXPECT_EQ(r.lines(), repair_polygon_soup(plain).lines());
  EXPECT_EQ(watched.faces.n_faces(), 6);
  ASSERT_EQ(fractions.size(), 8u);  // at the start and after each of the seven steps
  for (size_t k = 0; k < fractions.size(); ++k) EXPECT_DOUBLE_EQ(fractions[k], double(k) / 7) << k;

  int calls = 0;
  options.progress = [&](double) { return ++calls < 3; };
  PolygonSoup stopped = input;
  EXPECT_THROW(repair_polygon_soup(stopped, options), Cancelled);
  EXPECT_EQ(calls, 3);
}

TEST(MeshRepair, WeldToleranceIsSettable) {
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 1e-3, 0), Vec3(-1, 1, 0)};
  const PolygonSoup s = soup_of(p, {{0, 1, 2}, {0, 3, 4}});
  EXPECT_EQ(diagnose_polygon_soup(s).count(Defect::coincident_vertices), 0);
  RepairOptions o;
  o.weld_tolerance = 1e-3;  // 1.4e-3 with the diagonal of 1.41
  EXPECT_EQ(diagnose_polygon_soup(s, o).count(Defect::coincident_vertices), 2);
}

// Pairs of vertices within the tolerance of each other, in random directions and places (so that many
// straddle the sides of the weld's grid cells), each pair far from the others: every pair is welded,
// and no two pairs are.
TEST(MeshRepair, WeldFindsEveryPairWithinTheToleranceWhereverItLies) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 1, 1)};  // the bounding box: the tolerance is 1e-6 √3
  const double tolerance = 1e-6 * std::sqrt(3.0);
  constexpr int n = 2000;
  for (int i = 0; i < n; ++i) {
    const Vec3 at = Vec3(0.5, 0.5, 0.5) + 0.45 * Vec3(unit(random), unit(random), unit(random));
    Vec3 direction(unit(random), unit(random), unit(random));
    p.push_back(at);
    p.push_back(at + 0.99 * tolerance * direction.normalized());
  }
  const RepairReport r = diagnose_polygon_soup(soup_of(p, {{0, 1, 2}}));
  EXPECT_EQ(r.count(Defect::coincident_vertices), 2 * n);
  EXPECT_EQ(r.welded_groups, n);
}

// Crowds of vertices a few tolerances across (some at one position, the others scattered so that
// chains of close pairs join some crowds and not others): the weld's groups are those of every pair
// measured.
TEST(MeshRepair, WeldOfCrowdedVerticesGroupsAsEveryPairMeasured) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 1, 1)};
  const double tolerance = 1e-6 * std::sqrt(3.0);
  for (int crowd = 0; crowd < 12; ++crowd) {
    const Vec3 at = Vec3(0.5, 0.5, 0.5) + 0.4 * Vec3(unit(random), unit(random), unit(random));
    const double spread = (crowd % 4 == 3 ? 40 : crowd % 4 + 1) * tolerance;
    for (int i = 0; i < 150; ++i)
      p.push_back(i % 5 == 0 ? at : at + spread * Vec3(unit(random), unit(random), unit(random)));
  }
  std::vector<int> root(p.size());
  for (size_t v = 0; v < p.size(); ++v) root[v] = int(v);
  const auto find = [&](int v) {
    while (root[size_t(v)] != v) v = root[size_t(v)];
    return v;
  };
  for (size_t a = 0; a < p.size(); ++a)
    for (size_t b = a + 1; b < p.size(); ++b)
      if ((p[a] - p[b]).norm() <= tolerance)
        root[size_t(std::max(find(int(a)), find(int(b))))] = std::min(find(int(a)), find(int(b)));
  std::map<int, int> group_size;
  for (size_t v = 0; v < p.size(); ++v) ++group_size[find(int(v))];
  int welded = 0, groups = 0;
  for (const auto& [group, size] : group_size)
    if (size > 1) welded += size, ++groups;
  ASSERT_GE(groups, 12);
  const RepairReport r = diagnose_polygon_soup(soup_of(p, {{0, 1, 2}}));
  EXPECT_EQ(r.count(Defect::coincident_vertices), welded);
  EXPECT_EQ(r.welded_groups, groups);
}

TEST(MeshRepair, PinchVertexOfTwoTetrahedraIsSplit) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> faces;
  add_tetrahedron(p, faces, Vec3(0, 0, 0));
  add_tetrahedron(p, faces, Vec3(0, 0, 0), 0);  // closed fans touching at vertex 0
  ASSERT_EQ(p.size(), 7u);
  {
    PolygonSoup copy = soup_of(p, faces);
    EXPECT_THROW(mesh_of_soup(std::move(copy), "pinch"), Error);
  }
  PolygonSoup s = soup_of(p, faces);
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::pinch_vertices), 1);
  EXPECT_EQ(r.pinch_copies, 1);
  EXPECT_EQ(r.problems({}, true), std::vector<std::string>{"non-manifold (pinch) vertices: 1 (vertex 0 with 2 fans)"});
  EXPECT_EQ(r.lines(), std::vector<std::string>{"split 1 pinch vertex (1 copy added, one per extra fan)"});
  EXPECT_EQ(s.positions.size(), 8u);
  EXPECT_EQ(s.positions[7], p[0]) << "the copy comes last, at its original's position";
  EXPECT_EQ(s.faces.n_faces(), 8);
  EXPECT_EQ(boundary_edges(s), 0);
  EXPECT_EQ(r.parts, 2);
  EXPECT_EQ(r.boundary_loops, 0);
}

// Two tetrahedra touching at a point that the file holds twice are a pinch only once the copies are
// welded: named so among the defects of the file as read (the repair gives the same mesh back).
TEST(MeshRepair, APinchMadeByTheWeldIsNamedAsSuch) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> faces;
  add_tetrahedron(p, faces, Vec3(0, 0, 0));
  add_tetrahedron(p, faces, Vec3(0, 0, 0), 0);
  p.push_back(p[0]);  // the second tetrahedron's apex as a vertex of its own
  for (size_t f = 4; f < faces.size(); ++f)
    for (int& v : faces[f])
      if (v == 0) v = 7;
  PolygonSoup s = soup_of(p, faces);
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::coincident_vertices), 2);
  EXPECT_EQ(r.count(Defect::pinch_vertices), 1);
  EXPECT_EQ(r.problems({}, true), std::vector<std::string>{"non-manifold (pinch) vertices: 1 (vertex 0 with 2 "
                                                           "fans once coincident vertices are welded)"});
  EXPECT_EQ(s.positions.size(), 8u);
  EXPECT_EQ(r.parts, 2);
}

TEST(MeshRepair, DanglingTrianglesAreSeparated) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> faces;
  add_tetrahedron(p, faces, Vec3(0, 0, 0));
  // Two triangles hanging from the tetrahedron's vertex 1 by that vertex alone, and from vertex 2.
  p.insert(p.end(), {Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(0, 2, 0), Vec3(1, 2, 0)});
  faces.insert(faces.end(), {{1, 4, 5}, {2, 6, 7}});
  PolygonSoup s = soup_of(p, faces);
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::pinch_vertices), 2);
  EXPECT_EQ(r.pinch_copies, 2);
  EXPECT_EQ(s.positions.size(), 10u);
  EXPECT_EQ(boundary_edges(s), 6);
  EXPECT_EQ(r.parts, 3);
  EXPECT_EQ(r.boundary_loops, 2);
}

TEST(MeshRepair, FinFaceGetsItsOwnEdge) {
  // Three quads on the edge 0–1: A runs it 0→1, C too, B the other way. A and B are kept, C is separated
  // although it comes before B.
  const std::vector<Vec3> p = {Vec3(0, 0, 0),  Vec3(0, 0, 1),  Vec3(1, 0, 1), Vec3(1, 0, 0),
                               Vec3(-1, 0, 1), Vec3(-1, 0, 0), Vec3(0, 1, 1), Vec3(0, 1, 0)};
  const std::vector<int> a = {0, 1, 2, 3}, b = {1, 0, 5, 4}, c = {0, 1, 6, 7};
  PolygonSoup s = soup_of(p, {a, c, b});
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::fin_edges), 1);
  EXPECT_EQ(r.fin_faces, 1);
  EXPECT_EQ(r.fin_copies, 2);
  EXPECT_EQ(r.count(Defect::pinch_vertices), 0);
  EXPECT_EQ(r.problems({}, true), std::vector<std::string>{"non-manifold edges (fins: more than two faces): 1 (the "
                                                           "edge of vertex 0 and vertex 1 with 3 faces)"});
  EXPECT_EQ(r.lines(),
            std::vector<std::string>{"separated 1 face from 1 edge with more than two faces (2 vertex copies)"});
  const auto f = faces_of(s);
  EXPECT_EQ(f[0], a);
  EXPECT_EQ(f[2], b);
  EXPECT_EQ(f[1], (std::vector<int>{8, 9, 6, 7})) << "C on copies of 0 and 1";
  EXPECT_EQ(s.positions[8], p[0]);
  EXPECT_EQ(s.positions[9], p[1]);
  EXPECT_EQ(boundary_edges(s), 10);
  EXPECT_EQ(r.parts, 2);
  EXPECT_EQ(r.boundary_loops, 2);
}

// A closed tetrahedron 0 1 2 3 and a triangle 0 1 4 hanging from its edge 0–1, written first: the
// tetrahedron's faces on the fin close one sheet and stay paired, although the triangle comes before
// them, and each of its other faces joins them at 0 and at 1; the tetrahedron's last face is flipped.
TEST(MeshRepair, FinFaceConnectedThroughOtherEdgesIsSeparated) {
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1, 0), Vec3(0.5, 0.3, 1), Vec3(0.5, -1, 0)};
  const std::vector<std::vector<int>> tetrahedron = {{1, 0, 2}, {0, 1, 3}, {3, 1, 2}, {2, 0, 3}};
  std::vector<std::vector<int>> faces = {{0, 1, 4}};
  faces.insert(faces.end(), tetrahedron.begin(), tetrahedron.end());
  std::reverse(faces[4].begin() + 1, faces[4].end());
  PolygonSoup s = soup_of(p, faces);
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::fin_edges), 1);
  EXPECT_EQ(r.fin_faces, 1);
  EXPECT_EQ(r.fin_copies, 2);
  EXPECT_EQ(r.count(Defect::pinch_vertices), 0);
  EXPECT_EQ(r.count(Defect::flipped_faces), 1);
  EXPECT_EQ(r.examples[size_t(Defect::flipped_faces)][0].element, 4);
  const auto f = faces_of(s);
  ASSERT_EQ(f.size(), 5u);
  EXPECT_EQ(f[0], faces[0]) << "the triangle's fans come first: it keeps vertices 0 and 1";
  const std::map<int, int> copy = {{0, 6}, {1, 5}, {2, 2}, {3, 3}};  // the tetrahedron on their copies
  for (size_t i = 0; i < tetrahedron.size(); ++i)
    EXPECT_EQ(f[i + 1],
              (std::vector<int>{copy.at(tetrahedron[i][0]), copy.at(tetrahedron[i][1]), copy.at(tetrahedron[i][2])}));
  EXPECT_EQ(s.positions[5], p[1]);
  EXPECT_EQ(s.positions[6], p[0]);
  EXPECT_EQ(s.positions.size(), 7u);
  EXPECT_EQ(boundary_edges(s), 3);
  EXPECT_EQ(r.parts, 2);
  EXPECT_EQ(r.boundary_loops, 1);
}

TEST(MeshRepair, ZeroAreaDuplicateAndDegenerateFacesAreDropped) {
  // A square of two triangles; a duplicate of the first (rotated), a sliver on the edge 0–1 through
  // vertex 4 (its midpoint), a face listing vertex 2 twice in a row (mended) and one on two vertices.
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0),   Vec3(1, 1, 0),
                               Vec3(0, 1, 0), Vec3(0.5, 0, 0), Vec3(2, 1, 0)};
  PolygonSoup s = soup_of(p, {{0, 1, 2}, {0, 2, 3}, {2, 0, 1}, {0, 4, 1}, {1, 5, 2, 2}, {3, 3, 0}});
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::duplicate_faces), 1);
  EXPECT_EQ(r.count(Defect::zero_area_faces), 1);
  EXPECT_EQ(r.problems({}, false), std::vector<std::string>{"zero-area faces: 1 (face 3)"});
  EXPECT_EQ(r.refusal({}),
            "1 face with a repeated corner, face 4; --repair removes the repeat; "
            "1 degenerate face (fewer than 3 distinct corners), face 5; --repair drops it; "
            "1 duplicate face (on the vertices of an earlier one), face 2 as face 0; --repair drops it");
  EXPECT_EQ(r.count(Defect::repeated_corners), 1);
  EXPECT_EQ(r.count(Defect::degenerate_faces), 1);
  EXPECT_EQ(r.count(Defect::isolated_vertices), 0) << "the file's faces use every vertex";
  EXPECT_EQ(r.orphaned_vertices, 1) << "vertex 4, left by the sliver";
  EXPECT_EQ(faces_of(s), (std::vector<std::vector<int>>{{0, 1, 2}, {0, 2, 3}, {1, 4, 2}}));
  EXPECT_EQ(s.positions.size(), 5u);
  EXPECT_EQ(s.positions[4], p[5]);
  EXPECT_EQ(boundary_edges(s), 5);
  EXPECT_EQ(r.boundary_loops, 1);
}

TEST(MeshRepair, FaceUsingAVertexTwiceIsSplitIntoLoops) {
  // A bow tie through vertex 0: 0 1 2 0 3 4 → triangles 0 1 2 and 0 3 4.
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)};
  PolygonSoup s = soup_of(p, {{0, 1, 2, 0, 3, 4}});
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::repeated_corners), 1);
  EXPECT_EQ(r.split_faces, 1);
  EXPECT_EQ(r.count(Defect::pinch_vertices), 1) << "the two loops meet at vertex 0 only";
  EXPECT_EQ(s.faces.n_faces(), 2);
  EXPECT_EQ(boundary_edges(s), 6);
}

TEST(MeshRepair, IsolatedVerticesAreDropped) {
  std::vector<Vec3> p = cube_positions();
  p.insert(p.begin() + 3, Vec3(5, 5, 5));
  p.push_back(Vec3(-5, 0, 0));
  std::vector<std::vector<int>> faces = kCubeFaces;
  for (auto& face : faces)
    for (int& v : face) v += v >= 3;
  PolygonSoup s = soup_of(p, faces);
  s.covariances.assign(10, Mat3::Identity());
  s.covariances[4] *= 4.0;  // cube vertex 3, vertex 3 after the repair
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::isolated_vertices), 2);
  EXPECT_EQ(r.problems({}, false), std::vector<std::string>{"isolated vertices (in no face): 2 (vertex 3; vertex 9)"});
  EXPECT_FALSE(r.refuses()) << "a mesh with isolated vertices is read as it is";
  EXPECT_EQ(r.refusal({}), "");
  EXPECT_EQ(faces_of(s), kCubeFaces);
  EXPECT_EQ(s.covariances[3](0, 0), 4.0);
  EXPECT_EQ(boundary_edges(s), 0);
}

TEST(MeshRepair, FlippedFaceIsFlippedBack) {
  std::vector<std::vector<int>> faces = kCubeFaces;
  std::reverse(faces[0].begin() + 1, faces[0].end());
  PolygonSoup s = soup_of(cube_positions(), faces);
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::flipped_faces), 1);
  ElementNumbering obj;
  obj.base = 1;
  obj.face_lines[0] = 9;
  EXPECT_EQ(r.refusal(obj), "1 face oriented against its neighbours, face 1 (line 9); --repair flips it")
      << "numbered from 1, with the line";
  EXPECT_EQ(boundary_edges(s), 0);
  EXPECT_EQ(faces_of(s)[0], kCubeFaces[0]);
  EXPECT_EQ(faces_of(s)[1], kCubeFaces[1]);
  EXPECT_EQ(r.boundary_loops, 0);
}

TEST(MeshRepair, MobiusStripIsNamedUnorientable) {
  // Six quads around a band whose cross-section turns half a turn: the last quad joins the first
  // edge backwards (A_6 = B_0, B_6 = A_0).
  constexpr int n = 6;
  std::vector<Vec3> p(2 * n);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    const Vec3 radial(std::cos(a), std::sin(a), 0);
    const Vec3 across = std::cos(a / 2) * radial + std::sin(a / 2) * Vec3(0, 0, 1);
    p[size_t(2 * i)] = 3 * radial + across;      // A_i
    p[size_t(2 * i + 1)] = 3 * radial - across;  // B_i
  }
  std::vector<std::vector<int>> faces;
  for (int i = 0; i + 1 < n; ++i) faces.push_back({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  faces.push_back({2 * n - 2, 1, 0, 2 * n - 1});
  PolygonSoup s = soup_of(p, faces);
  const RepairReport r = repair_polygon_soup(s);
  EXPECT_EQ(r.count(Defect::unorientable_parts), 1);
  EXPECT_EQ(r.boundary_loops, -1);
  ASSERT_EQ(r.lines().size(), 1u);
  EXPECT_NE(r.lines()[0].find("cannot be oriented"), std::string::npos) << r.lines()[0];
  EXPECT_FALSE(r.changed());
}

TEST(MeshRepair, ProblemsListEveryClassWithExamples) {
  std::vector<Vec3> p;
  std::vector<std::vector<int>> faces;
  add_tetrahedron(p, faces, Vec3(0, 0, 0));
  add_tetrahedron(p, faces, Vec3(0, 0, 0), 0);
  faces.push_back(faces[0]);  // a duplicate
  std::reverse(faces[1].begin(), faces[1].end());
  p.push_back(Vec3(9, 9, 9));  // isolated
  const RepairReport r = diagnose_polygon_soup(soup_of(p, faces));
  const auto problems = r.problems({}, true);
  ASSERT_EQ(problems.size(), 3u) << ::testing::PrintToString(problems);
  EXPECT_EQ(problems[0], "duplicate faces (on the vertices of an earlier one): 1 (face 8 as face 0)");
  EXPECT_EQ(problems[1], "non-manifold (pinch) vertices: 1 (vertex 0 with 2 fans)");
  EXPECT_EQ(problems[2], "faces oriented against their neighbours: 1 (face 1)");
  EXPECT_EQ(r.problems({}, false), std::vector<std::string>{"isolated vertices (in no face): 1 (vertex 7)"});
  std::vector<int> vertices, faces_named;
  r.named_elements(vertices, faces_named);
  EXPECT_EQ(vertices, (std::vector<int>{0, 7}));
  EXPECT_EQ(faces_named, (std::vector<int>{8, 0, 1}));
}

}  // namespace
}  // namespace gps
