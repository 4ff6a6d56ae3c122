// Patch edge neighbours and corner owners (core/plans/patch_adjacency.h), the tables behind bit-exact
// shared edges on the GPU.
#include "core/plans/patch_adjacency.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>

#include "core/io/mesh_io.h"
#include "core/plans/planned_surface.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/fill.h"
#include "core/modelling/samples.h"
#include "tests/support/patch_edge_point.h"
#include "tests/support/plan_fixture.h"
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
  for (size_t e = 0; e < mesh.n_edges(); ++e)
    if (mesh.is_boundary_edge(e)) out.insert({mesh.edge(e)[0], mesh.edge(e)[1]});
  return out;
}

void check_adjacency(const std::string& name, const CovarianceMesh& mesh) {
  const SurfaceTables tables = build_surface_plans(mesh.topology(), PlanOptions{});
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
  // Limit curves: each named by one patch edge, the same for both sides and for itself: the whole
  // edge beside two halves, else the lower side (or the edge itself on the boundary).
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int k = 0; k < n; ++k) {
      const PatchEdgeSlot curve = curve_edge(plans, p, k), own{p, k};
      EXPECT_EQ(curve_edge(plans, curve.patch, curve.edge), curve) << name << " patch " << p << " edge " << k;
      const EdgeNeighbour a = edge_neighbour(plans, p, k, 0), b = edge_neighbour(plans, p, k, 1);
      const PatchEdgePart part = ends(plans, p, k).part;
      if (a.patch < 0 || part == PatchEdgePart::whole_beside_halves) {
        EXPECT_EQ(curve, own) << name << " patch " << p << " edge " << k;
        for (const EdgeNeighbour& h : {a, b})
          if (part == PatchEdgePart::whole_beside_halves) EXPECT_EQ(curve_edge(plans, h.patch, h.edge), own) << name;
        continue;
      }
      if (ends(plans, a.patch, a.edge).part == PatchEdgePart::whole_beside_halves) {
        EXPECT_EQ(curve, (PatchEdgeSlot{a.patch, a.edge})) << name << " patch " << p << " edge " << k;
        continue;
      }
      const PatchEdgeSlot across{a.patch, a.edge};
      const bool lower = std::make_pair(p, k) < std::make_pair(a.patch, a.edge);
      EXPECT_EQ(curve, lower ? own : across) << name << " patch " << p << " edge " << k;
      EXPECT_EQ(curve_edge(plans, a.patch, a.edge), curve) << name << " patch " << p << " edge " << k;
    }
  // Corners: owned by the lowest patch with the same corner point.
  std::map<int32_t, int> first;
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int c = 0; c < n; ++c) {
      const int32_t point = plans.patch_corner_points[size_t(n * p + c)];
      first.try_emplace(point, p);
      const CornerOwner owner = corner_owner(plans, p, c);
      EXPECT_EQ(owner.patch, first[point]) << name;
      EXPECT_EQ(plans.patch_corner_points[size_t(n * owner.patch + owner.corner)], point) << name;
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
  const SurfaceTables tables = build_surface_plans(mesh.topology(), PlanOptions{});
  int beside = 0;
  for (int p = 0; p < tables.plans.n_patches(); ++p)
    for (int k = 0; k < 4; ++k) beside += patch_edge(tables.plans, p, k).part == PatchEdgePart::whole_beside_halves;
  EXPECT_EQ(beside, 16);  // two octagons of 8 sides
}

Vec3 normal_at(const test::PlannedMesh& m, int patch, std::pair<double, double> uv) {
  const auto s = evaluate_patch(m.tables.plans, m.points, patch, uv.first, uv.second);
  EXPECT_TRUE(s.has_value()) << "patch " << patch;
  return s ? s->normal : Vec3::Zero();
}

struct SharpFlags {
  int edges = 0, corners = 0;              // flagged patch edges and corners
  int edges_apart = 0, corners_apart = 0;  // of those, where the sides' normals differ
};

// The flags against the CPU evaluator's normals: where an edge or corner is not flagged, the patches
// that meet there have one normal (so the canonical patch's serves all); where it is, they may differ.
SharpFlags check_sharp_flags(const std::string& name, const CovarianceMesh& mesh) {
  const test::PlannedMesh m(mesh, PlanOptions{});
  const PatchPlans& plans = m.tables.plans;
  const int n = plans.corners();
  SharpFlags out;
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int k = 0; k < n; ++k) {
      const EdgeNeighbour a = edge_neighbour(plans, p, k);
      if (a.patch < 0) continue;
      // A half beside a whole quad edge is compared from the whole edge's side, where the point at
      // fraction t lies on the half at its `from` end (t < ½) or `to` end at fraction 2t or 2t − 1.
      const bool beside_halves =
          plans.shape == PatchShape::quad && patch_edge(plans, p, k).part == PatchEdgePart::whole_beside_halves;
      if (plans.shape == PatchShape::quad &&
          patch_edge(plans, a.patch, a.edge).part == PatchEdgePart::whole_beside_halves)
        continue;
      out.edges += a.sharp;
      double apart = 0;
      for (const double t : {0.25, 0.5, 0.75}) {
        const EdgeNeighbour b = beside_halves ? edge_neighbour(plans, p, k, t < 0.5 ? 0 : 1) : a;
        const double along = beside_halves ? (t < 0.5 ? 2 * t : 2 * t - 1) : t;
        EXPECT_EQ(b.sharp, a.sharp) << name;
        EXPECT_EQ(edge_neighbour(plans, b.patch, b.edge).sharp, a.sharp) << name << ": the way back";
        const Vec3 mine = normal_at(m, p, test::edge_point(plans.shape, k, t));
        const Vec3 theirs =
            normal_at(m, b.patch, test::edge_point(plans.shape, b.edge, b.reversed ? 1 - along : along));
        apart = std::max(apart, (mine - theirs).norm());
      }
      if (!a.sharp) {
        EXPECT_LT(apart, 1e-6) << name << ": patch " << p << " edge " << k << " is not flagged";
      }
      out.edges_apart += a.sharp && apart > 1e-3;
    }
  std::map<int32_t, std::vector<std::pair<int, int>>> around;  // corner point -> (patch, corner)
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int c = 0; c < n; ++c) around[plans.patch_corner_points[size_t(n * p + c)]].emplace_back(p, c);
  const std::pair<double, double> corner_uv[4] = {
      {0, 0}, {1, 0}, n == 4 ? std::pair{1.0, 1.0} : std::pair{0.0, 1.0}, {0, 1}};
  for (const auto& [point, corners] : around) {
    const bool sharp = corner_owner(plans, corners[0].first, corners[0].second).sharp;
    double apart = 0;
    const Vec3 first = normal_at(m, corners[0].first, corner_uv[corners[0].second]);
    for (const auto& [p, c] : corners) {
      EXPECT_EQ(corner_owner(plans, p, c).sharp, sharp) << name << ": point " << point << " patch " << p;
      apart = std::max(apart, (normal_at(m, p, corner_uv[c]) - first).norm());
    }
    if (!sharp) {
      EXPECT_LT(apart, 1e-6) << name << ": point " << point << " is not flagged";
    }
    out.corners += sharp ? int(corners.size()) : 0;
    out.corners_apart += sharp && apart > 1e-3;
  }
  std::printf("%-16s %3d sharp patch edges (%3d with normals apart), %3d sharp patch corners (%2d points apart)\n",
              name.c_str(), out.edges, out.edges_apart, out.corners, out.corners_apart);
  return out;
}

TEST(PatchAdjacency, SharpFlagsMarkWhereTheSidesNormalsDiffer) {
  const auto file = [](const std::string& name) {
    return read_mesh(std::string(GPS_TEST_DATA_DIR) + "/" + name + ".ply");
  };
  // The cube's top rim: 4 edges, each on 2 patches; its 4 corners on 3 patches each.
  const SharpFlags cube = check_sharp_flags("creased_cube", file("creased_cube"));
  EXPECT_EQ(cube.edges, 8);
  EXPECT_EQ(cube.corners, 12);
  EXPECT_GT(cube.edges_apart, 0);
  EXPECT_EQ(cube.corners_apart, 4);
  // The top rim against the octagon's half-size patches: their edge points are sharp corners too.
  const SharpFlags cylinder = check_sharp_flags("creased_cylinder", file("creased_cylinder"));
  EXPECT_EQ(cylinder.edges, 8);  // counted on the side quads' whole edges
  EXPECT_GT(cylinder.edges_apart, 0);
  EXPECT_EQ(cylinder.corners_apart, 8);  // its rim vertices (an edge point has the top on both patches)
  const SharpFlags cone = check_sharp_flags("creased_cone", file("creased_cone"));  // Loop
  EXPECT_EQ(cone.edges, 4);
  EXPECT_GT(cone.corners_apart, 0);
  // A crease inside a grid that ends in two darts: its edges are flagged, the darts are not (the
  // surface is smooth there), and a smooth mesh has no flag at all.
  CovarianceMesh grid = test::grid_mesh(5, 5);
  const int middle = 2 * 6 + 2;
  grid.sharpness.set_crease(middle, middle + 1, kInfiniteSharpness);
  grid.sharpness.set_crease(middle + 1, middle + 2, kInfiniteSharpness);
  const SharpFlags darts = check_sharp_flags("grid with darts", grid);
  EXPECT_EQ(darts.edges, 4);
  EXPECT_EQ(darts.corners, 4);  // the crease vertex between them
  const SharpFlags smooth = check_sharp_flags("cube", make_sample("cube"));
  EXPECT_EQ(smooth.edges + smooth.corners, 0);
}

// Patches said to be kept beside a hole that a new face fills (and all others): the update links
// their boundary edges to the new face's patches, as a whole build links them.
TEST(PatchAdjacency, AnUpdateLinksKeptPatchesToNewOnesAsAWholeBuildDoes) {
  const CovarianceMesh cylinder = make_sample("cylinder");
  const auto first_patches = [](const PolygonTopology& t) {  // Catmull-Clark: one per quad, n per n-gon
    std::vector<int> first{0};
    for (int g = 0; g < t.n_faces(); ++g) first.push_back(first.back() + (t.face_size(g) == 4 ? 1 : t.face_size(g)));
    return first;
  };
  for (int f = 0; f < int(cylinder.n_faces()); ++f) {
    const std::span<const int> c = cylinder.face(size_t(f));
    const CovarianceMesh hole = delete_faces(cylinder, {f}).mesh;
    const Modelled filled = fill(hole, {c.begin(), c.end()});  // the hole's faces, then the new one
    const SurfaceTables before = build_surface_plans(hole, {}), after = build_surface_plans(filled.mesh, {});
    const std::vector<int> old_first = first_patches(hole.topology()),
                           new_first = first_patches(filled.mesh.topology());
    std::vector<int> new_of_old(size_t(before.plans.n_patches()), -1);
    for (int g = 0; g < int(hole.n_faces()); ++g)
      for (int i = old_first[size_t(g)]; i < old_first[size_t(g) + 1]; ++i)
        new_of_old[size_t(i)] = new_first[size_t(g)] + i - old_first[size_t(g)];
    PatchPlans updated = after.plans;
    ASSERT_TRUE(update_patch_adjacency(updated, {}, before.plans.patch_neighbours, new_of_old));
    EXPECT_EQ(updated.patch_neighbours, after.plans.patch_neighbours) << "face " << f;
    EXPECT_EQ(updated.corner_owners, after.plans.corner_owners) << "face " << f;
  }
}

// The same where every patch keeps its number and the storage holds the records of the tables two
// updates back: the hole's boundary edges, which the update before wrote none of, are linked to the
// new face's patches all the same, and the writes told say what the next update may rest on.
TEST(PatchAdjacency, AnUpdateThatKeepsNumbersLinksKeptBoundaryEdgesItDidNotWriteBefore) {
  const CovarianceMesh cylinder = make_sample("cylinder");
  for (int f = 0; f < int(cylinder.n_faces()); ++f) {
    const std::span<const int> c = cylinder.face(size_t(f));
    const CovarianceMesh hole = delete_faces(cylinder, {f}).mesh;
    const Modelled filled = fill(hole, {c.begin(), c.end()});  // the hole's faces in order, then the new one
    const SurfaceTables before = build_surface_plans(hole, {}), after = build_surface_plans(filled.mesh, {});
    const std::vector<KeptPatches> kept{{0, 0, before.plans.n_patches()}};
    // The hole's tables again, every patch kept: nothing written, the hole's edges a boundary.
    PatchPlans again = before.plans;
    AdjacencyWrites first, second;
    ASSERT_TRUE(update_patch_adjacency(again, {}, hole.connectivity(), before.plans, kept, nullptr, first));
    EXPECT_TRUE(first.numbers_kept && first.written.empty()) << "face " << f;
    EXPECT_EQ(first.boundary, boundary_records(before.plans)) << "face " << f;
    EXPECT_EQ(again.patch_neighbours, before.plans.patch_neighbours) << "face " << f;
    PatchPlans updated = after.plans;
    updated.patch_neighbours = before.plans.patch_neighbours;
    updated.corner_owners = before.plans.corner_owners;
    ASSERT_TRUE(update_patch_adjacency(updated, {}, filled.mesh.connectivity(), again, kept, &first, second));
    EXPECT_EQ(updated.patch_neighbours, after.plans.patch_neighbours) << "face " << f;
    EXPECT_EQ(updated.corner_owners, after.plans.corner_owners) << "face " << f;
    EXPECT_TRUE(second.numbers_kept) << "face " << f;
    EXPECT_EQ(second.boundary, boundary_records(after.plans)) << "face " << f;
    if (f + 1 == int(cylinder.n_faces())) {  // the last face: its patches go, every other keeps its number
      PatchPlans made = before.plans;
      AdjacencyWrites writes;
      ASSERT_TRUE(update_patch_adjacency(made, {}, hole.connectivity(), after.plans, kept, nullptr, writes));
      EXPECT_EQ(made.patch_neighbours, before.plans.patch_neighbours);
      EXPECT_FALSE(writes.written.empty());
      EXPECT_EQ(writes.boundary, boundary_records(before.plans));
    }
  }
}

// A mesh's last face moved to face 0's place, then to face 5's and back, face 0 and 5 left as holes:
// the patches of the other faces keep their numbers, and each move makes new patches at points that
// no gone patch had and takes gone ones from points that no new patch has. Each update, made in the
// storage of the tables two back with the writes of the one before, gives a whole build's records.
TEST(PatchAdjacency, UpdatesThatKeepNumbersFollowAFaceMovingAsWholeBuildsDo) {
  for (const std::string name : {"grid", "sphere", "icosphere"})  // one patch per face
    for (const bool creased : {false, true}) {  // face 1's edges infinitely sharp: flags to keep and to set
      const std::string where = name + (creased ? " creased" : "");
      const CovarianceMesh a = make_sample(name, 64);
      std::vector<std::vector<int>> faces;
      for (size_t f = 0; f < a.n_faces(); ++f) faces.emplace_back(a.face(f).begin(), a.face(f).end());
      const auto moved = [&](size_t to) {
        std::vector<std::vector<int>> f = faces;
        f[to] = f.back();
        f.pop_back();
        return f;
      };
      const std::vector<std::vector<std::vector<int>>> steps{faces, moved(0), moved(5), moved(0), moved(5)};
      std::vector<CovarianceMesh> meshes;
      std::vector<SurfaceTables> whole;
      for (const auto& f : steps) {
        CovarianceMesh m = make_covariance_mesh(a.means(), a.covariances, f, name);
        for (size_t k = 0; creased && k < faces[1].size(); ++k)
          m.sharpness.set_crease(faces[1][k], faces[1][(k + 1) % faces[1].size()], kInfiniteSharpness);
        whole.push_back(build_surface_plans(m, {}));
        meshes.push_back(std::move(m));
      }
      const auto kept_between = [&](size_t from, size_t to) {
        std::vector<KeptPatches> kept;
        for (size_t f = 0; f < std::min(steps[from].size(), steps[to].size()); ++f)
          if (steps[from][f] != steps[to][f])
            continue;
          else if (!kept.empty() && kept.back().first + kept.back().count == int(f))
            ++kept.back().count;
          else
            kept.push_back({int(f), int(f), 1});
        return kept;
      };
      const auto update = [&](PatchPlans& plans, size_t step, const PatchPlans& old, const AdjacencyWrites* held,
                              AdjacencyWrites& told) {
        return update_patch_adjacency(plans, meshes[step].sharpness, meshes[step].connectivity(), old,
                                      kept_between(step - 1, step), held, told);
      };
      // The first update links every record again (no storage to rest on), the next ones rest on it.
      std::vector<PatchPlans> made{whole[0].plans, whole[1].plans};
      std::vector<AdjacencyWrites> writes(1);
      ASSERT_TRUE(update(made[1], 1, whole[0].plans, nullptr, writes[0])) << where;
      EXPECT_EQ(made[1].patch_neighbours, whole[1].plans.patch_neighbours) << where;
      EXPECT_EQ(made[1].corner_owners, whole[1].plans.corner_owners) << where;
      for (size_t step = 2; step < steps.size(); ++step) {
        PatchPlans next = whole[step].plans;
        next.patch_neighbours = made[step - 2].patch_neighbours;
        next.corner_owners = made[step - 2].corner_owners;
        if (!writes.back().owners_written)  // owners the update may not rest on
          std::fill(next.corner_owners.begin(), next.corner_owners.end(), -7);
        AdjacencyWrites told;
        ASSERT_TRUE(update(next, step, made[step - 1], &writes.back(), told)) << where << " step " << step;
        EXPECT_EQ(next.patch_neighbours, whole[step].plans.patch_neighbours) << where << " step " << step;
        EXPECT_EQ(next.corner_owners, whole[step].plans.corner_owners) << where << " step " << step;
        EXPECT_TRUE(told.numbers_kept && told.owners_written) << where << " step " << step;
        made.push_back(std::move(next));
        writes.push_back(std::move(told));
      }
      int sharp_corners = 0;  // the flags are there to be kept
      for (size_t i = 1; i < made.back().corner_owners.size(); i += 2)
        sharp_corners += (made.back().corner_owners[i] & kOwnerSharpCorner) != 0;
      EXPECT_EQ(sharp_corners > 0, creased) << where;
    }
}

// A face taken out of a mesh, leaving a hole, and put back: the patches after it move down by one and
// back up. Each update renumbers the kept records and owners, and finds again those at the points of
// the face's patch, which the hole takes away from its neighbours and the face gives back: a whole
// build's records either way.
TEST(PatchAdjacency, UpdatesThatRenumberFollowAFaceTakenOutAndPutBackAsWholeBuildsDo) {
  for (const std::string name : {"grid", "sphere", "icosphere"})  // one patch per face
    for (const bool creased : {false, true}) {                    // face 1's edges infinitely sharp: flags to keep
      const CovarianceMesh a = make_sample(name, 64);
      std::vector<std::vector<int>> faces;
      for (size_t f = 0; f < a.n_faces(); ++f) faces.emplace_back(a.face(f).begin(), a.face(f).end());
      const auto mesh_of = [&](const std::vector<std::vector<int>>& f) {
        CovarianceMesh m = make_covariance_mesh(a.means(), a.covariances, f, name);
        for (size_t k = 0; creased && k < faces[1].size(); ++k)
          m.sharpness.set_crease(faces[1][k], faces[1][(k + 1) % faces[1].size()], kInfiniteSharpness);
        return m;
      };
      const CovarianceMesh whole_mesh = mesh_of(faces);
      const SurfaceTables whole = build_surface_plans(whole_mesh, {});
      const int n = int(faces.size());
      for (const int f : {0, 9, n / 2, n - 10}) {
        const std::string where = name + (creased ? " creased" : "") + " face " + std::to_string(f);
        std::vector<std::vector<int>> holed = faces;
        holed.erase(holed.begin() + f);
        const CovarianceMesh hole_mesh = mesh_of(holed);
        const SurfaceTables hole = build_surface_plans(hole_mesh, {});
        const std::vector<KeptPatches> out{{0, 0, f}, {f, f + 1, n - f - 1}}, back{{0, 0, f}, {f + 1, f, n - f - 1}};
        const auto runs = [](std::vector<KeptPatches> kept) {  // a run of no patches is none
          std::erase_if(kept, [](const KeptPatches& run) { return run.count == 0; });
          return kept;
        };
        PatchPlans taken = hole.plans, put = whole.plans;
        std::fill(taken.corner_owners.begin(), taken.corner_owners.end(), -7);
        std::fill(put.corner_owners.begin(), put.corner_owners.end(), -7);
        AdjacencyWrites told, told_back;
        ASSERT_TRUE(update_patch_adjacency(taken, hole_mesh.sharpness, hole_mesh.connectivity(), whole.plans, runs(out),
                                           nullptr, told))
            << where;
        EXPECT_EQ(taken.patch_neighbours, hole.plans.patch_neighbours) << where;
        EXPECT_EQ(taken.corner_owners, hole.plans.corner_owners) << where;
        EXPECT_EQ(told.numbers_kept, f == n - 1) << where;
        ASSERT_TRUE(update_patch_adjacency(put, whole_mesh.sharpness, whole_mesh.connectivity(), taken, runs(back),
                                           &told, told_back))
            << where;
        EXPECT_EQ(put.patch_neighbours, whole.plans.patch_neighbours) << where;
        EXPECT_EQ(put.corner_owners, whole.plans.corner_owners) << where;
      }
    }
}

}  // namespace
}  // namespace gps
