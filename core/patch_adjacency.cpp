#include "core/patch_adjacency.h"

#include <algorithm>
#include <unordered_map>

namespace gps {

namespace {

struct EdgeUse {
  int patch, k;
  int32_t from, to;
  PatchEdgePart part;
};

EdgeUse edge_use(const PlanTable& plans, int patch, int k) {
  if (plans.shape == PatchShape::quad) {
    const PatchEdge e = patch_edge(plans, patch, k);
    return {patch, k, e.from, e.to, e.part};
  }
  const int32_t* c = &plans.patch_corner_points[size_t(3 * patch)];
  return {patch, k, c[k], c[(k + 1) % 3], PatchEdgePart::whole};
}

// The end of the whole edge a half lies at.
int32_t half_end(const EdgeUse& e) { return e.part == PatchEdgePart::first_half ? e.from : e.to; }

void link(PlanTable& plans, const EdgeUse& a, const EdgeUse& b, int which) {
  int32_t* r = &plans.patch_neighbours[size_t(4 * (plans.corners() * a.patch + a.k) + 2 * which)];
  r[0] = b.patch;
  r[1] = b.k + (b.from == a.from ? 0 : 4);
}

}  // namespace

void add_patch_adjacency(PlanTable& plans) {
  const int n = plans.corners(), n_patches = plans.n_patches();
  plans.patch_neighbours.assign(size_t(4 * n * n_patches), -1);
  plans.corner_owners.assign(size_t(2 * n * n_patches), -1);
  // The uses of each edge of the (base or split-face) mesh, keyed by its two end points.
  std::unordered_map<uint64_t, std::vector<EdgeUse>> edges;
  edges.reserve(size_t(2 * n * n_patches));
  for (int p = 0; p < n_patches; ++p)
    for (int k = 0; k < n; ++k) {
      const EdgeUse e = edge_use(plans, p, k);
      if (e.from == e.to) continue;  // degenerate: nothing to share
      const uint64_t key = uint64_t(uint32_t(std::min(e.from, e.to))) << 32 | uint32_t(std::max(e.from, e.to));
      edges[key].push_back(e);
    }
  for (const auto& entry : edges) {
    const std::vector<EdgeUse>& uses = entry.second;
    std::vector<const EdgeUse*> whole, beside, halves;
    for (const EdgeUse& e : uses)
      (e.part == PatchEdgePart::whole ? whole : e.part == PatchEdgePart::whole_beside_halves ? beside : halves).push_back(&e);
    // Two sides exactly, or the edge is left as a boundary (a non-manifold edge has no one partner).
    if (whole.size() == 2 && beside.empty() && halves.empty()) {
      link(plans, *whole[0], *whole[1], 0);
      link(plans, *whole[1], *whole[0], 0);
    } else if (beside.size() == 1 && whole.empty() && halves.size() == 2 && half_end(*halves[0]) != half_end(*halves[1])) {
      const EdgeUse& quad = *beside[0];
      const EdgeUse* at_from = half_end(*halves[0]) == quad.from ? halves[0] : halves[1];
      const EdgeUse* at_to = at_from == halves[0] ? halves[1] : halves[0];
      link(plans, quad, *at_from, 0);
      link(plans, quad, *at_to, 1);
      link(plans, *at_from, quad, 0);
      link(plans, *at_to, quad, 0);
    } else if (whole.empty() && beside.empty() && halves.size() == 4) {
      for (const EdgeUse* a : halves)
        for (const EdgeUse* b : halves)
          if (a != b && a->patch != b->patch && half_end(*a) == half_end(*b) && a->from != b->from) link(plans, *a, *b, 0);
    }
  }
  // Corner owners: the first (lowest) patch with each corner point.
  std::unordered_map<int32_t, int32_t> owner;  // corner point -> n·patch + corner
  owner.reserve(plans.patch_corner_points.size());
  for (int p = 0; p < n_patches; ++p)
    for (int c = 0; c < n; ++c) {
      const int32_t point = plans.patch_corner_points[size_t(n * p + c)];
      const int32_t first = owner.try_emplace(point, n * p + c).first->second;
      plans.corner_owners[size_t(2 * (n * p + c))] = first / n;
      plans.corner_owners[size_t(2 * (n * p + c)) + 1] = first % n;
    }
}

}  // namespace gps
