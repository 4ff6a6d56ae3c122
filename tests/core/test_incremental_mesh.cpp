// A changed mesh's connectivity carried over from the mesh it was made from (updated_connectivity)
// against one built from scratch: equal array for array wherever the update vouches for it, and never
// vouching for what a whole build refuses; and the modelling operations, whose results are made that
// way, against whole builds of the same faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <optional>
#include <cstdio>
#include <random>
#include <span>

#include "core/mesh/connectivity_update.h"
#include "core/mesh/covariance_mesh.h"
#include "core/mesh/spare_connectivity.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/extrude.h"
#include "core/modelling/inset.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/mesh_arrays.h"
#include "core/modelling/samples.h"
#include "core/modelling/subdivide_mesh.h"
#include "core/support/error.h"
#include "tests/support/connectivity_equal.h"

namespace gps {
namespace {

using Faces = std::vector<std::vector<int>>;

// A changed topology and where its elements came from.
struct Changed {
  Faces faces;
  MeshOrigins origins;
  int n_vertices = 0;
};

PolygonTopology topology_of(const Faces& faces, int n_vertices) {
  PolygonTopology t = polygon_topology(faces);
  t.n_vertices = n_vertices;
  return t;
}

Faces faces_of(const CovarianceMesh& m) {
  Faces out;
  for (size_t f = 0; f < m.n_faces(); ++f) out.emplace_back(m.face(f).begin(), m.face(f).end());
  return out;
}

// One random edit of the kinds operations make, good and bad: a face deleted, reversed, split, a new
// vertex's triangle on an edge (on a boundary edge good, elsewhere a third face), a face of random
// vertices, two vertices made one, a face's reverse added (a pillow), the unused vertices dropped.
void random_edit(Changed& c, std::mt19937& rng) {
  const auto pick = [&](size_t n) { return size_t(std::uniform_int_distribution<size_t>(0, n - 1)(rng)); };
  if (c.faces.size() < 2) return;
  const size_t f = pick(c.faces.size());
  const auto drop_face = [&](size_t g) {
    c.faces.erase(c.faces.begin() + long(g));
    if (g < c.origins.faces.size()) c.origins.faces.erase(c.origins.faces.begin() + long(g));
  };
  // Weighted toward the edits that keep a manifold: deletions, splits, triangles on edges, compaction.
  constexpr int kKinds[] = {0, 0, 0, 0, 2, 3, 3, 4, 4, 5, 6, 7, 8, 8, 9};
  switch (kKinds[pick(std::size(kKinds))]) {
    case 0:
      drop_face(f);
      break;
    case 2:
      std::reverse(c.faces[f].begin(), c.faces[f].end());
      break;
    case 3:
      if (c.faces[f].size() >= 4) {
        const std::vector<int> piece{c.faces[f][0], c.faces[f][2], c.faces[f][3]};
        c.faces[f].erase(c.faces[f].begin() + 3);
        c.faces.push_back(piece);
      }
      break;
    case 4: {
      const std::vector<int>& face = c.faces[f];
      const size_t k = pick(face.size());
      const int a = face[k], b = face[(k + 1) % face.size()];
      c.origins.vertices.push_back(-1);
      if (pick(4) == 0)  // flipped: running the edge the way its face does
        c.faces.push_back({a, b, c.n_vertices++});
      else
        c.faces.push_back({b, a, c.n_vertices++});
      break;
    }
    case 5:
      c.faces.push_back(
          {int(pick(size_t(c.n_vertices))), int(pick(size_t(c.n_vertices))), int(pick(size_t(c.n_vertices)))});
      break;
    case 6: {
      const int u = int(pick(size_t(c.n_vertices))), w = int(pick(size_t(c.n_vertices)));
      for (auto& face : c.faces) std::replace(face.begin(), face.end(), w, u);
      break;
    }
    case 7:
      c.faces.emplace_back(c.faces[f].rbegin(), c.faces[f].rend());
      break;
    case 9: {  // two faces trade places: the kept faces no longer in their old order
      const size_t g = pick(c.faces.size());
      std::swap(c.faces[f], c.faces[g]);
      if (f < c.origins.faces.size() && g < c.origins.faces.size()) std::swap(c.origins.faces[f], c.origins.faces[g]);
      break;
    }
    case 8: {
      std::vector<int> used(size_t(c.n_vertices), 0), new_index(size_t(c.n_vertices), -1);
      for (const auto& face : c.faces)
        for (int v : face)
          if (v >= 0 && v < c.n_vertices) used[size_t(v)] = 1;
      std::vector<int> origin;
      for (int v = 0; v < c.n_vertices; ++v)
        if (used[size_t(v)]) {
          new_index[size_t(v)] = int(origin.size());
          origin.push_back(c.origins.vertices[size_t(v)]);
        }
      for (auto& face : c.faces)
        for (int& v : face)
          if (v >= 0 && v < c.n_vertices) v = new_index[size_t(v)];
      c.origins.vertices = origin;
      c.n_vertices = int(origin.size());
      break;
    }
  }
}

// `before` unchanged, as a change of itself: every vertex and face its own origin.
Changed unchanged(const CovarianceMesh& before) {
  Changed c{faces_of(before), {}, int(before.n_vertices())};
  c.origins.vertices.resize(before.n_vertices());
  std::iota(c.origins.vertices.begin(), c.origins.vertices.end(), 0);
  c.origins.faces.resize(before.n_faces());
  std::iota(c.origins.faces.begin(), c.origins.faces.end(), 0);
  return c;
}

enum class Outcome { refused, declined, vouched };

// The update of `before` to the change `c` against a whole build of its faces: where the whole build
// refuses them the update must not vouch for them; where it vouches it must give the whole build's
// connectivity (a failure otherwise, named by `trial`).
Outcome update_against_whole_build(const CovarianceMesh& before, const Changed& c, int trial) {
  const PolygonTopology t = topology_of(c.faces, c.n_vertices);
  const std::optional<MeshConnectivity> updated =
      updated_connectivity(before.topology(), before.connectivity(), t, c.origins);
  std::optional<CovarianceMesh> whole;
  try {
    whole =
        make_covariance_mesh(std::vector<Vec3>(size_t(c.n_vertices), Vec3::Zero()), {}, PolygonTopology(t), "changed");
  } catch (const Error&) {
  }
  if (!whole) {
    EXPECT_FALSE(updated.has_value()) << "trial " << trial << ": vouched for a topology a whole build refuses";
    return Outcome::refused;
  }
  if (!updated) return Outcome::declined;
  test::expect_equal(*updated, whole->connectivity());
  return Outcome::vouched;
}

// Random edits of meshes of quads, triangles and both: wherever the update vouches for a topology
// it equals connectivity_of's whole build, which accepts it; wherever the whole build refuses one,
// the update does not vouch for it. Both kinds occur often.
TEST(IncrementalConnectivity, RandomChangesGiveWhatAWholeBuildGivesAndNeverPassWhatItRefuses) {
  std::mt19937 rng(46);
  int vouched = 0, refused = 0, declined = 0, large_vouched = 0;
  // The last, past kParallelFaces vertices, follows the rows on all cores.
  const std::vector<std::tuple<const char*, int, int>> cases = {
      {"grid", 200, 300}, {"icosphere", 200, 300}, {"cylinder", 200, 300}, {"pawn-quads", 200, 300},
      {"cone", 200, 300}, {"torus", 200, 300},     {"wirecube", 200, 300}, {"sphere", 6000, 30}};
  for (const auto& [name, size, trials] : cases) {
    SCOPED_TRACE(name);
    const CovarianceMesh before = make_sample(name, size);
    const bool large = size > 1000;
    if (large) {
      EXPECT_GE(before.n_vertices(), size_t(kParallelFaces));
    }
    for (int trial = 0; trial < trials; ++trial) {
      Changed c = unchanged(before);
      const int n_edits = 1 + trial % 4;
      for (int i = 0; i < n_edits; ++i) random_edit(c, rng);
      const Outcome outcome = update_against_whole_build(before, c, trial);
      refused += outcome == Outcome::refused;
      declined += outcome == Outcome::declined;
      vouched += outcome == Outcome::vouched;
      large_vouched += large && outcome == Outcome::vouched;
      if (HasFailure()) return;
    }
  }
  std::printf("vouched %d refused %d declined %d\n", vouched, refused, declined);
  EXPECT_GT(vouched, 500);
  EXPECT_GT(refused, 500);
  EXPECT_LT(declined, vouched / 4);
  EXPECT_GT(large_vouched, 5);
}

// The update writes into the arrays of a connectivity let go before (core/mesh/spare_connectivity.h):
// given spares from half to twice the sizes it needs, every element a value no connectivity holds, it
// still gives what a whole build gives.
TEST(IncrementalConnectivity, ASpareOfOtherSizesAndValuesGivesWhatAWholeBuildGives) {
  std::mt19937 rng(4747);
  int vouched = 0;
  for (const char* name : {"grid", "icosphere", "pawn-quads", "torus"}) {
    SCOPED_TRACE(name);
    const CovarianceMesh before = make_sample(name, 200);
    const MeshConnectivity& b = before.connectivity();
    for (int trial = 0; trial < 60; ++trial) {
      Changed c = unchanged(before);
      for (int i = 0; i < 1 + trial % 3; ++i) random_edit(c, rng);
      const double scale = 0.5 + 0.5 * double(trial % 4);
      const auto poisoned = [&](const std::vector<int>& like) {
        return std::vector<int>(size_t(scale * double(like.size())) + 1, -7);
      };
      take_spare_connectivity();  // the last whole build's, let go
      keep_spare_connectivity({.edge_verts = poisoned(b.edge_verts),
                               .edge_faces = poisoned(b.edge_faces),
                               .face_edges = poisoned(b.face_edges),
                               .vertex_edge_offsets = poisoned(b.vertex_edge_offsets),
                               .vertex_edges = poisoned(b.vertex_edges),
                               .vertex_face_offsets = poisoned(b.vertex_face_offsets),
                               .vertex_faces = poisoned(b.vertex_faces),
                               .vertex_face_corners = poisoned(b.vertex_face_corners)});
      vouched += update_against_whole_build(before, c, trial) == Outcome::vouched;
      if (HasFailure()) return;
    }
  }
  EXPECT_GT(vouched, 100);
}

// Edits that leave every old vertex and every kept face its number (faces changed in place, the last
// ones dropped, new ones added after), where the update copies the old edges whose faces all stay in
// runs: the same as a whole build wherever it vouches, and never vouching for what that refuses.
TEST(IncrementalConnectivity, EdgesWhoseFacesAllKeepTheirNumbersAreCarriedAsWholeBuildsGiveThem) {
  std::mt19937 rng(4646);
  const auto pick = [&](size_t n) { return size_t(std::uniform_int_distribution<size_t>(0, n - 1)(rng)); };
  int vouched = 0, refused = 0;
  for (const auto& [name, size] : std::vector<std::pair<const char*, int>>{
           {"grid", 200}, {"icosphere", 200}, {"cylinder", 200}, {"torus", 200}, {"sphere", 6000}}) {
    SCOPED_TRACE(name);
    const CovarianceMesh before = make_sample(name, size);
    for (int trial = 0; trial < 150; ++trial) {
      Changed c = unchanged(before);
      for (int i = 0; i <= trial % 3; ++i) {
        const size_t f = pick(c.faces.size());
        switch (pick(4)) {
          case 0:  // the last faces dropped: a hole whose edges keep one face, or lose both
            for (size_t k = 0, n = 1 + pick(3); k < n && c.faces.size() > 2; ++k) c.faces.pop_back();
            break;
          case 1:  // a face turned over in place
            std::reverse(c.faces[f].begin(), c.faces[f].end());
            break;
          case 2: {  // a new vertex's triangle on an edge: filling a boundary, or a third face
            const size_t k = pick(c.faces[f].size());
            c.origins.vertices.push_back(-1);
            c.faces.push_back({c.faces[f][(k + 1) % c.faces[f].size()], c.faces[f][k], c.n_vertices++});
            break;
          }
          default:  // a face's corners moved to new vertices, the old face's place kept
            for (int& v : c.faces[f]) {
              c.origins.vertices.push_back(-1);
              v = c.n_vertices++;
            }
        }
      }
      c.origins.faces.resize(std::min(c.origins.faces.size(), c.faces.size()));
      const Outcome outcome = update_against_whole_build(before, c, trial);
      refused += outcome == Outcome::refused;
      vouched += outcome == Outcome::vouched;
      if (HasFailure()) return;
    }
  }
  std::printf("vouched %d refused %d\n", vouched, refused);
  EXPECT_GT(vouched, 200);
  EXPECT_GT(refused, 50);
}

// Where the change cannot be followed the update declines, and the mesh is built whole: old vertices
// in a new order, most faces new, no face origins.
TEST(IncrementalConnectivity, DeclinesWhatItCannotFollow) {
  const CovarianceMesh before = make_sample("grid", 64);
  const int n = int(before.n_vertices());
  MeshOrigins same;
  same.vertices.resize(size_t(n));
  std::iota(same.vertices.begin(), same.vertices.end(), 0);
  same.faces.resize(before.n_faces());
  std::iota(same.faces.begin(), same.faces.end(), 0);
  const PolygonTopology& t = before.topology();
  ASSERT_TRUE(updated_connectivity(t, before.connectivity(), t, same).has_value());
  test::expect_equal(*updated_connectivity(t, before.connectivity(), t, same), before.connectivity());

  MeshOrigins swapped = same;
  std::swap(swapped.vertices[0], swapped.vertices[1]);
  EXPECT_FALSE(updated_connectivity(t, before.connectivity(), t, swapped).has_value());
  MeshOrigins no_faces = same;
  no_faces.faces.clear();
  EXPECT_FALSE(updated_connectivity(t, before.connectivity(), t, no_faces).has_value());
  MeshOrigins shifted = same;
  std::rotate(shifted.faces.begin(), shifted.faces.begin() + 1, shifted.faces.end());
  EXPECT_FALSE(updated_connectivity(t, before.connectivity(), t, shifted).has_value());
}

// Faces whose corners are the old faces' numbers, but every vertex one further along (old vertex 0
// gone, one new vertex at the end): the numbers are the same, the vertices are not, so no face
// continues its old one. Followed, the update gives the whole build; else it declines.
TEST(IncrementalConnectivity, AFaceOfTheOldNumbersOnOtherVerticesIsNotTheOldFace) {
  const CovarianceMesh before = make_sample("grid", 10000);  // runs of faces compared at once
  const int n = int(before.n_vertices());
  MeshOrigins moved;
  moved.vertices.resize(size_t(n));
  std::iota(moved.vertices.begin(), moved.vertices.end(), 1);
  moved.vertices.back() = -1;
  moved.faces.resize(before.n_faces());
  std::iota(moved.faces.begin(), moved.faces.end(), 0);
  const PolygonTopology& t = before.topology();
  const std::optional<MeshConnectivity> updated = updated_connectivity(t, before.connectivity(), t, moved);
  if (updated) test::expect_equal(*updated, before.connectivity());
  EXPECT_FALSE(updated.has_value()) << "every face is new: a whole build costs less";
}

// On a mesh whose edges are merged in blocks on all cores: a hole over a run of vertices (its faces gone,
// its vertices dropped, the others renumbered) leaves blocks of edges without a kept face, and a triangle
// on the hole's rim past them adds edges that sort after those blocks. The update puts them where a whole
// build does.
TEST(IncrementalConnectivity, EdgesOfNewFacesPastABlockOfGoneEdgesLandWhereAWholeBuildPutsThem) {
  const CovarianceMesh before = make_sample("sphere", 6000);
  ASSERT_GE(before.n_edges(), size_t(2 * kParallelFaces));
  const int v0 = int(before.n_vertices()) / 3, v1 = v0 + 400;
  std::vector<char> gone(before.n_faces(), 0);
  Changed c;
  for (size_t f = 0; f < before.n_faces(); ++f) {
    const std::span<const int> corners = before.face(f);
    gone[f] = std::any_of(corners.begin(), corners.end(), [&](int v) { return v >= v0 && v < v1; });
    if (gone[f]) continue;
    c.faces.emplace_back(corners.begin(), corners.end());
    c.origins.faces.push_back(int(f));
  }
  // A rim edge with both ends past the hole, run x → y by the face kept beside it.
  const MeshConnectivity& k = before.connectivity();
  int x = -1, y = -1;
  for (size_t e = 0; e < size_t(k.n_edges()) && x < 0; ++e) {
    const int a = k.edge_faces[2 * e], b = k.edge_faces[2 * e + 1];
    if (a < 0 || b < 0 || gone[size_t(a)] == gone[size_t(b)] || k.edge_verts[2 * e] < v1) continue;
    const std::span<const int> kept = before.face(size_t(gone[size_t(a)] ? b : a));
    for (size_t i = 0; i < kept.size(); ++i) {
      const int from = kept[i], to = kept[(i + 1) % kept.size()];
      if (std::minmax(from, to) == std::minmax(k.edge_verts[2 * e], k.edge_verts[2 * e + 1])) x = from, y = to;
    }
  }
  ASSERT_GE(x, 0) << "no rim edge past the hole";
  // The hole's vertices dropped, the others renumbered in order, a new vertex last.
  std::vector<int> new_index(before.n_vertices(), -1);
  for (int v = 0; v < int(before.n_vertices()); ++v)
    if (v < v0 || v >= v1) {
      new_index[size_t(v)] = c.n_vertices++;
      c.origins.vertices.push_back(v);
    }
  for (auto& face : c.faces)
    for (int& v : face) v = new_index[size_t(v)];
  c.faces.push_back({new_index[size_t(y)], new_index[size_t(x)], c.n_vertices++});
  c.origins.vertices.push_back(-1);
  EXPECT_EQ(update_against_whole_build(before, c, 0), Outcome::vouched);
}

// A vertex of 100,000 faces and a face of 100,000 corners: an operation beside them reads each once
// (a walk that looked through the whole face, or the vertex's whole row, at every step would not end).
TEST(IncrementalConnectivity, AVertexOfManyFacesAndAFaceOfManyCornersAreNotReadOverAndOver) {
  constexpr int n = 100000;
  std::vector<Vec3> means{Vec3(0, 0, 1)};
  Faces fan;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.141592653589793 * i / n;
    means.emplace_back(std::cos(a), std::sin(a), 0.0);
    fan.push_back({0, 1 + i, 1 + (i + 1) % n});
  }
  const CovarianceMesh cone = make_covariance_mesh(means, {}, fan, "cone");
  // A disc of one face of n corners with a ring of quads around it.
  std::vector<Vec3> ring;
  Faces disc(1);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.141592653589793 * i / n;
    ring.emplace_back(std::cos(a), std::sin(a), 0.0);
    disc[0].push_back(i);
  }
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.141592653589793 * i / n;
    ring.emplace_back(2 * std::cos(a), 2 * std::sin(a), 0.0);
    disc.push_back({(i + 1) % n, i, n + i, n + (i + 1) % n});
  }
  const CovarianceMesh annulus = make_covariance_mesh(ring, {}, disc, "disc");
  for (const Modelled& r : {delete_faces(cone, {0}), extrude_faces(cone, {n / 2}, 0.1), delete_faces(annulus, {5}),
                            extrude_faces(annulus, {7}, 0.1)}) {
    SCOPED_TRACE(r.summary);
    const CovarianceMesh whole = make_covariance_mesh(r.mesh.means(), r.mesh.covariances, faces_of(r.mesh), "whole");
    test::expect_equal(r.mesh.connectivity(), whole.connectivity());
  }
}

// The mesh an operation gives, whose connectivity is carried over from its input's, against a whole
// build of its faces, along random sequences of operations on meshes of quads, triangles, both, and
// creases.
TEST(IncrementalMesh, OperationSequencesGiveWhatWholeBuildsGive) {
  std::mt19937 rng(4646);
  int operations = 0;
  for (const char* name : {"grid", "icosphere", "cylinder", "pawn-quads", "torus"}) {
    SCOPED_TRACE(name);
    CovarianceMesh mesh = make_sample(name, 300);
    if (std::string(name) == "torus")  // creased here and there
      for (size_t e = 0; e < mesh.n_edges(); e += 7) mesh.sharpness.set_crease(mesh.edge(e)[0], mesh.edge(e)[1], 2.0);
    for (int step = 0; step < 40; ++step) {
      const auto pick = [&](size_t k) { return int(std::uniform_int_distribution<size_t>(0, k - 1)(rng)); };
      const int f = pick(mesh.n_faces());
      const std::span<const int> corners = mesh.face(size_t(f));
      std::optional<Modelled> r;
      try {
        switch (pick(7)) {
          case 0:
            r = extrude_faces(mesh, {f}, 0.05);
            break;
          case 1:
            r = inset_faces(mesh, {f, pick(mesh.n_faces())}, 0.01);
            break;
          case 2:
            r = loop_cut(mesh, corners[0], corners[1], 1);
            break;
          case 3:
            r = subdivide_faces(mesh, {f});
            break;
          case 4:
            r = delete_faces(mesh, {f});
            break;
          case 5:
            r = merge_vertices(mesh, {corners[0], corners[1]}, MergePoint::center);
            break;
          case 6:
            r = dissolve_edges(mesh, {{corners[0], corners[1]}});
            break;
        }
      } catch (const Error&) {
        continue;
      }
      ++operations;
      const CovarianceMesh& m = r->mesh;
      const CovarianceMesh whole = make_covariance_mesh(m.means(), m.covariances, faces_of(m), "whole");
      test::expect_equal(m.connectivity(), whole.connectivity());
      EXPECT_EQ(m.topology().offsets, whole.topology().offsets);
      EXPECT_EQ(m.topology().verts, whole.topology().verts);
      EXPECT_EQ(m.sharpness.creases, build_mesh(arrays_of(m)).sharpness.creases);
      if (HasFailure()) return;
      mesh = std::move(r->mesh);
    }
  }
  EXPECT_GT(operations, 100);
}

// Arrays changed at random, faces and Gaussians (some of them no longer valid), built from the mesh
// they were made from and built whole: the same mesh, array for array, or the same message.
TEST(IncrementalMesh, ChangedArraysBuildAsAWholeBuildDoesOrFailWithItsMessage) {
  std::mt19937 rng(146);
  int built = 0, failed = 0;
  for (const char* name : {"grid", "icosphere", "cylinder", "torus"}) {
    SCOPED_TRACE(name);
    CovarianceMesh before = make_sample(name, 150);
    for (size_t e = 0; e < before.n_edges(); e += 5)
      before.sharpness.set_crease(before.edge(e)[0], before.edge(e)[1], 1.5);
    for (int trial = 0; trial < 200; ++trial) {
      MeshArrays a = arrays_of(before);
      Changed c{a.faces, {a.origin, a.face_origin}, a.n_vertices()};
      for (int i = 0; i < 1 + trial % 3; ++i) random_edit(c, rng);
      a.faces = c.faces;
      a.face_origin = c.origins.faces;
      // The arrays' vertices follow the edits' renumbering; new ones copy vertex 0's Gaussian.
      std::vector<Vec3> means;
      std::vector<Mat3> covariances;
      for (int o : c.origins.vertices) {
        means.push_back(before.mean(size_t(std::max(o, 0))));
        covariances.push_back(before.covariance(size_t(std::max(o, 0))));
      }
      a.means = means;
      a.covariances = covariances;
      a.origin = c.origins.vertices;
      const size_t v = size_t(rng() % a.means.size());
      switch (rng() % 8) {
        case 0:
          a.means[v].x() += 0.01;
          break;
        case 1:
          a.covariances[v] = -a.covariances[v];
          break;
        case 2:
          a.means[v].y() = std::numeric_limits<double>::quiet_NaN();
          break;
        default:
          break;
      }
      std::string incremental_error, whole_error;
      std::optional<CovarianceMesh> incremental, whole;
      try {
        incremental = build_mesh(a, before);
      } catch (const Error& e) {
        incremental_error = e.what();
      }
      try {
        whole = build_mesh(a);
      } catch (const Error& e) {
        whole_error = e.what();
      }
      ASSERT_EQ(incremental_error, whole_error) << "trial " << trial;
      if (!whole) {
        ++failed;
        continue;
      }
      ++built;
      test::expect_equal(incremental->connectivity(), whole->connectivity());
      EXPECT_EQ(incremental->topology().verts, whole->topology().verts);
      EXPECT_EQ(incremental->means(), whole->means());
      EXPECT_EQ(incremental->covariances, whole->covariances);
      EXPECT_EQ(incremental->sharpness.creases, whole->sharpness.creases);
      EXPECT_EQ(incremental->sharpness.corners, whole->sharpness.corners);
      if (HasFailure()) return;
    }
  }
  std::printf("built %d failed %d\n", built, failed);
  EXPECT_GT(built, 100);
  EXPECT_GT(failed, 100);
}

// arrays_of fills the face lists that the last arrays destroyed on the thread leave, of other sizes
// and more or fewer faces: each list holds its face's corners, no more.
TEST(IncrementalMesh, ArraysOfRecycledListsHoldEachFaceExactly) {
  for (const char* name : {"pawn", "icosphere", "cube", "torus", "pawn", "cube"}) {
    const CovarianceMesh mesh = make_sample(name);
    const MeshArrays arrays = arrays_of(mesh);
    ASSERT_EQ(arrays.faces.size(), mesh.n_faces()) << name;
    for (size_t f = 0; f < mesh.n_faces(); ++f) {
      const std::span<const int> face = mesh.face(f);
      ASSERT_EQ(arrays.faces[f], std::vector<int>(face.begin(), face.end())) << name << ", face " << f;
    }
  }
}

}  // namespace
}  // namespace gps
