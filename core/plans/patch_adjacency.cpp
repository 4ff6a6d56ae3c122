#include "core/plans/patch_adjacency.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "core/plans/kept_patch_records.h"
#include "core/support/hash_mix.h"
#include "core/support/sorted_indices.h"

namespace gps {

namespace {

struct EdgeUse {
  int patch, k;
  int32_t from, to;
  PatchEdgePart part;
};

EdgeUse edge_use(const PatchPlans& plans, int patch, int k) {
  if (plans.shape == PatchShape::quad) {
    const PatchEdge e = patch_edge(plans, patch, k);
    return {patch, k, e.from, e.to, e.part};
  }
  const int32_t* c = &plans.patch_corner_points[size_t(3 * patch)];
  return {patch, k, c[k], c[(k + 1) % 3], PatchEdgePart::whole};
}

// The end of the whole edge a half lies at.
int32_t half_end(const EdgeUse& e) { return e.part == PatchEdgePart::first_half ? e.from : e.to; }

void link(PatchPlans& plans, const EdgeUse& a, const EdgeUse& b, int which) {
  int32_t* r = &plans.patch_neighbours[size_t(4 * (plans.corners() * a.patch + a.k) + 2 * which)];
  r[0] = b.patch;
  r[1] = b.k + (b.from == a.from ? 0 : 4);
}

// The uses of one edge of the (base or split-face) mesh: linked where they are two whole sides, a
// whole quad side beside two halves, or four halves; otherwise left as a boundary (a non-manifold
// edge has no one partner).
void link_edge(PatchPlans& plans, const std::vector<const EdgeUse*>& uses) {
  // At most 2 whole, 1 beside and 4 halves are linked; the counts say whether the edge has more.
  const EdgeUse *whole[2] = {}, *beside[1] = {}, *halves[4] = {};
  size_t n_whole = 0, n_beside = 0, n_halves = 0;
  for (const EdgeUse* e : uses) {
    if (e->part == PatchEdgePart::whole) {
      if (n_whole < 2) whole[n_whole] = e;
      ++n_whole;
    } else if (e->part == PatchEdgePart::whole_beside_halves) {
      if (n_beside < 1) beside[n_beside] = e;
      ++n_beside;
    } else {
      if (n_halves < 4) halves[n_halves] = e;
      ++n_halves;
    }
  }
  if (n_whole == 2 && n_beside == 0 && n_halves == 0) {
    link(plans, *whole[0], *whole[1], 0);
    link(plans, *whole[1], *whole[0], 0);
  } else if (n_beside == 1 && n_whole == 0 && n_halves == 2 && half_end(*halves[0]) != half_end(*halves[1])) {
    const EdgeUse& quad = *beside[0];
    const EdgeUse* at_from = half_end(*halves[0]) == quad.from ? halves[0] : halves[1];
    const EdgeUse* at_to = at_from == halves[0] ? halves[1] : halves[0];
    link(plans, quad, *at_from, 0);
    link(plans, quad, *at_to, 1);
    link(plans, *at_from, quad, 0);
    link(plans, *at_to, quad, 0);
  } else if (n_whole == 0 && n_beside == 0 && n_halves == 4) {
    for (const EdgeUse* a : halves)
      for (const EdgeUse* b : halves)
        if (a != b && a->patch != b->patch && half_end(*a) == half_end(*b) && a->from != b->from)
          link(plans, *a, *b, 0);
  }
}

bool has_infinite_sharpness(const Sharpness& sharpness) {
  for (const EdgeCrease& c : sharpness.creases)
    if (is_infinitely_sharp(c.sharpness)) return true;
  for (const double s : sharpness.corners)
    if (is_infinitely_sharp(s)) return true;
  return false;
}

// Whether the surface has no one tangent plane at base vertex v (patch_adjacency.h).
bool is_sharp_vertex(const MeshConnectivity& c, const Sharpness& sharpness, int v) {
  int between_faces = 0, on_boundary = 0;
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i) {
    const int e = c.vertex_edges[size_t(i)];
    if (c.is_boundary_edge(e))
      ++on_boundary;
    else if (is_infinitely_sharp(sharpness.crease(v, c.other_vertex(e, v))))
      ++between_faces;
  }
  return is_infinitely_sharp(sharpness.corner(v)) || (between_faces >= 1 && between_faces + on_boundary >= 2);
}

// Flags patch edge k's record where it is linked across an infinitely sharp edge.
void flag_sharp_edge(PatchPlans& plans, const Sharpness& sharpness, int n_base, int p, int k) {
  int32_t* r = &plans.patch_neighbours[size_t(4 * (plans.corners() * p + k))];
  const EdgeUse e = edge_use(plans, p, k);
  if (r[0] < 0 || e.from >= n_base || e.to >= n_base || !is_infinitely_sharp(sharpness.crease(e.from, e.to))) return;
  r[1] |= kNeighbourSharpEdge;
  if (r[2] >= 0) r[3] |= kNeighbourSharpEdge;
}

// Flags patch corner c's owner record where the patches around have normals of their own there, the
// edges' flags set: at a sharp base vertex (`sharp_vertex(point)`), or at a split face's edge point or
// face point on a sharp edge.
template <class SharpVertex>
void flag_sharp_corner(PatchPlans& plans, int n_base, int p, int c, const SharpVertex& sharp_vertex) {
  const int n = plans.corners();
  const int32_t point = plans.patch_corner_points[size_t(n * p + c)];
  const auto sharp_edge = [&](int k) { return edge_neighbour(plans, p, k).sharp; };
  if (point < n_base ? sharp_vertex(point) : sharp_edge(c) || sharp_edge((c + n - 1) % n))
    plans.corner_owners[size_t(2 * (n * p + c)) + 1] |= kOwnerSharpCorner;
}

// What the sharp flags read of the base mesh: its connectivity and sharpness.
struct SharpBase {
  const MeshConnectivity& connectivity;
  const Sharpness& sharpness;
  int n_base() const { return int(connectivity.vertex_edge_offsets.size()) - 1; }
};

// The owners' sharp flags of every corner the edges' flags set.
void flag_sharp_corners(PatchPlans& plans, const SharpBase& sharp) {
  std::vector<char> sharp_vertex(size_t(sharp.n_base()), 0);
  for (int v = 0; v < sharp.n_base(); ++v)
    sharp_vertex[size_t(v)] = is_sharp_vertex(sharp.connectivity, sharp.sharpness, v);
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int c = 0; c < plans.corners(); ++c)
      flag_sharp_corner(plans, sharp.n_base(), p, c, [&](int32_t v) { return sharp_vertex[size_t(v)] != 0; });
}

// Flags the linked patch edges on infinitely sharp edges and the patch corners where the patches
// around have normals of their own (patch_adjacency.h).
void add_sharp_flags(PatchPlans& plans, const PolygonTopology& topology, const Sharpness& sharpness,
                     const MeshConnectivity* connectivity) {
  const int n = plans.corners(), n_base = topology.n_vertices;
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int k = 0; k < n; ++k) flag_sharp_edge(plans, sharpness, n_base, p, k);
  const MeshConnectivity built = connectivity ? MeshConnectivity{} : connectivity_of(topology);
  flag_sharp_corners(plans, {connectivity ? *connectivity : built, sharpness});
}

// Corner owners: the first (lowest) patch with each corner point.
void add_corner_owners(PatchPlans& plans) {
  const int n = plans.corners(), n_patches = plans.n_patches();
  const int32_t* points = plans.patch_corner_points.data();
  int32_t corner_points = 0;
#pragma omp parallel for schedule(static) reduction(max : corner_points) if (n_patches >= kParallelFaces)
  for (size_t i = 0; i < plans.patch_corner_points.size(); ++i) corner_points = std::max(corner_points, points[i] + 1);
  // Corner point -> its first use, as patch · 4 + corner (in the order of the uses, for either shape;
  // a surface's patches stay far below 2^29): the least of its uses, found on all cores.
  std::vector<int32_t> first_use(size_t(corner_points), std::numeric_limits<int32_t>::max());
#pragma omp parallel for schedule(static) if (n_patches >= kParallelFaces)
  for (int p = 0; p < n_patches; ++p)
    for (int c = 0; c < n; ++c) {
      std::atomic_ref<int32_t> first(first_use[size_t(points[size_t(n * p + c)])]);
      const int32_t use = p << 2 | c;
      int32_t seen = first.load(std::memory_order_relaxed);
      while (use < seen && !first.compare_exchange_weak(seen, use, std::memory_order_relaxed)) {
      }
    }
  int32_t* owners = plans.corner_owners.data();
#pragma omp parallel for schedule(static) if (n_patches >= kParallelFaces)
  for (int p = 0; p < n_patches; ++p)
    for (int c = 0; c < n; ++c) {
      const int32_t use = first_use[size_t(points[size_t(n * p + c)])];
      owners[2 * size_t(n * p + c)] = use >> 2;
      owners[2 * size_t(n * p + c) + 1] = use & 3;
    }
}

// An edge use's key: its two end points, the lower first.
uint64_t edge_key(const EdgeUse& e) {
  const int32_t lo = std::min(e.from, e.to), hi = std::max(e.from, e.to);
  return (uint64_t(uint32_t(lo)) << 32) | uint32_t(hi);
}

}  // namespace

void add_patch_adjacency(PatchPlans& plans, const PolygonTopology& topology, const Sharpness& sharpness,
                         const MeshConnectivity* connectivity) {
  const int n = plans.corners(), n_patches = plans.n_patches();
  plans.patch_neighbours.assign(size_t(4 * n * n_patches), -1);
  plans.corner_owners.assign(size_t(2 * n * n_patches), -1);
  // The uses of each edge, grouped by their lower end point with a counting sort (linear, no map of
  // lists: hashed lists would weigh on plan building for a large mesh), then by the upper.
  std::vector<EdgeUse> uses;
  uses.reserve(size_t(n * n_patches));
  int32_t n_points = 0;
  for (int p = 0; p < n_patches; ++p)
    for (int k = 0; k < n; ++k) {
      const EdgeUse e = edge_use(plans, p, k);
      if (e.from == e.to) continue;  // degenerate: nothing to share
      uses.push_back(e);
      n_points = std::max(n_points, std::max(e.from, e.to) + 1);
    }
  std::vector<int> first(size_t(n_points) + 1, 0);
  for (const EdgeUse& e : uses) ++first[size_t(std::min(e.from, e.to)) + 1];
  for (size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
  std::vector<int> order(uses.size()), next(first.begin(), first.end() - 1);
  for (size_t u = 0; u < uses.size(); ++u) order[size_t(next[size_t(std::min(uses[u].from, uses[u].to))]++)] = int(u);
  std::vector<const EdgeUse*> group;
  for (int32_t lower = 0; lower < n_points; ++lower) {
    const auto begin = order.begin() + first[size_t(lower)], end = order.begin() + first[size_t(lower) + 1];
    const auto upper = [&](int u) { return std::max(uses[size_t(u)].from, uses[size_t(u)].to); };
    // By upper end, then in patch order (the order of `uses`) within an edge.
    std::sort(begin, end, [&](int a, int b) { return upper(a) != upper(b) ? upper(a) < upper(b) : a < b; });
    for (auto run = begin; run != end;) {
      auto run_end = run;
      group.clear();
      while (run_end != end && upper(*run_end) == upper(*run)) group.push_back(&uses[size_t(*run_end++)]);
      link_edge(plans, group);
      run = run_end;
    }
  }
  add_corner_owners(plans);
  if (has_infinite_sharpness(sharpness)) add_sharp_flags(plans, topology, sharpness, connectivity);
}

namespace {

// An update of the edge records: the plans being made, the records before, and what is to be linked.
class RecordUpdate {
public:
  // `sharp`: the base mesh's connectivity and sharpness, where the update keeps and sets the sharp flags
  // (null: a flagged record is linked again, its flag gone, and there is no infinite sharpness now).
  RecordUpdate(PatchPlans& plans, const std::vector<int32_t>& old_neighbours, const SharpBase* sharp)
      : plans_(plans), old_(old_neighbours), n_(plans.corners()), sharp_(sharp) {}

  // Room for every record: each is written below (a boundary until linked again), and every owner by
  // add_corner_owners, so storage the arrays already hold is not filled first.
  void resize() {
    plans_.patch_neighbours.resize(size_t(4 * n_ * plans_.n_patches()));
    plans_.corner_owners.resize(size_t(2 * n_ * plans_.n_patches()));
  }

  // New patch p: its records a boundary until linked again, its edges' keys listed (sorted by
  // sort_new_keys) for the kept boundary edges to look up.
  void add_new(int p) {
    for (int k = 0; k < n_; ++k) {
      unlink(p, k);
      const EdgeUse e = edge_use(plans_, p, k);
      new_keys_.push_back(edge_key(e));
      if (e.from != e.to) again_.push_back(e);
    }
  }
  void sort_new_keys() { std::sort(new_keys_.begin(), new_keys_.end()); }

  // Kept patch p (q before; `new_of(patch before)`: its number now, −1 gone): a record keeps its patches,
  // renumbered, unless the patch beside it is gone, its edge is a boundary that a new patch now has, or
  // it is flagged sharp (creases that are gone); those are unlinked, their edges put in `relink`, and p
  // is true's. The boundary records kept go in `boundary`.
  template <class NewOf>
  bool carry(int p, int q, const NewOf& new_of, std::vector<EdgeUse>& relink, std::vector<int>& boundary) const {
    bool unlinked = false;
    for (int k = 0; k < n_; ++k) {
      const int32_t* r = &old_[size_t(4 * (n_ * q + k))];
      bool kept =
          r[0] >= 0 || !std::binary_search(new_keys_.begin(), new_keys_.end(), edge_key(edge_use(plans_, p, k)));
      for (int j = 0; j < 4 && kept; j += 2)
        kept = r[j] < 0 || (new_of(r[j]) >= 0 && (sharp_ || !(r[j + 1] & kNeighbourSharpEdge)));
      if (!kept) {
        unlink(p, k);
        if (const EdgeUse e = edge_use(plans_, p, k); e.from != e.to) relink.push_back(e);
        unlinked = true;
        continue;
      }
      int32_t* out = &plans_.patch_neighbours[size_t(4 * (n_ * p + k))];
      for (int j = 0; j < 4; j += 2) {
        out[j] = r[j] >= 0 ? new_of(r[j]) : -1;
        out[j + 1] = r[j + 1];
      }
      if (out[0] < 0) boundary.push_back(n_ * p + k);
    }
    return unlinked;
  }

  void add_again(const std::vector<EdgeUse>& uses) { again_.insert(again_.end(), uses.begin(), uses.end()); }

  // Links the edges to be linked, in groups of one edge, in patch order within a group, as
  // add_patch_adjacency links them: sorted by key, then by patch edge (patch · n + k, unique), which
  // carries the use's index below it.
  void link_again() {
    std::vector<std::pair<uint64_t, uint64_t>> order(again_.size());
    for (size_t i = 0; i < again_.size(); ++i) {
      const EdgeUse& e = again_[i];
      order[i] = {edge_key(e), (uint64_t(e.patch) * uint64_t(n_) + uint64_t(e.k)) << 32 | i};
    }
    std::sort(order.begin(), order.end());
    std::vector<const EdgeUse*> group;
    for (size_t i = 0; i < order.size();) {
      group.clear();
      size_t j = i;
      for (; j < order.size() && order[j].first == order[i].first; ++j)
        group.push_back(&again_[size_t(order[j].second & 0xffffffffu)]);
      link_edge(plans_, group);
      i = j;
    }
  }

  // The writes: `written` (sorted here) and the boundary records, those kept (`kept_boundary`) and
  // those of the written patches as linked.
  void tell(std::vector<int>&& written, std::vector<int>&& kept_boundary, bool numbers_kept,
            AdjacencyWrites& writes) const {
    std::sort(written.begin(), written.end());
    if (sharp_)  // the kept records keep theirs: a change of an edge's crease builds its faces again
      for (const int p : written)
        for (int k = 0; k < n_; ++k) flag_sharp_edge(plans_, sharp_->sharpness, sharp_->n_base(), p, k);
    for (const int p : written)
      for (int k = 0; k < n_; ++k)
        if (plans_.patch_neighbours[size_t(4 * (n_ * p + k))] < 0) kept_boundary.push_back(n_ * p + k);
    std::sort(kept_boundary.begin(), kept_boundary.end());
    writes = {numbers_kept, std::move(written), std::move(kept_boundary), std::nullopt};
  }

private:
  void unlink(int p, int k) const { std::fill_n(&plans_.patch_neighbours[size_t(4 * (n_ * p + k))], 4, int32_t(-1)); }

  PatchPlans& plans_;
  const std::vector<int32_t>& old_;
  int n_;
  const SharpBase* sharp_;
  std::vector<uint64_t> new_keys_;
  std::vector<EdgeUse> again_;
};

// The uses (patch · 4 + corner) of the point at corner c of patch p: the corners with that point on
// the patches reached from p across the edges at such corners (the patches around a point of a
// manifold mesh are one fan, linked edge to edge). `patches` is scratch.
void point_uses(const PatchPlans& plans, int p, int c, std::vector<int>& patches, std::vector<int32_t>& uses) {
  const int n = plans.corners();
  const int32_t point = plans.patch_corner_points[size_t(n * p + c)];
  patches.assign(1, p);
  uses.clear();
  for (size_t i = 0; i < patches.size(); ++i) {
    const int m = patches[i];
    for (int j = 0; j < n; ++j) {
      if (plans.patch_corner_points[size_t(n * m + j)] != point) continue;
      uses.push_back(m << 2 | j);
      for (const int k : {j, (j + n - 1) % n})
        for (int w = 0; w < 4; w += 2)
          if (const int32_t across = plans.patch_neighbours[size_t(4 * (n * m + k) + w)];
              across >= 0 && std::find(patches.begin(), patches.end(), across) == patches.end())
            patches.push_back(across);
    }
  }
}

// Per point index a value (≥ 0), or −1 where none was set: an open-addressing table of the points a
// change walks, at their cost (an array over every point would be filled first, and a hash set
// allocates a node per point).
class PointValues {
public:
  /// Room for `points` without growing.
  explicit PointValues(size_t points) { resize(points); }

  int32_t get(int32_t point) const {
    for (size_t s = slot(point);; s = (s + 1) & mask()) {
      if (keys_[s] == point) return values_[s];
      if (keys_[s] < 0) return -1;
    }
  }
  void set(int32_t point, int32_t value) {
    if (2 * (count_ + 1) > keys_.size()) grow();
    size_t s = slot(point);
    while (keys_[s] >= 0 && keys_[s] != point) s = (s + 1) & mask();
    if (keys_[s] < 0) keys_[s] = point, ++count_;
    values_[s] = value;
  }

private:
  size_t mask() const { return keys_.size() - 1; }
  size_t slot(int32_t point) const { return size_t(mixed_hash(uint32_t(point))) & mask(); }
  void resize(size_t points) {
    size_t slots = 64;
    while (slots < 2 * points) slots *= 2;
    keys_.assign(slots, -1);
    values_.assign(slots, -1);
    count_ = 0;
  }
  void grow() {
    const std::vector<int32_t> keys = std::move(keys_), values = std::move(values_);
    resize(keys.size());
    for (size_t s = 0; s < keys.size(); ++s)
      if (keys[s] >= 0) set(keys[s], values[s]);
  }

  std::vector<int32_t> keys_, values_;  // a power of two of slots, at most half full; key −1: empty
  size_t count_ = 0;
};

// Visits the patches between the kept runs, in the new numbering (the new patches) or, with
// `old_numbers`, in the old (the patches that are gone).
template <class Visit>
void for_gaps(const std::vector<KeptPatches>& kept, bool old_numbers, int end, const Visit& visit) {
  int at = 0;
  for (const KeptPatches& run : kept) {
    const int first = old_numbers ? run.old_first : run.first;
    for (; at < first; ++at) visit(at);
    at = first + run.count;
  }
  for (; at < end; ++at) visit(at);
}

// The corner owners of plans whose kept patches are `kept` (runs increasing in both numberings;
// `new_of(patch before)`: its number now, −1 gone) from those of `old`. A corner's owner is the least use
// of its point; where every use stays, the least stays the least, renumbered. The owners found again are
// those of the corners whose point a new or a gone patch has; their patches go in `written`. Where
// `held_written` is given (every run keeps its numbers), plans.corner_owners holds the owners of the
// plans `old` was made from, which differ from old's at those patches only; else the kept runs' owners
// are carried over whole.
template <class NewOf>
void update_corner_owners(PatchPlans& plans, const PatchPlans& old, const SharpBase& sharp, const NewOf& new_of,
                          const std::vector<KeptPatches>& kept, const std::vector<int>* held_written,
                          std::vector<int>& written) {
  const int n = plans.corners(), n_old = old.n_patches();
  const bool same_numbers = keep_numbers(kept);
  const auto carry_old = [&](int p, int q, int count) {
    const int32_t* from = old.corner_owners.data() + 2 * ptrdiff_t(n) * q;
    int32_t* to = plans.corner_owners.data() + 2 * ptrdiff_t(n) * p;
    const ptrdiff_t size = 2 * ptrdiff_t(n) * count;
    if (same_numbers) return void(std::copy_n(from, size, to));
#pragma omp parallel for schedule(static) if (count >= kParallelFaces)
    for (ptrdiff_t i = 0; i < size; i += 2) {
      to[i] = from[i] >= 0 ? new_of(from[i]) : -1;  // −1 where the owner is gone: its point is found again below
      to[i + 1] = from[i + 1];
    }
  };
  if (held_written) {
    for (const int p : *held_written)
      if (new_of(p) >= 0) carry_old(p, p, 1);
  } else {
    for (const KeptPatches& run : kept) carry_old(run.first, run.old_first, run.count);
  }
  const bool flagged = has_infinite_sharpness(sharp.sharpness);
  // Each point walked around once (a point of many patches is a corner of each).
  std::vector<int> patches;
  std::vector<int32_t> uses;
  // Per point of the plans walked around: its least use, the owner of its corners; and the points of
  // the plans before walked around.
  int kept_patches = 0;
  for (const KeptPatches& run : kept) kept_patches += run.count;
  PointValues owner_of(size_t(n * (plans.n_patches() - kept_patches))),
      walked_before(size_t(n * (n_old - kept_patches)));
  const auto add_users = [&](const PatchPlans& of, int p, bool old_numbers) {
    PointValues& walked = old_numbers ? walked_before : owner_of;
    for (int c = 0; c < n; ++c) {
      const int32_t point = of.patch_corner_points[size_t(n * p + c)];
      if (walked.get(point) >= 0) continue;
      point_uses(of, p, c, patches, uses);
      walked.set(point, *std::min_element(uses.begin(), uses.end()));
      for (const int32_t use : uses)
        if (const int user = old_numbers ? new_of(use >> 2) : use >> 2; user >= 0) written.push_back(user);
    }
  };
  for_gaps(kept, false, plans.n_patches(), [&](int p) { add_users(plans, p, false); });
  for_gaps(kept, true, n_old, [&](int q) { add_users(old, q, true); });
  sort_unique_indices(written, plans.n_patches());
  for (const int p : written)
    for (int c = 0; c < n; ++c) {
      const int32_t point = plans.patch_corner_points[size_t(n * p + c)];
      int32_t owner = owner_of.get(point);
      if (owner < 0) {
        point_uses(plans, p, c, patches, uses);
        owner = *std::min_element(uses.begin(), uses.end());
        owner_of.set(point, owner);
      }
      plans.corner_owners[2 * size_t(n * p + c)] = owner >> 2;
      plans.corner_owners[2 * size_t(n * p + c) + 1] = owner & 3;
      if (flagged)
        flag_sharp_corner(plans, sharp.n_base(), p, c,
                          [&](int32_t v) { return is_sharp_vertex(sharp.connectivity, sharp.sharpness, v); });
    }
}

// update_patch_adjacency over every kept patch, telling what it wrote. Where the plans before (`old`)
// and the kept runs (`kept`) are given, the corner owners are updated from old's; else found whole.
bool update_every_record(PatchPlans& plans, const Sharpness& sharpness, const std::vector<int32_t>& old_neighbours,
                         const std::vector<int>& new_of_old, const SharpBase* sharp, AdjacencyWrites& writes,
                         const PatchPlans* old = nullptr, const std::vector<KeptPatches>* kept = nullptr) {
  const int n = plans.corners(), n_patches = plans.n_patches();
  const bool flagged = has_infinite_sharpness(sharpness);
  if ((flagged && !sharp) || old_neighbours.size() != size_t(4 * n) * new_of_old.size()) return false;
  std::vector<int> old_of_new(size_t(n_patches), -1);
  bool numbers_kept = true;
  for (size_t q = 0; q < new_of_old.size(); ++q)
    if (const int p = new_of_old[q]; p >= 0) {
      if (p >= n_patches || old_of_new[size_t(p)] >= 0) return false;
      old_of_new[size_t(p)] = int(q);
      numbers_kept = numbers_kept && p == int(q);
    }
  RecordUpdate update(plans, old_neighbours, sharp);
  update.resize();
  std::vector<int> written, boundary;
  for (int p = 0; p < n_patches; ++p)
    if (old_of_new[size_t(p)] < 0) update.add_new(p), written.push_back(p);
  update.sort_new_keys();
  const auto new_of = [&](int32_t q) { return new_of_old[size_t(q)]; };
#pragma omp parallel if (n_patches >= kParallelFaces)
  {
    // The kept patches' records, on all cores; each thread's edges to link again, and what it wrote, are
    // joined after (the edges are sorted when linked).
    std::vector<EdgeUse> own;
    std::vector<int> own_written, own_boundary;
#pragma omp for schedule(static) nowait
    for (int p = 0; p < n_patches; ++p)
      if (const int q = old_of_new[size_t(p)]; q >= 0 && update.carry(p, q, new_of, own, own_boundary))
        own_written.push_back(p);
#pragma omp critical
    {
      update.add_again(own);
      written.insert(written.end(), own_written.begin(), own_written.end());
      boundary.insert(boundary.end(), own_boundary.begin(), own_boundary.end());
    }
  }
  update.link_again();
  update.tell(std::move(written), std::move(boundary), numbers_kept, writes);
  if (old && kept && sharp) {
    std::vector<int> owners_written;
    update_corner_owners(plans, *old, *sharp, new_of, *kept, nullptr, owners_written);
    return true;
  }
  add_corner_owners(plans);
  if (flagged) flag_sharp_corners(plans, *sharp);
  return true;
}

}  // namespace

bool update_patch_adjacency(PatchPlans& plans, const Sharpness& sharpness, const std::vector<int32_t>& old_neighbours,
                            const std::vector<int>& new_of_old) {
  AdjacencyWrites writes;
  return update_every_record(plans, sharpness, old_neighbours, new_of_old, nullptr, writes);
}

std::vector<int> boundary_records(const PatchPlans& plans) {
  std::vector<int> boundary;
  const int n = plans.corners();
  for (int p = 0; p < plans.n_patches(); ++p)
    for (int k = 0; k < n; ++k)
      if (plans.patch_neighbours[size_t(4 * (n * p + k))] < 0) boundary.push_back(n * p + k);
  return boundary;
}

bool update_patch_adjacency(PatchPlans& plans, const Sharpness& sharpness, const MeshConnectivity& connectivity,
                            const PatchPlans& old, const std::vector<KeptPatches>& kept, const AdjacencyWrites* held,
                            AdjacencyWrites& writes) {
  const SharpBase sharp{connectivity, sharpness};
  writes = {};
  const std::vector<int32_t>& old_neighbours = old.patch_neighbours;
  const int n = plans.corners(), n_patches = plans.n_patches();
  if (n == 0 || old_neighbours.size() % size_t(4 * n) != 0) return false;
  const int n_old = int(old_neighbours.size() / size_t(4 * n));
  if (!kept_runs_fit(kept, n_old, n_patches)) return false;
  if (!held || !held->numbers_kept || !keep_numbers(kept)) {
    std::vector<int> new_of_old(size_t(n_old), -1);
    for (const KeptPatches& run : kept)
      for (int i = 0; i < run.count; ++i) new_of_old[size_t(run.old_first + i)] = run.first + i;
    return update_every_record(plans, sharpness, old_neighbours, new_of_old, &sharp, writes, &old, &kept);
  }
  // Every kept patch keeps its number, and a record that neither update wrote holds already: the one
  // before, renumbered to itself, unless it is a boundary's or lies beside a patch that is gone (links
  // go both ways, so the records of the patches that are gone name those).
  const auto is_kept = [&](int32_t p) {
    const auto run =
        std::upper_bound(kept.begin(), kept.end(), p, [](int32_t x, const KeptPatches& r) { return x < r.first; });
    return run != kept.begin() && p < std::prev(run)->first + std::prev(run)->count;
  };
  const auto new_of = [&](int32_t q) { return is_kept(q) ? q : -1; };
  RecordUpdate update(plans, old_neighbours, &sharp);
  update.resize();
  std::vector<int> written, candidates;
  for_gaps(kept, false, n_patches, [&](int p) { update.add_new(p), written.push_back(p); });
  update.sort_new_keys();
  for (const int p : held->written)
    if (is_kept(p)) candidates.push_back(p);
  for (const int record : held->boundary)
    if (is_kept(record / n)) candidates.push_back(record / n);
  for_gaps(kept, true, n_old, [&](int q) {
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < 4; j += 2)
        if (const int32_t p = old_neighbours[size_t(4 * (n * q + k) + j)]; p >= 0 && is_kept(p))
          candidates.push_back(p);
  });
  sort_unique_indices(candidates, n_patches);
  std::vector<EdgeUse> relink;
  std::vector<int> boundary;
  for (const int p : candidates)
    if (update.carry(p, p, new_of, relink, boundary)) written.push_back(p);
  update.add_again(relink);
  update.link_again();
  update.tell(std::move(written), std::move(boundary), true, writes);
  writes.owners_written.emplace();
  update_corner_owners(plans, old, sharp, new_of, kept, held->owners_written ? &*held->owners_written : nullptr,
                       *writes.owners_written);
  return true;
}

PatchEdgeSlot curve_edge(const PatchPlans& plans, int patch, int k) {
  const int32_t part = plans.shape == PatchShape::quad ? int32_t(patch_edge(plans, patch, k).part) : kEdgeWhole;
  if (part == kEdgeWholeBesideHalves) return {patch, k};
  const EdgeNeighbour across = edge_neighbour(plans, patch, k);
  if (across.patch < 0) return {patch, k};
  if (part != kEdgeWhole && patch_edge(plans, across.patch, across.edge).part == PatchEdgePart::whole_beside_halves)
    return {across.patch, across.edge};
  const bool lower = across.patch < patch || (across.patch == patch && across.edge < k);
  return lower ? PatchEdgeSlot{across.patch, across.edge} : PatchEdgeSlot{patch, k};
}

}  // namespace gps
