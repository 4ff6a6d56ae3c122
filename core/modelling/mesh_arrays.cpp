#include "core/modelling/mesh_arrays.h"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "core/io/mesh_repair.h"
#include "core/support/error.h"
#include "core/support/hash_mix.h"
#include "core/mesh/face_area.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/modelling/operation_words.h"
#include "core/plans/plan_builder.h"

namespace gps {

namespace {

// The sharpness of the arrays on the faces of `mesh` (made from them): creases on edges, corners on vertices.
Sharpness sharpness_on_edges(const MeshArrays& a, const CovarianceMesh& mesh) {
  if (a.sharpness.empty()) return {};
  Sharpness out;
  for (const EdgeCrease& c : a.sharpness.creases)
    if (c.a >= 0 && size_t(c.b) < mesh.n_vertices() && mesh.find_edge(c.a, c.b) >= 0) out.creases.push_back(c);
  out.corners = a.sharpness.corners;
  if (!out.corners.empty()) out.corners.resize(mesh.n_vertices(), 0.0);
  out.normalise();
  return out;
}

// The face lists of the largest arrays destroyed last on this thread, for arrays_of to fill again;
// those of a mesh past kSpareFaces faces are freed, so that what a thread holds stays bounded.
thread_local std::vector<std::vector<int>> spare_faces;
constexpr size_t kSpareFaces = size_t(1) << 21;

}  // namespace

MeshArrays::~MeshArrays() {
  if (faces.size() >= spare_faces.size() && faces.size() <= kSpareFaces) spare_faces = std::move(faces);
}

int MeshArrays::add_vertex(const Gaussian& g) {
  if (origin.size() == means.size()) origin.push_back(-1);
  means.push_back(g.mean);
  covariances.push_back(g.covariance);
  if (!sharpness.corners.empty()) sharpness.corners.resize(means.size(), 0.0);
  return int(means.size()) - 1;
}

MeshArrays arrays_of(const CovarianceMesh& m) {
  MeshArrays a;
  // Room for the vertices an operation adds, so that adding one does not copy every Gaussian.
  const size_t n = m.n_vertices(), room = n + n / 16 + 64;
  a.means.reserve(room);
  a.covariances.reserve(room);
  a.means.resize(n);  // Eigen's fixed-size matrices are left unset by their constructor: no pass here
  a.covariances.resize(n);
  // Copied a block at a time on all cores: one core does not draw the memory's bandwidth.
  constexpr int kBlocks = 64;
#pragma omp parallel for schedule(static) if (n >= size_t(kParallelFaces))
  for (int b = 0; b < kBlocks; ++b) {
    const size_t first = n * size_t(b) / kBlocks, last = n * size_t(b + 1) / kBlocks;
    std::copy(m.means().begin() + ptrdiff_t(first), m.means().begin() + ptrdiff_t(last),
              a.means.begin() + ptrdiff_t(first));
    std::copy(m.covariances.begin() + ptrdiff_t(first), m.covariances.begin() + ptrdiff_t(last),
              a.covariances.begin() + ptrdiff_t(first));
  }
  a.sharpness = m.sharpness;
  a.origin.resize(m.n_vertices());
  std::iota(a.origin.begin(), a.origin.end(), 0);
  a.face_origin.resize(m.n_faces());
  std::iota(a.face_origin.begin(), a.face_origin.end(), 0);
  const PolygonTopology& t = m.topology();
  a.faces.swap(spare_faces);
  a.faces.resize(size_t(t.n_faces()));
#pragma omp parallel for schedule(static) if (t.n_faces() >= kParallelFaces)
  for (int f = 0; f < t.n_faces(); ++f)
    a.faces[size_t(f)].assign(t.verts.begin() + t.offsets[size_t(f)], t.verts.begin() + t.offsets[size_t(f) + 1]);
  return a;
}

namespace {

// The arrays' faces on these Gaussians, built and checked whole.
CovarianceMesh built_whole(const MeshArrays& a, const std::vector<Vec3>& means, const std::vector<Mat3>& covariances) {
  if (a.faces.empty()) throw Error("the result would have no faces");
  try {
    CovarianceMesh m = make_covariance_mesh(means, covariances, a.faces, "the result would not be a valid mesh");
    validate_gaussians(m, "the result would not be a valid mesh");
    m.sharpness = sharpness_on_edges(a, m);
    return m;
  } catch (const Error& e) {
    throw Error(e.what());
  }
}

// build_mesh for arrays made from `before`, their Gaussians given apart (copied, or taken over).
CovarianceMesh built_from(const MeshArrays& a, std::vector<Vec3>&& means, std::vector<Mat3>&& covariances,
                          const CovarianceMesh& before) {
  if (a.faces.empty()) throw Error("the result would have no faces");
  const std::vector<int> origin = a.origin.size() == means.size() ? a.origin : std::vector<int>{};
  if (origin.empty()) return built_whole(a, means, covariances);
  const char* const source = "the result would not be a valid mesh";
  try {
    CovarianceMesh m = make_covariance_mesh(before, std::move(means), std::move(covariances), polygon_topology(a.faces),
                                            {origin, a.face_origin}, source);
    // The Gaussians that are new or changed, on all cores; the others were checked when `before` was made.
    const long long n = (long long)m.n_vertices();
    bool problem = false;
#pragma omp parallel for schedule(static) reduction(|| : problem) if (n >= kParallelFaces)
    for (long long v = 0; v < n; ++v) {
      const int o = origin[size_t(v)];
      const bool same = o >= 0 && size_t(o) < before.n_vertices() &&
                        std::memcmp(&m.mean(size_t(v)), &before.mean(size_t(o)), sizeof(Vec3)) == 0 &&
                        std::memcmp(&m.covariance(size_t(v)), &before.covariance(size_t(o)), sizeof(Mat3)) == 0;
      problem = problem || (!same && !(position_problem(m.mean(size_t(v))).empty() &&
                                       covariance_problem(m.covariance(size_t(v))).empty()));
    }
    if (problem) validate_gaussians(m, source);  // names the first vertex with a problem, as build_mesh does
    m.sharpness = sharpness_on_edges(a, m);
    return m;
  } catch (const Error& e) {
    throw Error(e.what());
  }
}

}  // namespace

CovarianceMesh build_mesh(const MeshArrays& a) { return built_whole(a, a.means, a.covariances); }

CovarianceMesh build_mesh(const MeshArrays& a, const CovarianceMesh& before) {
  return built_from(a, std::vector<Vec3>(a.means), std::vector<Mat3>(a.covariances), before);
}

void check_gaussians(const MeshArrays& a, const std::vector<int>& vertices) {
  for (const int v : vertices) {
    std::string why = position_problem(a.means[size_t(v)]);
    if (why.empty()) why = covariance_problem(a.covariances[size_t(v)]);
    if (!why.empty()) throw Error("the result would not be a valid mesh: vertex " + std::to_string(v) + " " + why);
  }
}

std::vector<int> vertex_origin(const MeshArrays& a) {
  return a.origin.size() == a.means.size() ? a.origin : std::vector<int>{};
}

std::vector<int> inverse_origin(const std::vector<int>& origin, size_t n_before) {
  if (origin.empty()) return {};
  std::vector<int> back(n_before, -1);
  for (size_t w = 0; w < origin.size(); ++w)
    if (origin[w] >= 0 && size_t(origin[w]) < n_before) back[size_t(origin[w])] = int(w);
  return back;
}

namespace {
// Refuses a result with a face of more sides, or a vertex of more faces, than a surface's patch plans
// take (core/plans/plan_builder.h), where the operation made it so: a mesh that came with such an
// element can still be edited.
void check_plan_limits(const CovarianceMesh& before, const MeshArrays& a, const CovarianceMesh& after,
                       const std::vector<int>& origin) {
  const std::string limit = std::to_string(kMaxPlanValence);
  for (size_t f = 0; f < after.n_faces(); ++f) {
    const int sides = after.face_size(f);
    if (sides <= kMaxPlanValence) continue;
    const int o = f < a.face_origin.size() ? a.face_origin[f] : -1;
    if (o >= 0 && size_t(o) < before.n_faces() && before.face_size(size_t(o)) > kMaxPlanValence) continue;
    throw Error("the result would have a face of " + std::to_string(sides) + " sides; a surface's patch plans take " +
                "up to " + limit + " (their stencils grow with the square of it)");
  }
  const MeshConnectivity& c = after.connectivity();
  for (size_t v = 0; v < after.n_vertices(); ++v) {
    const int faces = c.n_vertex_faces(int(v));
    if (faces <= kMaxPlanValence) continue;
    const int o = v < origin.size() ? origin[v] : -1;
    if (o >= 0 && size_t(o) < before.n_vertices() && before.connectivity().n_vertex_faces(o) > kMaxPlanValence)
      continue;
    throw Error((o >= 0 ? "vertex " + std::to_string(o) : std::string("a new vertex")) + " would have " +
                std::to_string(faces) + " faces; a surface's patch plans take up to " + limit +
                " at a vertex (their stencils grow with the square of it)");
  }
}
}  // namespace

Modelled modelled(const CovarianceMesh& before, const MeshArrays& a, std::vector<int> selection, std::string summary) {
  Modelled out{build_mesh(a, before), std::move(selection), std::move(summary), vertex_origin(a), {}};
  check_plan_limits(before, a, out.mesh, out.vertex_origin);
  return out;
}

Modelled modelled(const CovarianceMesh& before, MeshArrays&& a, std::vector<int> selection, std::string summary) {
  std::vector<int> origin = vertex_origin(a);
  Modelled out{built_from(a, std::move(a.means), std::move(a.covariances), before),
               std::move(selection),
               std::move(summary),
               std::move(origin),
               {}};
  check_plan_limits(before, a, out.mesh, out.vertex_origin);
  return out;
}

void check_new_geometry(const CovarianceMesh& before, const Modelled& result) {
  const CovarianceMesh& after = result.mesh;
  const std::vector<int>& origin = result.vertex_origin;
  if (origin.size() != after.n_vertices()) return;  // which vertices are new is not known
  std::vector<int> faces;
  const MeshConnectivity& c = after.connectivity();
  for (size_t v = 0; v < origin.size(); ++v)
    if (origin[v] < 0) {
      const std::span<const int> row = c.faces_of_vertex(int(v));
      faces.insert(faces.end(), row.begin(), row.end());
    }
  if (faces.empty()) return;
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  const double tolerance = RepairOptions().weld_tolerance * bounding_box_diagonal(before);
  const auto name = [&](int v) {
    return origin[size_t(v)] < 0 ? "new vertex " + std::to_string(v) : "vertex " + std::to_string(origin[size_t(v)]);
  };
  for (const int f : faces) {
    const std::span<const int> corners = after.face(size_t(f));
    const auto mean = [&](int v) -> const Vec3& { return after.mean(size_t(v)); };
    for (size_t k = 0; k < corners.size(); ++k) {
      const int x = corners[k], y = corners[(k + 1) % corners.size()];
      if ((mean(y) - mean(x)).norm() <= tolerance)
        throw Error("the result would put " + name(x) + " within " + short_number(tolerance) + " of " + name(y) +
                    " (a millionth of the mesh's size, which a repair welds)");
    }
    if (without_area(corners, mean, tolerance))
      throw Error("the result would have a face without area, face " + std::to_string(f) + " (its corners in a line)");
  }
}

void remove_faces(MeshArrays& a, const std::vector<char>& removed) {
  size_t next = 0;
  for (size_t f = 0; f < a.faces.size(); ++f) {
    if (removed[f]) continue;
    if (next < a.face_origin.size()) a.face_origin[next] = f < a.face_origin.size() ? a.face_origin[f] : -1;
    if (next != f) a.faces[next] = std::move(a.faces[f]);  // a vector moved onto itself would empty
    ++next;
  }
  a.face_origin.resize(std::min(a.face_origin.size(), next));
  a.faces.resize(next);
}

std::vector<int> drop_unused_vertices(MeshArrays& a) {
  std::vector<char> used(a.means.size(), 0);
  for (const auto& face : a.faces)
    for (int v : face) used[size_t(v)] = 1;
  return drop_unused_vertices(a, used);
}

std::vector<int> drop_unused_vertices(MeshArrays& a, const std::vector<char>& used) {
  std::vector<int> map(a.means.size(), -1);
  const bool origins = a.origin.size() == a.means.size();
  int next = 0;
  for (size_t v = 0; v < map.size(); ++v)
    if (used[v]) {
      if (size_t(next) != v) {  // the vertices before the first dropped one stay where they are
        a.means[size_t(next)] = a.means[v];
        a.covariances[size_t(next)] = a.covariances[v];
        if (origins) a.origin[size_t(next)] = a.origin[v];
      }
      map[v] = next++;
    }
  const bool dropped = size_t(next) != map.size();
  a.means.resize(size_t(next));
  a.covariances.resize(size_t(next));
  a.origin.resize(origins ? size_t(next) : 0);
  if (dropped)  // else every index stays
    for (auto& face : a.faces)
      for (int& v : face) v = map[size_t(v)];
  a.sharpness = renumbered(a.sharpness, map, next);
  return map;
}

Sharpness renumbered(const Sharpness& s, const std::vector<int>& new_index, int n_vertices) {
  Sharpness out;
  const auto index = [&](int v) { return size_t(v) < new_index.size() ? new_index[size_t(v)] : -1; };
  for (const EdgeCrease& c : s.creases) {
    const int a = index(c.a), b = index(c.b);
    if (a < 0 || b < 0 || a == b) continue;
    out.set_crease(a, b, std::max(out.crease(a, b), c.sharpness));
  }
  for (size_t v = 0; v < s.corners.size(); ++v)
    if (const int w = index(int(v)); w >= 0 && s.corners[v] > out.corner(w))
      out.set_corner(w, s.corners[v], n_vertices);
  return out;
}

void split_crease(MeshArrays& a, int u, int v, int m) {
  const double s = a.sharpness.crease(u, v);
  if (s <= 0.0) return;
  a.sharpness.set_crease(u, m, s);
  a.sharpness.set_crease(m, v, s);
}

Gaussian blend_gaussians(const MeshArrays& a, const std::vector<std::pair<int, double>>& weights) {
  Dual q = Dual::Zero();
  for (const auto& [v, w] : weights) q += w * to_dual(a.means[size_t(v)], a.covariances[size_t(v)]);
  const std::optional<Gaussian> g = from_dual(q);
  if (!g) throw Error("a new vertex would get a covariance that is not positive definite");
  return *g;
}

bool all_triangles(const MeshArrays& a) {
  return std::all_of(a.faces.begin(), a.faces.end(), [](const auto& face) { return face.size() == 3; });
}

void split_new_quads(MeshArrays& a, int first) {
  for (size_t f = size_t(first); f < a.faces.size(); ++f) {
    std::vector<int>& quad = a.faces[f];
    if (quad.size() != 4) continue;
    a.faces.push_back({quad[0], quad[2], quad[3]});
    a.faces[f].pop_back();  // quad[0], quad[1], quad[2]
  }
}

Gaussian face_point(const MeshArrays& a, int f) {
  const auto& face = a.faces[size_t(f)];
  std::vector<std::pair<int, double>> w;
  for (int v : face) w.emplace_back(v, 1.0 / double(face.size()));
  return blend_gaussians(a, w);
}

void DirectedEdges::reserve(size_t n) {
  entries_.reserve(n);
  size_t capacity = 16;
  while (capacity < 2 * n) capacity *= 2;
  if (capacity <= slots_.size()) return;
  slots_.assign(capacity, -1);
  slot_keys_.assign(capacity, 0);
  for (size_t i = 0; i < entries_.size(); ++i) {
    const size_t s = slot_of(entries_[i].first);
    slots_[s] = int(i);
    slot_keys_[s] = entries_[i].first;
  }
}

size_t DirectedEdges::slot_of(uint64_t key) const {
  const size_t mask = slots_.size() - 1;
  for (size_t s = size_t(mixed_hash(key)) & mask;; s = (s + 1) & mask)
    if (slots_[s] < 0 || slot_keys_[s] == key) return s;
}

void DirectedEdges::emplace(uint64_t key, std::pair<int, int> place) {
  if (2 * (entries_.size() + 1) > slots_.size()) reserve(std::max<size_t>(2 * entries_.size(), 8));
  const size_t s = slot_of(key);
  if (slots_[s] >= 0) return;
  slots_[s] = int(entries_.size());
  slot_keys_[s] = key;
  entries_.emplace_back(key, place);
}

std::pair<int, int> DirectedEdges::place(uint64_t key) const {
  if (!shape_) {
    const const_iterator it = find(key);
    return it == entries_.end() ? std::pair<int, int>(-1, -1) : it->second;
  }
  const PolygonTopology& t = shape_->topology;
  const MeshConnectivity& c = shape_->connectivity;
  const int a = int(uint32_t(key >> 32)), b = int(uint32_t(key));
  if (a < 0 || b < 0 || a >= t.n_vertices || b >= t.n_vertices) return {-1, -1};
  const int e = c.find_edge(a, b);
  for (int side = 0; e >= 0 && side < 2; ++side) {
    const int f = c.edge_faces[2 * size_t(e) + size_t(side)];
    if (f < 0) continue;
    const int first = t.offsets[size_t(f)], n = t.face_size(f);
    for (int k = 0; k < n; ++k)
      if (t.verts[size_t(first + k)] == a && t.verts[size_t(first + (k + 1) % n)] == b) return {f, k};
  }
  return {-1, -1};
}

DirectedEdges::const_iterator DirectedEdges::find(uint64_t key) const {
  if (slots_.empty()) return entries_.end();
  const int i = slots_[slot_of(key)];
  return i < 0 ? entries_.end() : entries_.begin() + i;
}

DirectedEdges directed_edges(const MeshArrays& a) {
  DirectedEdges edges;
  size_t n = 0;
  for (const auto& face : a.faces) n += face.size();
  edges.reserve(n);
  for (int f = 0; f < a.n_faces(); ++f) {
    const auto& face = a.faces[size_t(f)];
    for (size_t k = 0; k < face.size(); ++k)
      edges.emplace(directed_key(face[k], face[(k + 1) % face.size()]), std::pair<int, int>(f, int(k)));
  }
  return edges;
}

std::pair<int, int> face_of_edge(const DirectedEdges& edges, int u, int v) { return edges.place(directed_key(u, v)); }

bool has_edge(const DirectedEdges& e, int a, int b) {
  return e.count(directed_key(a, b)) != 0 || e.count(directed_key(b, a)) != 0;
}

bool is_boundary_edge(const DirectedEdges& e, int a, int b) {
  return (e.count(directed_key(a, b)) != 0) != (e.count(directed_key(b, a)) != 0);
}

void check_vertex(size_t n_vertices, int v) {
  if (v < 0 || size_t(v) >= n_vertices)
    throw Error("vertex " + std::to_string(v) + " is not in the mesh (" + std::to_string(n_vertices) + " vertices)");
}

void check_vertex(const MeshArrays& a, int v) { check_vertex(size_t(a.n_vertices()), v); }

void check_face(const MeshArrays& a, int f) {
  if (f < 0 || f >= a.n_faces())
    throw Error("face " + std::to_string(f) + " is not in the mesh (" + std::to_string(a.n_faces()) + " faces)");
}

std::vector<int> sorted_vertices(const MeshArrays& a, std::vector<int> vertices) {
  return sorted_vertices(size_t(a.n_vertices()), std::move(vertices));
}

std::vector<int> sorted_vertices(size_t n_vertices, std::vector<int> vertices) {
  for (int v : vertices) check_vertex(n_vertices, v);
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

std::vector<int> sorted_faces(const MeshArrays& a, std::vector<int> faces) {
  for (int f : faces) check_face(a, f);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

}  // namespace gps
