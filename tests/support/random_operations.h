#pragma once
// Random modelling operations of every kind on quad, triangle, mixed, open and creased meshes: the
// incremental re-planning tests (tests/core/test_incremental_plans.cpp), the renderer's that follow
// them (tests/render/test_incremental_gpu_buffers.cpp) and the undo's (tests/core/test_mesh_delta.cpp).
#include <random>
#include <string>

#include "core/modelling/affine_transform.h"
#include "core/modelling/bevel.h"
#include "core/modelling/bisect.h"
#include "core/modelling/bridge.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/duplicate.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/extrude.h"
#include "core/modelling/fill.h"
#include "core/modelling/grid_fill.h"
#include "core/modelling/inset.h"
#include "core/modelling/knife.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/mirror.h"
#include "core/modelling/primitives.h"
#include "core/modelling/samples.h"
#include "core/modelling/slide.h"
#include "core/modelling/spin.h"
#include "core/modelling/split_faces.h"
#include "core/modelling/subdivide_mesh.h"
#include "core/plans/plan_builder.h"
#include "core/support/error.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/test_meshes.h"

namespace gps::test {

struct RandomOperationCase {
  std::string name;
  CovarianceMesh mesh;
  Scheme scheme;
  int operations = 14;  // fewer for Loop, whose full re-plans build their exact tables afresh
};

inline CovarianceMesh creased(CovarianceMesh m, double sharpness) {
  const MeshConnectivity& c = m.connectivity();
  for (int e = 0; e < c.n_edges(); e += 7)
    m.sharpness.set_crease(c.edge_verts[2 * size_t(e)], c.edge_verts[2 * size_t(e) + 1], sharpness);
  return m;
}

inline std::vector<RandomOperationCase> random_operation_cases() {
  return {{"sphere (closed quads)", make_sample("sphere", 400), Scheme::catmull_clark},
          {"grid (open quads, creased)", creased(grid_mesh(8, 6), 2.0), Scheme::catmull_clark},
          {"cylinder (quads and octagons)", make_sample("cylinder"), Scheme::catmull_clark},
          {"cube (creased infinitely)", creased(cube_mesh(), kInfiniteSharpness), Scheme::catmull_clark},
          {"icosphere (triangles, creased)", creased(make_sample("icosphere", 300), 1.5), Scheme::loop, 8},
          {"triangle grid (open triangles, creased)", creased(triangle_grid_mesh(5, 4), kInfiniteSharpness),
           Scheme::loop, 8},
          {"icosphere (smooth triangles)", make_sample("icosphere", 320), Scheme::loop, 8},
          {"triangle grid (open triangles, smooth)", triangle_grid_mesh(12, 10), Scheme::loop, 8}};
}

// The kinds of operation random_operation picks from: the first `kBasicOperations` are those the
// editor's users reach for most (extrude, inset, loop cut, ...), the rest every other operation.
inline constexpr int kBasicOperations = 15, kOperationKinds = 37;

// `second`, made from `first`'s mesh, told as made from the mesh `first` was made from.
inline Modelled followed_by(const Modelled& first, Modelled second) {
  if (!first.vertex_origin.empty() && !second.vertex_origin.empty())
    for (int& o : second.vertex_origin)
      if (o >= 0) o = first.vertex_origin[size_t(o)];
  if (second.vertex_origin.empty()) second.vertex_origin = first.vertex_origin;
  second.summary = first.summary + "; " + second.summary;
  return second;
}

// A point inside face f: `towards` of the way from its centroid to its corner k.
inline Vec3 point_in_face(const CovarianceMesh& m, int f, int k, double towards) {
  const std::span<const int> corners = m.face(size_t(f));
  Vec3 centroid = Vec3::Zero();
  for (const int v : corners) centroid += m.mean(size_t(v)) / double(corners.size());
  return centroid + towards * (m.mean(size_t(corners[size_t(k) % corners.size()])) - centroid);
}

// Operation `kind` (0 .. kOperationKinds − 1) on `m` about random elements; throws gps::Error where the
// operation refuses. An operation that doubles the mesh or more is refused here past a few hundred
// faces, so that a sequence stays small.
inline Modelled operation_of_kind(const CovarianceMesh& m, int kind, std::mt19937& random) {
  const PolygonTopology& t = m.topology();
  const MeshConnectivity& c = m.connectivity();
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
  const int f = pick(t.n_faces()), e = pick(c.n_edges()), v = pick(t.n_vertices);
  const int a = c.edge_verts[2 * size_t(e)], b = c.edge_verts[2 * size_t(e) + 1];
  const double sharpness[] = {0.0, 1.0, 2.5, kInfiniteSharpness};
  BevelOptions bevel;
  bevel.width = 0.02;
  bevel.segments = 1 + pick(2);
  const auto small = [&] {
    if (m.n_faces() > 400) throw Error("the mesh is too large for an operation that doubles it");
  };
  // A boundary loop, where the mesh has one.
  const auto boundary = [&] {
    const std::vector<std::vector<int>> loops = boundary_loops(m);
    if (loops.empty()) throw Error("the mesh has no boundary");
    return loops[size_t(pick(int(loops.size())))];
  };
  const std::span<const int> corners = m.face(size_t(f));
  // Every draw a statement of its own: the order of a call's arguments is the compiler's, and one
  // stream of draws must give every build the same operations.
  const int nx = pick(3), ny = pick(3);
  const Vec3 normal(1.0 + nx, -1.0 + ny, 0.5);
  switch (kind) {
    case 0:
      return extrude_faces(m, {f}, 0.05);
    case 1:
      return inset_faces(m, {f}, 0.01);
    case 2:
      return loop_cut(m, a, b, 1 + pick(2));
    case 3:
      return subdivide_faces(m, {f});
    case 4:
      return delete_faces(m, {f});
    case 5:
      return merge_vertices(m, {a, b}, MergePoint::center);
    case 6:
      return split_edge(m, a, b);
    case 7:
      return bevel_edges(m, {{a, b}}, bevel);
    case 8:
      return dissolve_edges(m, {{a, b}});
    case 9:
      return set_crease(m, {{a, b}}, sharpness[pick(4)]);
    case 10:
      return set_corner(m, {v}, sharpness[pick(4)]);
    case 11:
      return delete_vertices(m, {v});
    case 12:
      return add_primitive(m, Primitive::cube, Vec3(3, 0, 0), 0.5);
    case 13:  // Gaussians moved, the topology kept
      return transform_vertices(m, {v, a}, AffineMap::about(m.mean(size_t(v)), 0.8 * Mat3::Identity()));
    case 14:
      return extrude_faces(m, {f, (f + 1) % t.n_faces()}, -0.02);
    case 15: {
      const double factor = pick(2) ? 0.4 : -0.4;
      const bool even = pick(2) == 0;
      return edge_slide(m, {{a, b}}, factor, even);
    }
    case 16:
      return vertex_slide(m, a, b, 0.3);
    case 17: {
      small();
      const int axis = pick(3);
      const bool merge = pick(2) == 0;
      return mirror(m, axis, m.mean(size_t(v)), merge);
    }
    case 18: {  // from a boundary edge where there is one (an edge with faces on both sides is refused)
      const int steps = 1 + pick(3);
      const std::vector<std::vector<int>> loops = boundary_loops(m);
      const std::vector<int> profile =
          loops.empty() ? std::vector<int>{a, b} : std::vector<int>{loops[0][0], loops[0][1]};
      return spin(m, profile, Vec3(0, 0, 1), m.mean(size_t(v)) + Vec3(0.5, 0, 0), 90.0, steps);
    }
    case 19:
      return bisect(m, m.mean(size_t(v)), normal);
    case 20:
      return bridge_faces(m, {f, pick(t.n_faces())});
    case 21:
      return fill_selected(m, boundary());
    case 22: {
      const std::vector<int> loop = boundary();
      const int span = pick(3), offset = pick(3);
      return grid_fill_selected(m, loop, span, offset);
    }
    case 23:
      return duplicate_faces(m, {f, (f + 1) % t.n_faces()}, Vec3(0.1, 0.2, 0.3));
    case 24:
      return split_faces(m, {f});
    case 25:
      return flip_edge(m, a, b);
    case 26:  // across one face, from near one corner to near the one opposite
      return knife(m, {point_in_face(m, f, 0, 0.5), point_in_face(m, f, int(corners.size()) / 2, 0.5)});
    case 27:  // across two neighbouring faces
      return knife(m, {point_in_face(m, f, 0, 0.3), point_in_face(m, c.edge_faces[2 * size_t(e)], 0, 0.3),
                       point_in_face(m, std::max(c.edge_faces[2 * size_t(e) + 1], 0), 1, 0.3)});
    case 28:
      return bevel_vertices(m, {v}, bevel);
    case 29: {  // a boundary edge
      const std::vector<int> loop = boundary();
      return extrude_edges(m, {{loop[0], loop[1]}}, Vec3(0, 0.1, 0.05));
    }
    case 30:  // a face's corners (its extrusion), or an edge's ends (on a boundary, the edge's)
      return extrude_vertices(m, pick(2) ? std::vector<int>(corners.begin(), corners.end()) : std::vector<int>{a, b},
                              Vec3(0.1, 0, 0));
    case 31:
      return dissolve_vertices(m, {v});
    case 32:
      return delete_edges(m, {{a, b}});
    case 33:
      return weld_by_distance(m, {a, b, v}, 0.6 * (m.mean(size_t(a)) - m.mean(size_t(b))).norm());
    case 34:
      small();
      return subdivide_all(m);
    case 35: {
      const double degrees = 20.0 + pick(40), to = sharpness[1 + pick(3)];
      return crease_sharp_edges(m, degrees, to);
    }
    default: {  // two faces deleted and the holes they leave bridged
      const Modelled holes = delete_faces(m, {f, pick(t.n_faces())});
      const std::vector<std::vector<int>> loops = boundary_loops(holes.mesh);
      if (loops.size() < 2) throw Error("the faces deleted left fewer than two holes");
      std::vector<int> selected = loops[loops.size() - 2];
      selected.insert(selected.end(), loops.back().begin(), loops.back().end());
      return followed_by(holes, bridge_selected(holes.mesh, selected));
    }
  }
}

// One random operation on `m`: one of the basic kinds as often as all the others together.
inline Modelled random_operation(const CovarianceMesh& m, std::mt19937& random) {
  const int kind = std::uniform_int_distribution<int>(0, 2 * kBasicOperations - 1)(random);
  return operation_of_kind(m,
                           kind < kBasicOperations
                               ? kind
                               : std::uniform_int_distribution<int>(kBasicOperations, kOperationKinds - 1)(random),
                           random);
}

}  // namespace gps::test
