// Patch edge neighbours and corner owners (core/plans/patch_adjacency.h), the tables behind bit-exact
// shared edges on the GPU.
#include "core/plans/patch_adjacency.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>

#include "core/plans/planned_surface.h"
#include "core/mesh/samples.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

struct Ends {
  int32_t from, to;
  PatchEdgePart part;
};

Ends ends(const PatchPlans& plans, int p, int k) {
  if (plans.shape == PatchShape::quad) {
    const PatchEdge e = patch_edge(plans, p, k);
    return {e.from, e.to, e.part};
  }
  const int32_t* c = &plans.patch_corner_points[size_t(3 * p)];
  return {c[k], c[(k + 1) % 3], PatchEdgePart::whole};
}

// The base edges of a mesh that have one face only.
std::set<std::pair<int, int>> boundary_edges(const CovarianceMesh& mesh) {
  std::set<std::pair<int, int>> out;
  for (const auto e : mesh.mesh.edges())
    if (e.is_boundary()) out.insert(std::minmax(e.v0().idx(), e.v1().idx()));
  return out;
}

void check_adjacency(const std::string& name, const CovarianceMesh& mesh) {
  const SurfaceTables tables = build_surface_plans(topology_of(mesh.mesh), PlanOptions{});
  const PatchPlans& plans = tables.plans;
  const int n = plans.corners();
  ASSERT_EQ(plans.patch_neighbours.size(), size_t(4 * n * plans.n_patches())) << name;
  ASSERT_EQ(plans.corner_owners.size(), size_t(2 * n * plans.n_patches())) << name;
  const auto open = boundary_edges(mesh);
  int t_junctions = 0, linked = 0;
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int k = 0; k < n; ++k) {
      const Ends e = ends(plans, p, k);
      const EdgeNeighbour a = edge_neighbour(plans, p, k, 0), b = edge_neighbour(plans, p, k, 1);
      // Base-mesh boundary edges (the points are base vertices there) have no neighbour; every other edge has.
      const bool on_boundary =
          e.from < int(mesh.n_vertices()) && e.to < int(mesh.n_vertices()) && open.count(std::minmax(e.from, e.to));
      EXPECT_EQ(a.patch < 0, on_boundary) << name << " patch " << p << " edge " << k;
      if (a.patch < 0) continue;
      ++linked;
      EXPECT_NE(a.patch, p) << name;
      const Ends f = ends(plans, a.patch, a.edge);
      // The same edge of the mesh, in the direction the flag says.
      EXPECT_EQ(std::minmax(e.from, e.to), std::minmax(f.from, f.to)) << name << " patch " << p << " edge " << k;
      EXPECT_EQ(a.reversed, f.from == e.to) << name;
      if (e.part == PatchEdgePart::whole_beside_halves) {
        ++t_junctions;
        ASSERT_GE(b.patch, 0) << name;
        const Ends g = ends(plans, b.patch, b.edge);
        // The half at our `from` end and the half at our `to` end.
        EXPECT_EQ(f.part == PatchEdgePart::first_half ? f.from : f.to, e.from) << name;
        EXPECT_EQ(g.part == PatchEdgePart::first_half ? g.from : g.to, e.to) << name;
        for (const EdgeNeighbour& h : {a, b}) {  // each half points back at the whole edge
          const EdgeNeighbour back = edge_neighbour(plans, h.patch, h.edge);
          EXPECT_EQ(back.patch, p) << name;
          EXPECT_EQ(back.edge, k) << name;
        }
        continue;
      }
      EXPECT_LT(b.patch, 0) << name;
      const EdgeNeighbour back = edge_neighbour(plans, a.patch, a.edge);
      if (f.part == PatchEdgePart::whole_beside_halves) {
        EXPECT_TRUE(e.part == PatchEdgePart::first_half || e.part == PatchEdgePart::second_half) << name;
        continue;
      }
      EXPECT_EQ(back.patch, p) << name;  // symmetric
      EXPECT_EQ(back.edge, k) << name;
      EXPECT_EQ(e.part == PatchEdgePart::whole, f.part == PatchEdgePart::whole) << name;
      if (e.part != PatchEdgePart::whole) {
        EXPECT_NE(e.part, f.part) << name;  // halves at the same end run opposite ways
      }
    }
  // Corners: owned by the lowest patch with the same corner point.
  std::map<int32_t, int> first;
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int c = 0; c < n; ++c) {
      const int32_t point = plans.patch_corner_points[size_t(n * p + c)];
      first.try_emplace(point, p);
      const int owner = plans.corner_owners[size_t(2 * (n * p + c))],
                corner = plans.corner_owners[size_t(2 * (n * p + c) + 1)];
      EXPECT_EQ(owner, first[point]) << name;
      EXPECT_EQ(plans.patch_corner_points[size_t(n * owner + corner)], point) << name;
    }
  EXPECT_GT(linked, 0) << name;
  std::printf("%-14s %5d patches: %5d linked edges, %3d whole quad edges beside halves\n", name.c_str(),
              plans.n_patches(), linked, t_junctions);
}

TEST(PatchAdjacency, EveryInnerEdgeHasItsNeighbourAndEveryCornerItsOwner) {
  for (const char* name : {"cube", "wirecube", "cylinder", "pawn", "icosphere", "cone", "grid", "valence5", "torus"})
    check_adjacency(name, make_sample(name));
  check_adjacency("open-cylinder", test::open_cylinder_mesh());
  check_adjacency("triangle-grid", test::triangle_grid_mesh(4, 3));
  check_adjacency("prism", test::prism_mesh());
}

// A T-junction of a quad and a split face: the quad's edge names both halves.
TEST(PatchAdjacency, CylinderCapsMeetTheSideQuadsHalfByHalf) {
  const CovarianceMesh mesh = make_sample("cylinder");
  const SurfaceTables tables = build_surface_plans(topology_of(mesh.mesh), PlanOptions{});
  int beside = 0;
  for (int p = 0; p < tables.plans.n_patches(); ++p)
    for (int k = 0; k < 4; ++k) beside += patch_edge(tables.plans, p, k).part == PatchEdgePart::whole_beside_halves;
  EXPECT_EQ(beside, 16);  // two octagons of 8 sides
}

}  // namespace
}  // namespace gps
