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

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// One random operation near a random face; empty where the operation refuses.
std::optional<Modelled> random_operation(const CovarianceMesh& mesh, std::mt19937& rng) {
  const auto pick = [&](size_t k) { return int(std::uniform_int_distribution<size_t>(0, k - 1)(rng)); };
  const int f = pick(mesh.n_faces());
  const std::span<const int> c = mesh.face(size_t(f));
  try {
    switch (pick(8)) {
      case 0:
        return extrude_faces(mesh, {f}, 0.05);
      case 1:
        return inset_faces(mesh, {f, pick(mesh.n_faces())}, 0.01);
      case 2:
        return loop_cut(mesh, c[0], c[1], 1);
      case 3:
        return subdivide_faces(mesh, {f});
      case 4:
        return delete_faces(mesh, {f});
      case 5:
        return merge_vertices(mesh, {c[0], c[1]}, MergePoint::center);
      case 6:
        return dissolve_edges(mesh, {{c[0], c[1]}});
      default:
        return transform_vertices(mesh, {c.begin(), c.end()},
                                  AffineMap::about(mesh.mean(size_t(c[0])), 1.2 * Mat3::Identity()));
    }
  } catch (const Error&) {
    return std::nullopt;
  }
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
      const MeshDelta forward = mesh_delta(mesh, r->mesh, r->vertex_origin);
      const MeshDelta back = mesh_delta(r->mesh, mesh, inverse_origin(r->vertex_origin, mesh.n_vertices()));
      const CovarianceMesh redone = apply_delta(mesh, forward);
      const CovarianceMesh undone = apply_delta(r->mesh, back);
      expect_same_mesh(redone, r->mesh);
      expect_same_mesh(undone, mesh);
      if (step % 10 == 0) {  // and their files
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

// Without origins the vertices are matched by index; a delta of a mesh against itself holds nothing
// of its own, and one against an unrelated mesh holds all of it, and both still restore it.
TEST(IncrementalUndo, DeltasWithoutOriginsStillRestore) {
  const CovarianceMesh grid = make_sample("grid", 100), torus = make_sample("torus");
  const MeshDelta same = mesh_delta(grid, grid, {});
  EXPECT_TRUE(same.own_gaussians.empty());
  EXPECT_TRUE(same.own_faces.empty());
  expect_same_mesh(apply_delta(grid, same), grid);
  const MeshDelta other = mesh_delta(grid, torus, {});
  EXPECT_EQ(other.own_faces.size(), torus.n_faces());
  expect_same_mesh(apply_delta(grid, other), torus);
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
