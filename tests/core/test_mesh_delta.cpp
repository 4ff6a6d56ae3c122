// A mesh told as a change of another (core/mesh/mesh_delta.h), as the undo history keeps operations:
// along random sequences of operations on meshes of quads, triangles, both, and creases, the result
// told against the mesh before and the mesh before told against the result restore each other byte for
// byte (arrays and written files), in memory proportional to what changed.
#include "core/mesh/mesh_delta.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <sstream>

#include "core/io/mesh_io.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/extrude.h"
#include "core/modelling/mesh_arrays.h"
#include "core/modelling/samples.h"
#include "core/support/error.h"
#include "tests/support/connectivity_equal.h"
#include "tests/support/random_operations.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

void expect_same_mesh(const CovarianceMesh& a, const CovarianceMesh& b) {
  EXPECT_EQ(a.means(), b.means());
  EXPECT_EQ(a.covariances, b.covariances);
  EXPECT_EQ(a.topology().offsets, b.topology().offsets);
  EXPECT_EQ(a.topology().verts, b.topology().verts);
  EXPECT_EQ(a.topology().n_vertices, b.topology().n_vertices);
  test::expect_equal(a.connectivity(), b.connectivity());
  EXPECT_EQ(a.sharpness.creases, b.sharpness.creases);
  EXPECT_EQ(a.sharpness.corners, b.sharpness.corners);
}

void expect_same_delta(const MeshDelta& a, const MeshDelta& b) {
  EXPECT_EQ(a.n_vertices, b.n_vertices);
  EXPECT_EQ(a.n_faces, b.n_faces);
  EXPECT_TRUE(a.vertex_runs == b.vertex_runs);
  EXPECT_TRUE(a.face_runs == b.face_runs);
  EXPECT_EQ(a.own_gaussians, b.own_gaussians);
  EXPECT_EQ(a.means, b.means);
  EXPECT_EQ(a.covariances, b.covariances);
  EXPECT_EQ(a.own_faces, b.own_faces);
  EXPECT_EQ(a.own_offsets, b.own_offsets);
  EXPECT_EQ(a.own_corners, b.own_corners);
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One random operation of any kind (tests/support/random_operations.h); empty where it refuses.
std::optional<Modelled> random_operation(const CovarianceMesh& mesh, std::mt19937& rng) {
  try {
    return test::random_operation(mesh, rng);
  } catch (const Error&) {
    return std::nullopt;
  }
}

// `after`, made from `before` by an operation whose vertices came from `origin`, and `before` told as
// changes of each other restore each other.
void expect_deltas_restore(const CovarianceMesh& before, const CovarianceMesh& after, const std::vector<int>& origin) {
  const MeshDelta forward = mesh_delta(before, after, origin);
  const MeshDelta back = mesh_delta(after, before, inverse_origin(origin, before.n_vertices()));
  expect_same_mesh(apply_delta(before, forward), after);
  expect_same_mesh(apply_delta(after, back), before);
}

TEST(IncrementalUndo, OperationsAndTheirInversesRestoreEachOtherByteForByte) {
  std::mt19937 rng(4747);
  test::TempDir dir;
  int steps = 0;
  for (const char* name : {"grid", "icosphere", "cylinder", "pawn-quads", "torus"}) {
    SCOPED_TRACE(name);
    CovarianceMesh mesh = make_sample(name, 300);
    if (std::string(name) == "torus")
      for (size_t e = 0; e < mesh.n_edges(); e += 6) mesh.sharpness.set_crease(mesh.edge(e)[0], mesh.edge(e)[1], 3.0);
    for (int step = 0; step < 30; ++step) {
      std::optional<Modelled> r = random_operation(mesh, rng);
      if (!r) continue;
      ++steps;
      expect_deltas_restore(mesh, r->mesh, r->vertex_origin);
      if (step % 10 == 0) {  // and their files
        const CovarianceMesh undone =
            apply_delta(r->mesh, mesh_delta(r->mesh, mesh, inverse_origin(r->vertex_origin, mesh.n_vertices())));
        write_mesh(dir.file("a.ply"), mesh, true);
        write_mesh(dir.file("b.ply"), undone, true);
        EXPECT_EQ(file_bytes(dir.file("a.ply")), file_bytes(dir.file("b.ply")));
      }
      if (HasFailure()) return;
      mesh = std::move(r->mesh);
    }
  }
  EXPECT_GT(steps, 100);
}

// Each kind of operation, on each sample it applies to (up to a few tries at random elements): the
// result and the mesh before restore each other. Every kind applies somewhere.
TEST(IncrementalUndo, EveryKindOfOperationAndTheMeshBeforeRestoreEachOther) {
  std::mt19937 rng(31);
  std::vector<int> applied(size_t(test::kOperationKinds), 0);
  for (const char* name : {"grid", "icosphere", "cylinder", "pawn-quads"}) {
    const CovarianceMesh mesh = make_sample(name, 200);
    for (int kind = 0; kind < test::kOperationKinds; ++kind)
      for (int attempt = 0; attempt < 6; ++attempt) {
        Modelled r;
        try {
          r = test::operation_of_kind(mesh, kind, rng);
        } catch (const Error&) {
          continue;
        }
        SCOPED_TRACE(std::string(name) + ", kind " + std::to_string(kind) + " (" + r.summary + ")");
        expect_deltas_restore(mesh, r.mesh, r.vertex_origin);
        ++applied[size_t(kind)];
        break;
      }
  }
  for (int kind = 0; kind < test::kOperationKinds; ++kind)
    EXPECT_GT(applied[size_t(kind)], 0) << "operation kind " << kind << " applied to none of the samples";
}

// Without origins the vertices are matched by index; a delta of a mesh against itself holds nothing
// of its own (and its mesh shares the faces), and one against an unrelated mesh holds all of it, and both still restore
// it.
TEST(IncrementalUndo, DeltasWithoutOriginsStillRestore) {
  const CovarianceMesh grid = make_sample("grid", 100), torus = make_sample("torus");
  const MeshDelta same = mesh_delta(grid, grid, {});
  EXPECT_TRUE(same.own_gaussians.empty());
  EXPECT_TRUE(same.own_faces.empty());
  expect_same_mesh(apply_delta(grid, same), grid);
  EXPECT_EQ(apply_delta(grid, same).shape(), grid.shape()) << "every face kept: the faces are shared";
  const MeshDelta other = mesh_delta(grid, torus, {});
  EXPECT_EQ(other.own_faces.size(), torus.n_faces());
  expect_same_mesh(apply_delta(grid, other), torus);
}

// An operation's deltas told again after a move of some vertices (new ones, old ones, some moved back
// onto where they were before the operation, one listed twice): what mesh_delta makes of the moved mesh
// each way, byte for byte, and they restore it and the mesh before.
TEST(IncrementalUndo, DeltasToldAgainAfterAMoveAreThoseMadeAfresh) {
  std::mt19937 rng(912);
  int retold = 0;
  for (const char* name : {"grid", "icosphere", "cylinder", "pawn-quads"}) {
    SCOPED_TRACE(name);
    CovarianceMesh mesh = make_sample(name, 300);
    for (int step = 0; step < 12; ++step) {
      // Every other step moves old vertices itself, whose Gaussians the deltas then hold.
      const std::span<const int> c = mesh.face(size_t(step) % mesh.n_faces());
      std::optional<Modelled> r =
          step % 2 ? random_operation(mesh, rng)
                   : transform_vertices(mesh, {c.begin(), c.end()},
                                        AffineMap::about(mesh.mean(size_t(c[0])), 0.8 * Mat3::Identity()));
      if (!r) continue;
      SCOPED_TRACE("step " + std::to_string(step) + " (" + r->summary + ")");
      MeshDelta forward = mesh_delta(mesh, r->mesh, r->vertex_origin);
      MeshDelta back = mesh_delta(r->mesh, mesh, inverse_origin(r->vertex_origin, mesh.n_vertices()));
      CovarianceMesh moved = r->mesh;
      std::vector<int> vertices;
      std::vector<Vec3> was_means;
      std::vector<Mat3> was_covariances;
      const auto move = [&](int v, const Vec3& mean, const Mat3& covariance) {
        vertices.push_back(v);
        was_means.push_back(moved.mean(size_t(v)));
        was_covariances.push_back(moved.covariance(size_t(v)));
        moved.set_mean(size_t(v), mean);
        moved.set_covariance(size_t(v), covariance);
      };
      std::uniform_int_distribution<int> pick(0, int(moved.n_vertices()) - 1);
      for (int k = 0; k < 6; ++k) {  // anywhere
        const int v = pick(rng);
        move(v, moved.mean(size_t(v)) + Vec3(0.01 * (k + 1), 0.0, -0.02), 1.1 * moved.covariance(size_t(v)));
      }
      for (size_t v = 0; v < moved.n_vertices(); ++v)  // the new ones, and back where an old one was
        if (const int o = r->vertex_origin.empty() ? -1 : r->vertex_origin[v]; o < 0)
          move(int(v), moved.mean(v) * 1.5, moved.covariance(v));
      const auto move_back = [&](int v) {  // onto the Gaussian its origin had before the operation
        if (const int o = r->vertex_origin.empty() ? v : r->vertex_origin[size_t(v)];
            o >= 0 && o < int(mesh.n_vertices()))
          move(v, mesh.mean(size_t(o)), mesh.covariance(size_t(o)));
      };
      for (int k = 0; k < 4; ++k) move_back(pick(rng));
      const std::vector<int> moved_by_operation = forward.own_gaussians;
      for (size_t i = 0; i < moved_by_operation.size(); i += 2) move_back(moved_by_operation[i]);
      retell_gaussians(forward, back, moved, vertices, was_means, was_covariances);
      expect_same_delta(forward, mesh_delta(mesh, moved, vertex_sources(forward)));
      expect_same_delta(back, mesh_delta(moved, mesh, vertex_sources(back)));
      expect_same_mesh(apply_delta(mesh, forward), moved);
      expect_same_mesh(apply_delta(moved, back), mesh);
      if (HasFailure()) return;
      ++retold;
      mesh = std::move(moved);
    }
  }
  EXPECT_GT(retold, 25);
}

// What one small operation keeps on a large mesh: its delta each way is a small part of the mesh.
TEST(IncrementalUndo, AnOperationsDeltasAreInProportionToItsChange) {
  const CovarianceMesh sphere = make_sample("sphere", 20000);
  const size_t mesh_bytes = sphere.n_vertices() * (sizeof(Vec3) + sizeof(Mat3)) + sphere.n_corners() * 4 * sizeof(int);
  const int f = int(sphere.n_faces() / 2);
  for (const Modelled& r : {extrude_faces(sphere, {f}, 0.01), delete_faces(sphere, {f}), subdivide_faces(sphere, {f}),
                            inset_faces(sphere, {f}, 1e-3)}) {
    SCOPED_TRACE(r.summary);
    const MeshDelta forward = mesh_delta(sphere, r.mesh, r.vertex_origin);
    const MeshDelta back = mesh_delta(r.mesh, sphere, inverse_origin(r.vertex_origin, sphere.n_vertices()));
    EXPECT_LT(forward.bytes() + back.bytes(), mesh_bytes / 100);
    expect_same_mesh(apply_delta(r.mesh, back), sphere);
  }
}

}  // namespace
}  // namespace gps
