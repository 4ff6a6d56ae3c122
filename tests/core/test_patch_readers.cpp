// The patches an edit changes (core/plans/patch_readers.h): every patch whose evaluation or whose
// canonical boundary patch reads a changed point is listed; the others evaluate bit for bit alike.
#include "core/plans/patch_readers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/evaluation/patch_eval.h"
#include "core/plans/patch_faces.h"
#include "core/plans/planned_surface.h"
#include "core/modelling/samples.h"

namespace gps {
namespace {

// The changed points of an edit of base vertices: the vertices, then the points of the rows reading them.
std::vector<int> changed_points(const PlannedSurface& surface, const std::vector<int>& vertices) {
  std::vector<int> points = vertices;
  for (const int r : surface.rows_reading(vertices)) points.push_back(surface.tables().stencils.first_row() + r);
  return points;
}

// Whether patch p evaluates alike (q and its derivatives, bit for bit) from both point sets, at a
// grid of parameters that includes its boundary.
bool evaluates_alike(const PatchPlans& plans, const std::vector<Dual>& a, const std::vector<Dual>& b, int p) {
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      const double u = i / 4.0, v = j / 4.0;
      if (plans.shape == PatchShape::triangle && u + v > 1.0) continue;
      Dual qa, qa_u, qa_v, qb, qb_u, qb_v;
      evaluate_dual(plans, a, p, u, v, qa, qa_u, qa_v);
      evaluate_dual(plans, b, p, u, v, qb, qb_u, qb_v);
      if (qa != qb || qa_u != qb_u || qa_v != qb_v) return false;
    }
  return true;
}

TEST(PatchReaders, UnlistedPatchesEvaluateAlikeAfterAnEdit) {
  for (const char* name : {"cube", "pawn", "icosphere", "sphere"}) {
    CovarianceMesh mesh = make_sample(name);
    const PlannedSurface surface(mesh, PlanOptions{});
    const PatchPlans& plans = surface.tables().plans;
    const PatchReaders readers(plans, surface.tables().stencils.n_points());
    const std::vector<Dual> before = apply_stencils(surface.tables().stencils, base_points(mesh));
    const std::vector<int> edited = {int(mesh.n_vertices() / 2), int(mesh.n_vertices() / 3)};
    for (const int v : edited) mesh.set_mean(size_t(v), mesh.mean(size_t(v)) + Vec3(0.1, -0.2, 0.05));
    const std::vector<Dual> after = apply_stencils(surface.tables().stencils, base_points(mesh));
    const std::vector<int> listed = readers.patches_changed_by(changed_points(surface, edited));
    ASSERT_TRUE(std::is_sorted(listed.begin(), listed.end())) << name;
    int changed = 0;
    for (int p = 0; p < plans.n_patches(); ++p) {
      const bool alike = evaluates_alike(plans, before, after, p);
      changed += !alike;
      if (!std::binary_search(listed.begin(), listed.end(), p)) {
        EXPECT_TRUE(alike) << name << " patch " << p;
      }
    }
    EXPECT_GT(changed, 0) << name;
    if (plans.n_patches() > 500) {
      EXPECT_LT(listed.size() * 4, size_t(plans.n_patches())) << name;
    }
  }
}

// Found from the mesh around the vertices, the patches an edit changes are those the index over every
// patch lists: on quads, triangles, mixed faces and creases (semi-sharp ones refine into stencil rows,
// infinitely sharp ones flag records), for vertices alone, beside each other, by an extraordinary
// vertex, on a boundary, and many at once.
TEST(PatchReaders, ThePatchesNearAnEditAreThoseTheIndexLists) {
  int compared = 0;
  for (const char* name : {"cube", "pawn", "icosphere", "sphere", "grid", "cylinder", "torus", "pawn-quads"})
    for (const bool creased : {false, true}) {
      CovarianceMesh mesh = make_sample(name);
      for (size_t e = 0; creased && e < mesh.n_edges(); e += 5)
        mesh.sharpness.set_crease(mesh.edge(e)[0], mesh.edge(e)[1], e % 3 ? 2.5 : kInfiniteSharpness);
      const PlannedSurface surface(mesh, PlanOptions{});
      const SurfaceTables& tables = surface.tables();
      const PatchReaders readers(tables.plans, tables.stencils.n_points());
      const std::vector<int> first = first_patches(mesh.topology(), tables.plans);
      const int n = int(mesh.n_vertices());
      std::vector<std::vector<int>> edits;
      for (const int v : {0, 1, n / 3, n / 2, n - 1}) edits.push_back({v});
      edits.push_back({n / 2, n / 2 + 1, n / 2 + 2});
      edits.push_back({});
      for (int v = 0; v < n; v += 3) edits.back().push_back(v);
      for (const std::vector<int>& edit : edits) {
        const std::vector<int> rows = surface.rows_reading(edit);
        const std::string where = std::string(name) + (creased ? " creased" : "") + ", " + std::to_string(edit.size()) +
                                  " vertices from " + std::to_string(edit.front());
        EXPECT_EQ(patches_changed_near(mesh.topology(), mesh.connectivity(), tables.plans, first,
                                       tables.stencils.first_row(), edit, rows),
                  readers.patches_changed_by(changed_points(surface, edit)))
            << where;
        compared += !rows.empty();
      }
    }
  EXPECT_GT(compared, 10);  // edits whose stencil rows change too
}

TEST(PatchReaders, NoPointsChangeNothingAndAllPointsEverything) {
  for (const char* name : {"pawn", "icosphere"}) {
    const CovarianceMesh mesh = make_sample(name);
    const PlannedSurface surface(mesh, PlanOptions{});
    const PatchReaders readers(surface.tables().plans, surface.tables().stencils.n_points());
    EXPECT_TRUE(readers.patches_changed_by({}).empty()) << name;
    std::vector<int> all(size_t(surface.tables().stencils.n_points()));
    for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
    EXPECT_EQ(readers.patches_changed_by(all).size(), size_t(surface.tables().plans.n_patches())) << name;
  }
}

}  // namespace
}  // namespace gps
