#include "core/reference/reference_subdivision.h"

#include <algorithm>

#include "core/reference/catmull_clark.h"
#include "core/reference/catmull_clark_connectivity.h"
#include "core/reference/crease_rules.h"
#include "core/reference/loop_connectivity.h"
#include "core/mesh/dual_map.h"
#include "core/support/error.h"
#include "core/reference/limit_masks.h"
#include "core/reference/limit_tangents.h"
#include "core/reference/subdivision_size.h"

namespace gps {

namespace {

// Where each face corner sits in the patch layout; patch −1 − p marks a corner of a base face that
// is split into patches p, p+1, … (core/plans/patch_layout.h), which begin only after the first step.
using CornerParams = std::vector<PatchParam>;

CornerParams base_corner_params(const PolygonTopology& t) {
  CornerParams params(t.verts.size());
  int patch = 0;
  for (int f = 0; f < t.n_faces(); ++f) {
    const int o = t.offsets[size_t(f)], n = t.face_size(f);
    if (n == 4) {
      const double us[4] = {0, 1, 1, 0}, vs[4] = {0, 0, 1, 1};
      for (int k = 0; k < 4; ++k) params[size_t(o + k)] = {patch, us[k], vs[k]};
      patch += 1;
    } else {
      for (int k = 0; k < n; ++k) params[size_t(o + k)] = {-1 - (patch + k), 0, 0};
      patch += n;
    }
  }
  return params;
}

PatchParam midpoint(const PatchParam& a, const PatchParam& b) {
  return {a.patch, 0.5 * (a.u + b.u), 0.5 * (a.v + b.v)};
}

// Corner params of the children, in catmull_clark_topology() order: put(i, param) for child corner i.
template <class Put>
void refine_corner_params(const PolygonTopology& t, const CornerParams& params, Put put) {
  size_t i = 0;
  for (int f = 0; f < t.n_faces(); ++f) {
    const int o = t.offsets[size_t(f)], n = t.face_size(f);
    const PatchParam* p = &params[size_t(o)];
    if (p[0].patch < 0) {  // an n-gon's child k is patch k of the face
      for (int k = 0; k < n; ++k) {
        const int patch = -1 - p[k].patch;
        for (const PatchParam& q : {PatchParam{patch, 0, 0}, {patch, 1, 0}, {patch, 1, 1}, {patch, 0, 1}}) put(i++, q);
      }
      continue;
    }
    const PatchParam centre = {p[0].patch, 0.25 * (p[0].u + p[1].u + p[2].u + p[3].u),
                               0.25 * (p[0].v + p[1].v + p[2].v + p[3].v)};
    for (int k = 0; k < 4; ++k)
      for (const PatchParam& q : {p[k], midpoint(p[k], p[(k + 1) % 4]), centre, midpoint(p[(k + 3) % 4], p[k])})
        put(i++, q);
  }
}

bool all_triangles(const PolygonTopology& t) {
  for (int f = 0; f < t.n_faces(); ++f)
    if (t.face_size(f) != 3) return false;
  return true;
}

// Loop: face f is patch f, its corners at (0,0), (1,0), (0,1) (core/plans/loop_plan_builder.h).
CornerParams loop_base_corner_params(const PolygonTopology& t) {
  CornerParams params(t.verts.size());
  for (int f = 0; f < t.n_faces(); ++f) {
    const int o = t.offsets[size_t(f)];
    params[size_t(o)] = {f, 0, 0};
    params[size_t(o + 1)] = {f, 1, 0};
    params[size_t(o + 2)] = {f, 0, 1};
  }
  return params;
}

// Corner params of the Loop children, in loop_topology() order: put(i, param) for child corner i.
template <class Put>
void refine_loop_corner_params(const PolygonTopology& t, const CornerParams& params, Put put) {
  size_t i = 0;
  for (int f = 0; f < t.n_faces(); ++f) {
    const PatchParam* p = &params[size_t(t.offsets[size_t(f)])];
    const PatchParam m01 = midpoint(p[0], p[1]), m12 = midpoint(p[1], p[2]), m20 = midpoint(p[2], p[0]);
    for (const PatchParam& q : {p[0], m01, m20, p[1], m12, m01, p[2], m20, m12, m01, m12, m20}) put(i++, q);
  }
}

// A vertex takes the param of its last corner, the split base faces' marks undone.
void put_vertex_param(std::vector<PatchParam>& vertex_params, int v, PatchParam p) {
  if (p.patch < 0) p.patch = -1 - p.patch;
  vertex_params[size_t(v)] = p;
}

std::vector<PatchParam> vertex_params_of(const PolygonTopology& t, const CornerParams& params) {
  std::vector<PatchParam> out(size_t(t.n_vertices));
  for (size_t i = 0; i < t.verts.size(); ++i) put_vertex_param(out, t.verts[i], params[i]);
  return out;
}

// One level of params from `coarse` to `fine` by refine(coarse, params, put): the corners' params,
// or at the last level straight the vertices' (the finest corners' array would only feed them,
// unless `keep_corners` asks for it too).
template <class Refine>
void refine_params(const PolygonTopology& coarse, const PolygonTopology& fine, bool last, bool keep_corners,
                   CornerParams& params, std::vector<PatchParam>& vertex_params, Refine refine) {
  if (last && !keep_corners) {
    vertex_params.assign(size_t(fine.n_vertices), PatchParam{});
    refine(coarse, params, [&](size_t i, const PatchParam& p) { put_vertex_param(vertex_params, fine.verts[i], p); });
    return;
  }
  CornerParams out(fine.verts.size());
  refine(coarse, params, [&](size_t i, const PatchParam& p) { out[i] = p; });
  params = std::move(out);
  if (last) vertex_params = vertex_params_of(fine, params);
}

// The mesh after N levels, its values before any limit, and the sharpness left on it.
template <class T>
struct Refined {
  PolygonTopology topology;
  MeshConnectivity connectivity;
  std::vector<T> values;
  CreaseLevel creases;
};

// With `corner_params`, the finest corners' params go there too (patch marks undone). The
// sharpness applies level by level and decays as it goes (core/reference/crease_rules.h).
template <class T>
Refined<T> refine(const PolygonTopology& base, std::vector<T> p, const Sharpness& sharpness,
                  const SubdivisionOptions& o, std::vector<PatchParam>* vertex_params,
                  std::vector<PatchParam>* corner_params = nullptr) {
  if (o.levels < 0 || o.levels > 8)
    throw usage_error("subdivision levels must be 0..8, got " + std::to_string(o.levels));
  PolygonTopology t = base;
  MeshConnectivity c = connectivity_of(t);
  CreaseLevel creases;
  if (!sharpness.empty()) creases = crease_level(sharpness, c, t.n_vertices);
  CornerParams params;
  if (vertex_params) params = o.scheme == Scheme::loop ? loop_base_corner_params(base) : base_corner_params(base);
  if (vertex_params && o.levels == 0) *vertex_params = vertex_params_of(t, params);
  for (int level = 0; level < o.levels; ++level) {
    const bool last = level + 1 == o.levels;
    if (o.scheme == Scheme::catmull_clark) {
      p = catmull_clark_values(t, c, p, &creases);
      MeshConnectivity finer_connectivity = catmull_clark_connectivity(t, c);
      PolygonTopology finer = catmull_clark_topology(t, c);
      creases = refined_crease_level(t, c, creases, finer_connectivity);
      if (vertex_params)
        refine_params(t, finer, last, corner_params, params, *vertex_params,
                      [](const auto&... a) { refine_corner_params(a...); });
      t = std::move(finer);
      c = std::move(finer_connectivity);
    } else {
      p = loop_values(t, c, p, o.loop_beta, &creases);
      PolygonTopology finer = loop_topology(t, c);  // throws where a face is not a triangle
      MeshConnectivity finer_connectivity = loop_connectivity(t, c);
      creases = refined_crease_level(t, c, creases, finer_connectivity);
      if (vertex_params)
        refine_params(t, finer, last, corner_params, params, *vertex_params,
                      [](const auto&... a) { refine_loop_corner_params(a...); });
      t = std::move(finer);
      c = std::move(finer_connectivity);
    }
  }
  if (vertex_params && corner_params) {
    for (PatchParam& q : params)
      if (q.patch < 0) q.patch = -1 - q.patch;
    *corner_params = std::move(params);
  }
  return {std::move(t), std::move(c), std::move(p), std::move(creases)};
}

// Each vertex's final value, its limit position or its refined value, handed to put(v, value) as it
// is made (from all cores for a large mesh): no array of limits is kept.
template <class T>
void put_final_values(const Refined<T>& r, const SubdivisionOptions& o, const PutLimit<T>& put) {
  const PolygonTopology& t = r.topology;
  const MeshConnectivity& c = r.connectivity;
  if (!o.limit) {
#pragma omp parallel for if (t.n_vertices >= kParallelFaces)
    for (int v = 0; v < t.n_vertices; ++v) put(v, r.values[size_t(v)]);
  } else if (o.scheme == Scheme::loop) {
    if (o.levels == 0) loop_topology(t, c);  // refuses non-triangle meshes
    loop_limit(t, c, r.values, o.loop_beta, put, &r.creases);
  } else if (all_quads(t)) {
    catmull_clark_limit(t, c, r.values, t.n_vertices, put, &r.creases);
  } else {
    // A vertex's limit is that of its vertex point one level down, where every face is a quad.
    const MeshConnectivity finer = catmull_clark_connectivity(t, c);
    const CreaseLevel finer_creases = refined_crease_level(t, c, r.creases, finer);
    catmull_clark_limit(catmull_clark_topology(t, c), finer, catmull_clark_values(t, c, r.values, &r.creases),
                        t.n_vertices, put, &finer_creases);
  }
}

// Zeroes the tangents of the vertices whose rule the sharpness changes: a crease or corner has a
// tangent plane on each side of it (one-sided normals), which no single pair of masks gives.
void drop_sharp_tangents(const MeshConnectivity& c, const CreaseLevel& creases, int n, std::vector<Dual>& first,
                         std::vector<Dual>& second) {
  if (creases.empty()) return;
  const CreaseLevel none;
  for (int v = 0; v < n; ++v) {
    const VertexRule rule = vertex_rule(c, creases, v);
    if ((rule == VertexRule::crease || rule == VertexRule::corner) && rule != vertex_rule(c, none, v)) {
      first[size_t(v)].setZero();
      second[size_t(v)].setZero();
    }
  }
}

// The limit tangents q_u, q_v of every vertex (core/reference/limit_tangents.h), where put_final_values
// takes its limits: on the refined mesh, or one Catmull-Clark step down where it has other faces
// than quads (a vertex's tangent plane is that of its vertex point).
void limit_tangents_of(const Refined<Dual>& r, const SubdivisionOptions& o, std::vector<Dual>& first,
                       std::vector<Dual>& second) {
  const PolygonTopology& t = r.topology;
  const MeshConnectivity& c = r.connectivity;
  if (o.scheme == Scheme::loop || all_quads(t)) {
    limit_tangents(t, c, r.values, o.scheme == Scheme::loop, first, second, &r.creases, o.loop_beta);
    drop_sharp_tangents(c, r.creases, t.n_vertices, first, second);
    return;
  }
  const MeshConnectivity finer = catmull_clark_connectivity(t, c);
  const CreaseLevel finer_creases = refined_crease_level(t, c, r.creases, finer);
  limit_tangents(catmull_clark_topology(t, c), finer, catmull_clark_values(t, c, r.values, &r.creases), false, first,
                 second, &finer_creases);
  drop_sharp_tangents(finer, finer_creases, t.n_vertices, first, second);
  first.resize(size_t(t.n_vertices));
  second.resize(size_t(t.n_vertices));
}

}  // namespace

SubdivisionResult subdivide(const CovarianceMesh& mesh, const SubdivisionOptions& options) {
  const PolygonTopology& base = mesh.topology();
  // Loop on a mesh that is not all triangles is refused below, naming the face.
  if (options.scheme != Scheme::loop || all_triangles(base))
    check_output_size(subdivision_size(mesh, options),
                      std::to_string(options.levels) + (options.levels == 1 ? " level" : " levels") + " of " +
                          (options.scheme == Scheme::loop ? "Loop" : "Catmull-Clark") + " subdivision",
                      "faces", "use fewer levels");
  SubdivisionResult result;
  const bool with_params = options.scheme == Scheme::catmull_clark || all_triangles(base);
  const bool with_normals = options.normals && options.limit;
  // Evaluated about the mesh's evaluation origin, each mean moved back as it is mapped back.
  const Vec3 origin = evaluation_origin(mesh);
  Refined<Dual> r =
      refine(base, base_points(mesh, origin), mesh.sharpness, options, with_params ? &result.vertex_params : nullptr,
             with_normals ? &result.corner_params : nullptr);
  std::vector<Dual> first, second;  // limit tangents, with_normals
  if (with_normals) {
    limit_tangents_of(r, options, first, second);
    result.normals.resize(size_t(r.topology.n_vertices));
  }

  // Each Gaussian is mapped back as its value is made; the refined faces and their connectivity
  // become the mesh's own.
  const int n = r.topology.n_vertices;
  std::vector<Vec3> means(static_cast<size_t>(n));
  std::vector<Mat3> covariances(static_cast<size_t>(n));
  int first_invalid = n;
  put_final_values<Dual>(r, options, [&](int v, const Dual& q) {
    const auto g = from_dual(q);
    if (!g) {
#pragma omp critical
      first_invalid = std::min(first_invalid, v);
      return;
    }
    means[size_t(v)] = g->mean + origin;
    covariances[size_t(v)] = g->covariance;
    if (with_normals) result.normals[size_t(v)] = limit_normal(q, g->mean, first[size_t(v)], second[size_t(v)]);
  });
  if (first_invalid < n)
    throw Error("subdivided vertex " + std::to_string(first_invalid) + " left the cone of positive definite matrices");
  if (options.levels == 0 && !options.limit) {  // the mesh's own Gaussians, not their round trip through 9D
    means = mesh.means();
    covariances = mesh.covariances;
  }
  Sharpness sharpness = sharpness_of(r.connectivity, r.creases);
  result.mesh = make_covariance_mesh(std::move(means), std::move(covariances), std::move(r.topology),
                                     std::move(r.connectivity), "subdivided mesh");
  result.mesh.sharpness = std::move(sharpness);
  return result;
}

std::vector<Vec3> subdivide_points(const CovarianceMesh& mesh, const SubdivisionOptions& options) {
  std::vector<Vec3> points(mesh.n_vertices());
  for (size_t i = 0; i < points.size(); ++i) points[i] = mesh.mean(i);
  const Refined<Vec3> r = refine(mesh.topology(), points, mesh.sharpness, options, nullptr);
  points.resize(size_t(r.topology.n_vertices));
  put_final_values<Vec3>(r, options, [&](int v, const Vec3& p) { points[size_t(v)] = p; });
  return points;
}

}  // namespace gps
