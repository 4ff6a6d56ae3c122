#include "core/plans/surface_replanner.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <numeric>
#include <utility>

#include "core/plans/loop_crease_plan_builder.h"
#include "core/plans/loop_plan_builder.h"
#include "core/plans/patch_adjacency.h"
#include "core/support/sorted_indices.h"

namespace gps {
namespace {

// Whether some edge or vertex is sharp (crease_level's level is not empty).
bool has_sharpness(const Sharpness& s) {
  return std::any_of(s.creases.begin(), s.creases.end(), [](const EdgeCrease& e) { return e.sharpness > 0.0; }) ||
         std::any_of(s.corners.begin(), s.corners.end(), [](double c) { return c > 0.0; });
}

// Every old vertex's new index from the new vertices' origins (empty origin: the indices kept), or
// false where they cannot serve: a kept range's rows list their terms in index order, which only an
// increasing renumbering keeps.
bool new_index_of(const std::vector<int>& origin, int n_old, int n_new, std::vector<int>& new_index) {
  new_index.assign(size_t(n_old), -1);
  if (origin.empty()) {
    for (int v = 0; v < std::min(n_old, n_new); ++v) new_index[size_t(v)] = v;
    return true;
  }
  if (origin.size() != size_t(n_new)) return false;
  int last = -1;
  for (int w = 0; w < n_new; ++w) {
    const int o = origin[size_t(w)];
    if (o < 0) continue;
    if (o <= last || o >= n_old) return false;
    new_index[size_t(o)] = w;
    last = o;
  }
  return true;
}

// Renumbers a kept range's points onto the new mesh: base vertex p becomes new_index[p], the range's
// own rows follow the new base. False if it reads a vertex that is gone (it must be built again). Where
// every old vertex that stays keeps its index (`same_base`) nothing moves: the range's own rows stay
// after its own n_base, which merge_ranges reads.
bool renumber_range(RangePlans& range, const std::vector<int>& new_index, bool same_base, int n_new) {
  if (same_base) return true;
  PatchPlans& p = range.tables.plans;
  StencilTable& s = range.tables.stencils;
  const int n_own = s.n_base;  // the base the range's points are numbered on
  bool gone = false, moved = false;
  const auto point = [&](int32_t& q) {
    if (q >= n_own) {
      q = q - n_own + n_new;
      return;
    }
    const int w = new_index[size_t(q)];
    gone |= w < 0;
    moved |= w != q;
    q = w;
  };
  for_each_point(p, point);
  for (int32_t& q : s.indices) point(q);  // rows are over base vertices only
  s.n_base = n_new;
  // A row's key hashes its indices: merge_ranges hashes it again. What the last merge found of the rows
  // holds: one renumbering of every kept range, one to one, leaves rows alike that were alike.
  if (moved) range.row_keys.clear();
  return !gone;
}

// How many patches face f has (core/plans/patch_layout.h): one per quad or triangle patch, n for an
// n-gon split by Catmull-Clark.
int patches_of_face(const PolygonTopology& t, int f, Scheme scheme) {
  return scheme == Scheme::loop || t.face_size(f) == 4 ? 1 : t.face_size(f);
}

// Whether `made` (a shape's origin) says where each face of the shape came from, as the replanner would
// find it: made from `previous` with the vertex origins `origin` (empty: every old vertex keeps its
// index, the new ones after).
bool continues(const ShapeOrigin& made, const std::shared_ptr<const MeshShape>& previous,
               const std::vector<int>& origin, int n_old) {
  if (made.from.lock() != previous || made.faces.empty()) return false;
  if (!origin.empty()) return made.vertices == origin;
  for (size_t v = 0; v < made.vertices.size(); ++v)
    if (made.vertices[v] != (int(v) < n_old ? int(v) : -1)) return false;
  return true;
}

// A new id for a replanner's tables, unique in the process.
long long next_tables_id() {
  static std::atomic<long long> last{0};
  return ++last;
}

}  // namespace

std::vector<int> faces_reading(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<int>& edges,
                               const std::vector<int>& vertices) {
  std::vector<int> holders;  // the faces that hold a changed edge or vertex
  for (const int e : edges)
    for (int k = 0; k < 2; ++k)
      if (const int f = c.edge_faces[2 * size_t(e) + size_t(k)]; f >= 0) holders.push_back(f);
  for (const int v : vertices)
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
      holders.push_back(c.vertex_faces[size_t(i)]);
  std::sort(holders.begin(), holders.end());
  holders.erase(std::unique(holders.begin(), holders.end()), holders.end());
  return faces_around(t, c, holders);
}

std::vector<int> faces_around(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<int>& faces) {
  // Each face once, marked as it is met: gathered with its repeats (every face around a corner, at each
  // corner), the list to sort was several times as long.
  std::vector<char> met(size_t(t.n_faces()), 0);
  std::vector<int> around;
  for (const int g : faces)
    for (int k = t.offsets[size_t(g)]; k < t.offsets[size_t(g) + 1]; ++k) {
      const int w = t.verts[size_t(k)];
      for (int i = c.vertex_face_offsets[size_t(w)]; i < c.vertex_face_offsets[size_t(w) + 1]; ++i)
        if (const int f = c.vertex_faces[size_t(i)]; !met[size_t(f)]) {
          met[size_t(f)] = 1;
          around.push_back(f);
        }
    }
  if (around.size() * 16 < met.size()) {
    std::sort(around.begin(), around.end());
  } else {  // many: read off in order
    around.clear();
    for (size_t f = 0; f < met.size(); ++f)
      if (met[f]) around.push_back(int(f));
  }
  return around;
}

SurfaceReplanner::SurfaceReplanner(const PolygonTopology& topology, const PlanOptions& options,
                                   const Sharpness& sharpness, int faces_per_range)
    : SurfaceReplanner(base_local_mesh(topology, sharpness), options, sharpness, faces_per_range) {}

SurfaceReplanner::SurfaceReplanner(const CovarianceMesh& mesh, const PlanOptions& options, int faces_per_range)
    : SurfaceReplanner(base_local_mesh(mesh.shape(), mesh.sharpness), options, mesh.sharpness, faces_per_range) {}

SurfaceReplanner::SurfaceReplanner(LocalMesh&& base, const PlanOptions& options, const Sharpness& sharpness,
                                   int faces_per_range)
    : options_(options),
      scheme_(scheme_for(base.topology(), options, &base.connectivity())),
      faces_per_range_(std::max(1, faces_per_range)),
      base_(std::move(base)),
      sharpness_(sharpness) {
  check(base_.topology(), base_.connectivity(), scheme_);
  build_all(sharpness);
}

void SurfaceReplanner::check(const PolygonTopology& topology, const MeshConnectivity& connectivity,
                             Scheme scheme) const {
  // `scheme` is scheme_for's: left to choose, it picks Loop only for triangles with at most
  // kMaxLoopValence faces at a vertex, which is all that Loop's checks look at.
  if (scheme == Scheme::loop) {
    if (options_.scheme) check_loop_plans(topology, &connectivity);
  } else {
    check_quad_plans(topology, options_.depth, options_.exact ? ExtraordinaryNodes::exact : ExtraordinaryNodes::bezier,
                     &connectivity);
  }
}

void SurfaceReplanner::build_all(const Sharpness& sharpness) {
  const int n_faces = base_.topology().n_faces();
  range_first_.clear();
  for (int f = 0; f < n_faces; f += faces_per_range_) range_first_.push_back(f);
  if (range_first_.empty()) range_first_.push_back(0);
  range_first_.push_back(n_faces);
  ranges_.assign(range_first_.size() - 1, {});
  range_kept_.assign(ranges_.size(), 0);
  std::vector<int> all(ranges_.size());
  for (size_t r = 0; r < all.size(); ++r) all[r] = int(r);
  build(all, sharpness);
}

void SurfaceReplanner::build(const std::vector<int>& which, const Sharpness& sharpness,
                             const std::vector<int>& old_patch_first, const std::vector<int>& old_face_patch,
                             size_t same_leading) {
  const PolygonTopology& t = base_.topology();
  change_ = {change_.to, next_tables_id(), {}, std::nullopt, {}};
  std::vector<KeptPatches>& kept = change_.kept;
  const bool creased = base_.has_creases();
  if (scheme_ == Scheme::loop && !creased && !loop_tables_)
    loop_tables_ = std::make_unique<LoopExtraordinaryTableCache>(options_.loop_beta);
  if (scheme_ == Scheme::loop && creased && !loop_crease_tables_)
    loop_crease_tables_ = std::make_unique<LoopCreaseTables>(options_.loop_beta);
  if (scheme_ == Scheme::catmull_clark && !quad_tables_) quad_tables_ = std::make_unique<QuadExtraordinaryTableCache>();
  const ExtraordinaryNodes extraordinary = options_.exact ? ExtraordinaryNodes::exact : ExtraordinaryNodes::bezier;
  std::vector<std::exception_ptr> failures(which.size());
#pragma omp parallel for schedule(dynamic)
  for (size_t i = 0; i < which.size(); ++i) {
    const size_t r = size_t(which[i]);
    const int first = range_first_[r], last = range_first_[r + 1];
    try {
      if (scheme_ == Scheme::catmull_clark)
        ranges_[r] = build_quad_range(base_, first, last, options_.depth, extraordinary, true, *quad_tables_);
      else if (creased)
        ranges_[r] = build_creased_loop_range(base_, first, last, options_.loop_beta, *loop_crease_tables_);
      else
        ranges_[r] = build_loop_range(t, base_.connectivity(), first, last, options_.loop_beta, *loop_tables_);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  }
  for (const auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
  const std::shared_ptr<const SurfaceTables> old = tables_;
  const PatchShape old_shape = old->plans.shape;
  // The tables before the previous ones, once nothing else holds them, lend their storage.
  // Their first ranges' part is there already where those ranges led both merges since.
  SurfaceTables storage;
  size_t storage_leading = 0;
  const bool storage_retired = retired_ && retired_.use_count() == 1;
  if (storage_retired) {
    storage = std::move(*retired_);
    storage_leading = std::min(tables_leading_, same_leading);
  }
  retired_.reset();
  SurfaceTables merged = merge_ranges(ranges_, t.n_vertices, false, old.get(), same_leading, &storage,
                                      &change_.kept_rows, storage_leading, &change_.same_leading);
  merged.plans.patch_neighbours = std::move(storage.plans.patch_neighbours);  // assigned whole below
  merged.plans.corner_owners = std::move(storage.plans.corner_owners);
  patch_first_.assign(ranges_.size(), 0);
  // The runs kept, in order in both numberings (a run that would go back in the old one is left out).
  const auto keep = [&](int first, int old_first, int count) {
    KeptPatches* last = kept.empty() ? nullptr : &kept.back();
    if (count <= 0 || (last && last->old_first + last->count > old_first)) return;
    if (last && last->first + last->count == first && last->old_first + last->count == old_first)
      last->count += count;
    else
      kept.push_back({first, old_first, count});
  };
  int first = 0;
  for (size_t r = 0; r < ranges_.size(); ++r) {
    patch_first_[r] = first;
    const int count = int(ranges_[r].tables.plans.patch_roots.size());
    const int old_first = r < old_patch_first.size() ? old_patch_first[r] : -1;
    if (old_first >= 0) {
      keep(first, old_first, count);
    } else if (!old_face_patch.empty()) {  // built again: its faces whose pieces stayed keep their plans
      int patches = 0;
      for (int f = range_first_[r]; f < range_first_[r + 1]; ++f) patches += patches_of_face(t, f, scheme_);
      for (int f = range_first_[r], patch = first; f < range_first_[r + 1] && patches == count; ++f) {
        const int n = patches_of_face(t, f, scheme_);
        if (old_face_patch[size_t(f)] >= 0) keep(patch, old_face_patch[size_t(f)], n);
        patch += n;
      }
    }
    first += count;
  }
  // The patch adjacency follows the kept patches where it can, else is found again whole. The retired
  // tables' records, where their storage came back, are those the last update started from.
  AdjacencyWrites writes;
  const bool held = storage_retired && !merged.plans.patch_neighbours.empty();
  const bool updated = !kept.empty() && old_shape == merged.plans.shape &&
                       update_patch_adjacency(merged.plans, sharpness, base_.connectivity(), old->plans, kept,
                                              held ? &adjacency_writes_ : nullptr, writes);
  if (!updated) {
    add_patch_adjacency(merged.plans, t, sharpness, &base_.connectivity());
    writes = {false, {}, boundary_records(merged.plans)};
  }
  if (updated && writes.numbers_kept) {
    change_.neighbours_written = writes.written;
    change_.owners_written = writes.owners_written;
  }
  adjacency_writes_ = std::move(writes);
  if (updated) change_.relinked = kept_beside_built(kept);
  retired_ = std::exchange(tables_, std::make_shared<SurfaceTables>(std::move(merged)));
  tables_leading_ = same_leading;
}

std::vector<int> SurfaceReplanner::kept_beside_built(const std::vector<KeptPatches>& kept) const {
  const PolygonTopology& t = base_.topology();
  const MeshConnectivity& c = base_.connectivity();
  // Whether patches [first, last) all lie in kept runs; called in increasing order, `run` walks the runs.
  size_t run = 0;
  const auto all_kept = [&](int first, int last) {
    while (first < last) {
      while (run < kept.size() && kept[run].first + kept[run].count <= first) ++run;
      if (run == kept.size() || kept[run].first > first) return false;
      first = kept[run].first + kept[run].count;
    }
    return true;
  };
  // The faces with a patch not kept, listed and flagged: a range kept whole is passed over at once.
  std::vector<int> built;
  std::vector<char> is_built(size_t(t.n_faces()), 0);
  for (size_t r = 0; r < ranges_.size(); ++r) {
    const size_t at = run;
    if (all_kept(patch_first_[r], patch_first_[r] + int(ranges_[r].tables.plans.patch_roots.size()))) continue;
    run = at;
    for (int f = range_first_[r], p = patch_first_[r]; f < range_first_[r + 1]; ++f) {
      const int n = patches_of_face(t, f, scheme_);
      if (!all_kept(p, p + n)) built.push_back(f), is_built[size_t(f)] = 1;
      p += n;
    }
  }
  // The other faces at their corners: every patch of theirs is kept.
  std::vector<int> beside;
  for (const int g : built)
    for (int k = t.offsets[size_t(g)]; k < t.offsets[size_t(g) + 1]; ++k) {
      const int w = t.verts[size_t(k)];
      for (int i = c.vertex_face_offsets[size_t(w)]; i < c.vertex_face_offsets[size_t(w) + 1]; ++i)
        if (const int f = c.vertex_faces[size_t(i)]; !is_built[size_t(f)]) beside.push_back(f);
    }
  sort_unique_indices(beside, t.n_faces());
  // Their patches: face f's first is p, f in range r, walked forward.
  std::vector<int> relinked;
  size_t r = 0;
  int f = 0, p = 0;
  for (const int g : beside) {
    if (g >= range_first_[r + 1]) {
      r = size_t(std::upper_bound(range_first_.begin(), range_first_.end(), g) - range_first_.begin()) - 1;
      f = range_first_[r];
      p = patch_first_[r];
    }
    while (f < g) p += patches_of_face(t, f++, scheme_);
    for (int i = 0; i < patches_of_face(t, g, scheme_); ++i) relinked.push_back(p + i);
  }
  return relinked;
}

std::vector<int> SurfaceReplanner::set_sharpness(const Sharpness& sharpness) {
  const PolygonTopology& t = base_.topology();
  const MeshConnectivity& c = base_.connectivity();
  CreaseLevel level = crease_level(sharpness, c, t.n_vertices);
  if (level.empty()) level = {};
  const CreaseLevel& old = base_.creases;
  std::vector<int> faces;
  sharpness_ = sharpness;
  if (level.empty() != old.empty()) {  // the first sharpness or the last: every plan
    base_.creases = std::move(level);
    build_all(sharpness);
    faces.resize(size_t(t.n_faces()));
    for (size_t f = 0; f < faces.size(); ++f) faces[f] = int(f);
    return faces;
  }
  if (!level.empty()) {
    std::vector<int> edges, vertices;
    for (size_t e = 0; e < level.edges.size(); ++e)
      if (level.edges[e] != old.edges[e]) edges.push_back(int(e));
    for (size_t v = 0; v < level.vertices.size(); ++v)
      if (level.vertices[v] != old.vertices[v]) vertices.push_back(int(v));
    faces = faces_reading(t, c, edges, vertices);
  }
  base_.creases = std::move(level);
  if (faces.empty()) {  // every edge and vertex as sharp as before: the same tables, adjacency included
    keep_every_plan();
    return faces;
  }
  // The same faces and vertices: each its own; the faces that read a change are built again.
  const int n_faces = t.n_faces();
  std::vector<int> face_itself(static_cast<size_t>(n_faces)), vertex_itself(static_cast<size_t>(t.n_vertices));
  std::iota(face_itself.begin(), face_itself.end(), 0);
  std::iota(vertex_itself.begin(), vertex_itself.end(), 0);
  std::vector<char> dirty(size_t(n_faces), 0);
  for (const int f : faces) dirty[size_t(f)] = 1;
  keep_runs_and_build(t, face_itself, face_itself, dirty, vertex_itself, true, sharpness);
  return faces;
}

bool SurfaceReplanner::same_faces(const PolygonTopology& topology, const std::vector<int>& origin) const {
  const PolygonTopology& t = base_.topology();
  // A mesh whose shape the base shares has these very faces: not compared with themselves.
  if (&topology != &t &&
      !(topology.n_vertices == t.n_vertices && topology.offsets == t.offsets && topology.verts == t.verts))
    return false;
  for (size_t v = 0; v < origin.size(); ++v)
    if (origin[v] != int(v)) return false;
  return origin.empty() || origin.size() == size_t(t.n_vertices);
}

bool SurfaceReplanner::same_surface(const PolygonTopology& topology, const Sharpness& sharpness,
                                    const std::vector<int>& origin) const {
  return tables_->plans.n_patches() > 0 && sharpness == sharpness_ && same_faces(topology, origin);
}

void SurfaceReplanner::keep_every_plan() {
  change_ = {change_.to, next_tables_id(), {}, std::vector<int>{}, {}};
  if (const int n = tables_->plans.n_patches(); n > 0) change_.kept.push_back({0, 0, n});
  if (const int n = tables_->stencils.n_rows(); n > 0) change_.kept_rows.push_back({0, 0, n});
}

int SurfaceReplanner::set_topology(const PolygonTopology& topology, const Sharpness& sharpness,
                                   const std::vector<int>& origin) {
  if (same_surface(topology, sharpness, origin)) return keep_every_plan(), 0;
  // The checks first: a refusal changes nothing.
  LocalMesh base = base_local_mesh(topology, sharpness);
  const Scheme scheme = scheme_for(topology, options_, &base.connectivity());
  check(topology, base.connectivity(), scheme);
  return replan(std::move(base), scheme, sharpness, origin);
}

int SurfaceReplanner::set_topology(const CovarianceMesh& mesh, const std::vector<int>& origin) {
  if (same_surface(mesh.topology(), mesh.sharpness, origin)) return keep_every_plan(), 0;
  // The very faces of the base, every vertex where it was (a crease's undo, which shares them), sharp
  // before and after: only the sharpness changed, re-planned where it reaches. (A first or last
  // sharpness is planned where it reaches below, where set_sharpness plans everything.)
  if (mesh.shape() == base_.shape && tables_->plans.n_patches() > 0 && base_.has_creases() &&
      has_sharpness(mesh.sharpness) && same_faces(mesh.topology(), origin))
    return int(set_sharpness(mesh.sharpness).size());
  const Scheme scheme = scheme_for(mesh.topology(), options_, &mesh.connectivity());
  check(mesh.topology(), mesh.connectivity(), scheme);
  return replan(base_local_mesh(mesh.shape(), mesh.sharpness), scheme, mesh.sharpness, origin);
}

int SurfaceReplanner::replan(LocalMesh&& base, Scheme scheme, const Sharpness& sharpness,
                             const std::vector<int>& origin) {
  // Loop plans creased and smooth meshes with two builders, whose ranges do not mix; Catmull-Clark's
  // one builder plans both, so a first crease or corner is planned where it reaches.
  const bool same_builder = scheme == scheme_ && !ranges_.empty() &&
                            (scheme == Scheme::catmull_clark || base.has_creases() == base_.has_creases());
  const LocalMesh previous = std::exchange(base_, std::move(base));
  const Sharpness old_sharpness = std::exchange(sharpness_, sharpness);
  scheme_ = scheme;
  const PolygonTopology& t = base_.topology();
  const MeshConnectivity& c = base_.connectivity();
  const PolygonTopology& old = previous.topology();
  const int n_old = old.n_vertices, n_new = t.n_vertices, n_faces = t.n_faces();
  std::vector<int> new_index;
  if (!same_builder || !new_index_of(origin, n_old, n_new, new_index)) {
    build_all(sharpness);
    return n_faces;
  }

  // Every old vertex that stays keeps its index (an operation that only adds vertices, or its undo):
  // the kept ranges need no renumbering then, since none reads a vertex that is gone (its faces are
  // gone, and every face that shares a vertex with them is built again).
  bool same_base = true;
  for (int v = 0; v < n_old && same_base; ++v) same_base = new_index[size_t(v)] < 0 || new_index[size_t(v)] == v;
  // Faces that are still there, corner for corner: old face → new face and back. Where the operation
  // that made the new shape from the old one found them with these vertex origins, they are taken from
  // it; else each old face's first match is found on all cores, and where an earlier face took it (a
  // face repeated), the next free one.
  std::vector<int> new_face(size_t(old.n_faces()), -1), old_face(size_t(n_faces), -1);
  if (const ShapeOrigin& made = base_.shape->origin; continues(made, previous.shape, origin, n_old)) {
    for (int g = 0; g < n_faces; ++g)
      if (const int f = made.faces[size_t(g)]; f >= 0) old_face[size_t(g)] = f, new_face[size_t(f)] = g;
  } else {
    match_faces(old, new_index, new_face, old_face);
  }
  // Vertices whose pieces changed: corners of faces added or removed, ends of changed creases, changed corners.
  std::vector<char> changed(size_t(n_new), 0);
  const auto mark_old = [&](int v) {
    if (const int w = new_index[size_t(v)]; w >= 0) changed[size_t(w)] = 1;
  };
  for (int g = 0; g < n_faces; ++g)
    if (old_face[size_t(g)] < 0)
      for (int k = t.offsets[size_t(g)]; k < t.offsets[size_t(g) + 1]; ++k) changed[size_t(t.verts[size_t(k)])] = 1;
  for (int f = 0; f < old.n_faces(); ++f)
    if (new_face[size_t(f)] < 0)
      for (int k = old.offsets[size_t(f)]; k < old.offsets[size_t(f) + 1]; ++k) mark_old(old.verts[size_t(k)]);
  for (const EdgeCrease& e : old_sharpness.creases) {
    const int a = new_index[size_t(e.a)], b = new_index[size_t(e.b)];
    if (a < 0 || b < 0 || sharpness.crease(a, b) != e.sharpness) mark_old(e.a), mark_old(e.b);
  }
  if (!sharpness.creases.empty() || !sharpness.corners.empty() || !old_sharpness.corners.empty()) {
    std::vector<int> old_index(size_t(n_new), -1);
    for (int v = 0; v < n_old; ++v)
      if (const int w = new_index[size_t(v)]; w >= 0) old_index[size_t(w)] = v;
    for (const EdgeCrease& e : sharpness.creases) {
      const int a = old_index[size_t(e.a)], b = old_index[size_t(e.b)];
      if (a < 0 || b < 0 || old_sharpness.crease(a, b) != e.sharpness) changed[size_t(e.a)] = changed[size_t(e.b)] = 1;
    }
    for (int w = 0; w < n_new; ++w) {
      const int v = old_index[size_t(w)];
      if (sharpness.corner(w) != (v < 0 ? 0.0 : old_sharpness.corner(v))) changed[size_t(w)] = 1;
    }
  }
  std::vector<int> changed_vertices;
  for (int w = 0; w < n_new; ++w)
    if (changed[size_t(w)]) changed_vertices.push_back(w);
  std::vector<char> dirty(size_t(n_faces), 0);
  for (const int g : faces_reading(t, c, {}, changed_vertices)) dirty[size_t(g)] = 1;

  return keep_runs_and_build(old, new_face, old_face, dirty, new_index, same_base, sharpness);
}

void SurfaceReplanner::match_faces(const PolygonTopology& old, const std::vector<int>& new_index,
                                   std::vector<int>& new_face, std::vector<int>& old_face) const {
  const PolygonTopology& t = base_.topology();
  const MeshConnectivity& c = base_.connectivity();
  // Whether new face g has old face f's corners, renumbered, from its first corner on.
  const auto same_corners = [&](int f, int g) {
    const int first = old.offsets[size_t(f)], size = old.face_size(f);
    if (g < 0 || g >= t.n_faces() || t.face_size(g) != size) return false;
    for (int k = 0; k < size; ++k)
      if (new_index[size_t(old.verts[size_t(first + k)])] != t.verts[size_t(t.offsets[size_t(g)] + k)]) return false;
    return true;
  };
  // The first face (in the row of f's first corner, renumbered) with f's corners; `free_only`: that
  // no old face has yet.
  const auto match = [&](int f, bool free_only) {
    const int w = new_index[size_t(old.verts[size_t(old.offsets[size_t(f)])])];
    if (w < 0) return -1;
    for (int i = c.vertex_face_offsets[size_t(w)]; i < c.vertex_face_offsets[size_t(w) + 1]; ++i) {
      const int g = c.vertex_faces[size_t(i)];
      if (c.vertex_face_corners[size_t(i)] == 0 && !(free_only && old_face[size_t(g)] >= 0) && same_corners(f, g))
        return g;
    }
    return -1;
  };
  // A manifold mesh has no two faces with the same corners: the face after the previous one's match,
  // where it has this one's corners, is its match, found without a lookup in the rows (most faces
  // follow the one before them, numbers shifted past a change).
  constexpr int kBlocks = 64;
  const int n_old = old.n_faces();
#pragma omp parallel for schedule(static) if (n_old >= kParallelFaces)
  for (int b = 0; b < kBlocks; ++b) {
    int guess = -1;
    for (int f = int(int64_t(n_old) * b / kBlocks); f < int(int64_t(n_old) * (b + 1) / kBlocks); ++f) {
      const int g = same_corners(f, guess) ? guess : match(f, false);
      new_face[size_t(f)] = g;
      guess = g >= 0 ? g + 1 : -1;
    }
  }
  for (int f = 0; f < old.n_faces(); ++f) {
    int& g = new_face[size_t(f)];
    if (g >= 0 && old_face[size_t(g)] >= 0) g = match(f, true);
    if (g >= 0) old_face[size_t(g)] = f;
  }
}

int SurfaceReplanner::keep_runs_and_build(const PolygonTopology& old, const std::vector<int>& new_face,
                                          const std::vector<int>& old_face, const std::vector<char>& dirty,
                                          const std::vector<int>& new_index, bool same_base,
                                          const Sharpness& sharpness) {
  const int n_faces = base_.topology().n_faces(), n_new = base_.topology().n_vertices;
  // The runs of old faces kept: still there, clean, consecutive and in order, each within one old range.
  // A range kept whole is taken as it is; of one that a change reaches, each run of at least
  // min_run_faces() faces is cut out (cut_range); the faces between are built again.
  struct KeptRun {
    int range, first_face, n_faces, first_patch, n_patches;  // in the old range's faces and patches
    bool whole, usable = false;
    RangePlans cut;
  };
  std::vector<KeptRun> runs;
  std::vector<int> kept_at(size_t(n_faces), -1);  // new face → the run that starts there
  const auto clean = [&](int f) { return new_face[size_t(f)] >= 0 && !dirty[size_t(new_face[size_t(f)])]; };
  for (size_t r = 0; r + 1 < range_first_.size(); ++r) {
    const int a = range_first_[r], b = range_first_[r + 1];
    for (int f = a, patch = 0; f < b;) {
      if (!clean(f)) {
        patch += patches_of_face(old, f++, scheme_);
        continue;
      }
      const int start = f, start_patch = patch;
      do patch += patches_of_face(old, f++, scheme_);
      while (f < b && clean(f) && new_face[size_t(f)] == new_face[size_t(f) - 1] + 1);
      const bool whole = start == a && f == b;
      if (whole || f - start >= min_run_faces())
        runs.push_back({int(r), start, f - start, start_patch, patch - start_patch, whole, false, {}});
    }
  }
  // Cut and renumbered onto the new mesh on all cores (each its own tables); a run that reads a vertex
  // that is gone, or cannot be cut, is built again.
#pragma omp parallel for schedule(dynamic)
  for (size_t i = 0; i < runs.size(); ++i) {
    KeptRun& run = runs[i];
    RangePlans& range = ranges_[size_t(run.range)];
    run.usable = (run.whole || cut_range(range, run.first_patch, run.first_patch + run.n_patches, run.cut)) &&
                 renumber_range(run.whole ? range : run.cut, new_index, same_base, n_new);
  }
  for (size_t i = 0; i < runs.size(); ++i)
    if (runs[i].usable) kept_at[size_t(new_face[size_t(runs[i].first_face)])] = int(i);
  std::vector<RangePlans> ranges;
  std::vector<int> firsts, fresh, old_patch_first, kept_changes;
  int planned = 0;
  size_t same_leading = 0;  // the first ranges: old ranges in their place, whole and not renumbered
  for (int g = 0; g < n_faces;) {
    const int start = g;
    if (const int i = kept_at[size_t(g)]; i >= 0) {
      KeptRun& run = runs[size_t(i)];
      if (same_base && run.whole && run.range == int(ranges.size()) && same_leading == ranges.size()) ++same_leading;
      old_patch_first.push_back(patch_first_[size_t(run.range)] + run.first_patch);
      kept_changes.push_back(run.whole ? range_kept_[size_t(run.range)] + 1 : 0);
      ranges.push_back(std::move(run.whole ? ranges_[size_t(run.range)] : run.cut));
      g += run.n_faces;
    } else {
      while (g < n_faces && kept_at[size_t(g)] < 0 && g - start < faces_per_range_) ++g;
      fresh.push_back(int(ranges.size()));
      old_patch_first.push_back(-1);
      kept_changes.push_back(0);
      ranges.emplace_back();
      planned += g - start;
    }
    firsts.push_back(start);
  }
  if (firsts.empty())
    firsts.push_back(0), fresh.push_back(0), old_patch_first.push_back(-1), kept_changes.push_back(0),
        ranges.emplace_back();
  firsts.push_back(n_faces);
  // The faces built again whose pieces stayed: where their old patches started.
  std::vector<int> old_first_patch(size_t(old.n_faces()) + 1, 0), old_face_patch(size_t(n_faces), -1);
  for (int f = 0; f < old.n_faces(); ++f)
    old_first_patch[size_t(f) + 1] = old_first_patch[size_t(f)] + patches_of_face(old, f, scheme_);
  for (int g = 0; g < n_faces; ++g)
    if (const int f = old_face[size_t(g)]; f >= 0 && !dirty[size_t(g)])
      old_face_patch[size_t(g)] = old_first_patch[size_t(f)];
  ranges_ = std::move(ranges);
  range_first_ = std::move(firsts);
  range_kept_ = std::move(kept_changes);
  build(fresh, sharpness, old_patch_first, old_face_patch, same_leading);
  join_short_ranges();
  return planned;
}

void SurfaceReplanner::join_short_ranges() {
  size_t into = 0;  // the range the ones after it join
  std::vector<AppendedRows> appended;
  for (size_t r = 1; r < ranges_.size(); ++r) {
    // The faces of `into`, which reaches up to range r, and of range r.
    const int faces_into = range_first_[r] - range_first_[into], faces = range_first_[r + 1] - range_first_[r];
    if (faces_into + faces > faces_per_range_ || std::min(faces_into, faces) >= short_range_faces() ||
        std::min(range_kept_[into], range_kept_[r]) < kSettledChanges) {
      ++into;
      if (into != r) {
        ranges_[into] = std::move(ranges_[r]);
        range_first_[into] = range_first_[r];
        range_kept_[into] = range_kept_[r];
        patch_first_[into] = patch_first_[r];
      }
      continue;
    }
    if (AppendedRows rows = append_range(ranges_[into], ranges_[r]); rows.from != 0)
      appended.push_back(std::move(rows));
    tables_leading_ = std::min(tables_leading_, into);
  }
  if (ranges_.empty()) return;
  if (!appended.empty()) {
#pragma omp parallel for schedule(dynamic)
    for (size_t r = 0; r <= into; ++r) rename_appended_rows(ranges_[r].row_firsts, appended);
  }
  ranges_.resize(into + 1);
  range_kept_.resize(into + 1);
  range_first_[into + 1] = range_first_.back();
  range_first_.resize(into + 2);
  patch_first_.resize(into + 1);
}

}  // namespace gps
