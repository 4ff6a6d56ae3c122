#pragma once
// Random modelling operations of every kind on quad, triangle, mixed, open and creased meshes: the
// incremental re-planning tests (tests/core/test_incremental_plans.cpp) and the renderer's that follow
// them (tests/render/test_incremental_gpu_buffers.cpp).
#include <random>
#include <string>

#include "core/modelling/affine_transform.h"
#include "core/modelling/bevel.h"
#include "core/modelling/crease_edges.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/extrude.h"
#include "core/modelling/inset.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/primitives.h"
#include "core/modelling/samples.h"
#include "core/modelling/subdivide_mesh.h"
#include "core/plans/plan_builder.h"
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

// One random operation on `m` (extrude, inset, loop cut, subdivide, delete faces or vertices, merge,
// split, bevel, dissolve, crease, corner, a primitive added, a transform of two vertices); throws gps::Error where the
// operation refuses.
inline Modelled random_operation(const CovarianceMesh& m, std::mt19937& random) {
  const PolygonTopology& t = m.topology();
  const MeshConnectivity& c = m.connectivity();
  const auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
  const int f = pick(t.n_faces()), e = pick(c.n_edges()), v = pick(t.n_vertices);
  const int a = c.edge_verts[2 * size_t(e)], b = c.edge_verts[2 * size_t(e) + 1];
  const double sharpness[] = {0.0, 1.0, 2.5, kInfiniteSharpness};
  BevelOptions bevel;
  bevel.width = 0.02;
  bevel.segments = 1 + pick(2);
  switch (pick(15)) {
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
    default:
      return extrude_faces(m, {f, (f + 1) % t.n_faces()}, -0.02);
  }
}

}  // namespace gps::test
