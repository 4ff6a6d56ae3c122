#include "core/io/position_weld.h"

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/support/disjoint_sets.h"

namespace gps {

namespace {

struct CellKey {
  double x, y, z;
  bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
// The cell indices' bits mixed as splitmix64 does: a few multiplications, no byte-wise hashing.
struct CellHash {
  static uint64_t bits(double x) {
    uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  }
  size_t operator()(const CellKey& k) const {
    uint64_t h = bits(k.x) ^ (bits(k.y) * 0x9E3779B97F4A7C15ull) ^ (bits(k.z) * 0xC2B2AE3D27D4EB4Full);
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    return size_t(h ^ (h >> 31));
  }
};

// Indices into an array, found by the CellKey each has (key_of(index)): open addressing over a table of
// ints at most half full, 8 bytes an index where a node-based map would take some 50.
template <class KeyOf>
class IndexTable {
public:
  IndexTable(size_t capacity, const KeyOf& key_of) : key_of_(key_of) {
    size_t n = 16;
    while (n < 2 * capacity) n *= 2;
    slots_.assign(n, -1);
  }
  /// The index with key k, or −1 where there is none.
  int find(const CellKey& k) const { return slots_[slot_of(k)]; }
  /// The index with key k, or −1 after adding `index` (whose key is k) for it.
  int find_or_add(const CellKey& k, int index) {
    int& slot = slots_[slot_of(k)];
    if (slot >= 0) return slot;
    slot = index;
    return -1;
  }

private:
  size_t slot_of(const CellKey& k) const {
    const size_t mask = slots_.size() - 1;
    for (size_t s = CellHash()(k) & mask;; s = (s + 1) & mask)
      if (slots_[s] < 0 || key_of_(slots_[s]) == k) return s;
  }
  const KeyOf& key_of_;
  std::vector<int> slots_;
};

// Joins the `distinct` positions (ascending vertices) lying within the tolerance of one another.
void weld_within_tolerance(const std::vector<Vec3>& p, const std::vector<int>& distinct, const Vec3& lo,
                           double tolerance, LowestRootSets& sets) {
  const double cell = 0.5 * tolerance, block = 4 * tolerance;
  const double reach = 0.25 + 1e-6;  // the tolerance in blocks, rounding allowed for
  const double tolerance2 = tolerance * tolerance;
  const auto key_of = [&](const Vec3& x, double size) {
    const Vec3 c = ((x - lo) / size).array().floor();
    return CellKey{c.x(), c.y(), c.z()};
  };
  struct Cell {
    int head = -1;           // its last vertex; next_in_cell chains the rest
    int next_in_block = -1;  // the block's previous cell
  };
  struct Block {
    int vertex = -1;  // one of its vertices
    int last_cell = -1;
    int n_cells = 0;
  };
  constexpr int kCellsAround = 125;  // the cells within the tolerance of a cell: ±2 along each axis
  std::vector<Cell> cells;
  std::vector<Block> blocks;
  const auto cell_key = [&](int c) { return key_of(p[size_t(cells[size_t(c)].head)], cell); };
  const auto block_key = [&](int b) { return key_of(p[size_t(blocks[size_t(b)].vertex)], block); };
  IndexTable<decltype(cell_key)> cell_at(distinct.size(), cell_key);
  IndexTable<decltype(block_key)> block_at(distinct.size(), block_key);
  // The squared distance from x to a cell's box, in cells (computed as key_of places x): a cell
  // farther than the tolerance is not measured.
  const auto cells2_to = [&](const Vec3& x, int c) {
    const CellKey k = cell_key(c);
    const Vec3 d = (x - lo) / cell - Vec3(k.x, k.y, k.z);
    return (-d).cwiseMax(d - Vec3::Ones()).cwiseMax(0.0).squaredNorm();
  };
  std::vector<int> next_in_cell(p.size(), -1);
  for (const int v : distinct) {
    const Vec3& x = p[size_t(v)];
    const int own = cell_at.find_or_add(key_of(x, cell), int(cells.size()));
    if (own >= 0)
      sets.unite(cells[size_t(own)].head, v);
    else
      cells.push_back({v, -1});
    // The cells not yet in v's cluster whose box lies within the tolerance: each measured until a
    // vertex within it is found.
    const auto measure = [&](int c) {
      if (sets.find(cells[size_t(c)].head) == sets.find(v) || cells2_to(x, c) > 4 * (1 + 1e-6)) return;
      for (int u = cells[size_t(c)].head; u >= 0; u = next_in_cell[size_t(u)])
        if ((p[size_t(u)] - x).squaredNorm() <= tolerance2) {
          sets.unite(u, v);
          return;
        }
    };
    const CellKey k = key_of(x, block);
    const Vec3 in_block = (x - lo) / block - Vec3(k.x, k.y, k.z);  // each in [0, 1)
    int from[3], to[3];
    for (int a = 0; a < 3; ++a) {
      from[a] = in_block[a] < reach ? -1 : 0;
      to[a] = in_block[a] > 1 - reach ? 1 : 0;
    }
    int near[8], n_near = 0, near_cells = 0;
    for (int dx = from[0]; dx <= to[0]; ++dx)
      for (int dy = from[1]; dy <= to[1]; ++dy)
        for (int dz = from[2]; dz <= to[2]; ++dz)
          if (const int b = block_at.find({k.x + dx, k.y + dy, k.z + dz}); b >= 0) {
            near[n_near++] = b;
            near_cells += blocks[size_t(b)].n_cells;
          }
    if (near_cells <= kCellsAround) {
      for (int i = 0; i < n_near; ++i)
        for (int c = blocks[size_t(near[i])].last_cell; c >= 0; c = cells[size_t(c)].next_in_block) measure(c);
    } else {  // crowded blocks: the cells within the tolerance looked up instead
      const CellKey at = key_of(x, cell);
      for (int dx = -2; dx <= 2; ++dx)
        for (int dy = -2; dy <= 2; ++dy)
          for (int dz = -2; dz <= 2; ++dz)
            if (const int c = cell_at.find({at.x + dx, at.y + dy, at.z + dz}); c >= 0) measure(c);
    }
    if (own >= 0) {
      next_in_cell[size_t(v)] = cells[size_t(own)].head;
      cells[size_t(own)].head = v;
      continue;
    }
    const int c = int(cells.size()) - 1;
    const int b = block_at.find_or_add(k, int(blocks.size()));
    if (b < 0) {
      blocks.push_back({v, c, 1});
    } else {
      cells[size_t(c)].next_in_block = blocks[size_t(b)].last_cell;
      blocks[size_t(b)].last_cell = c;
      ++blocks[size_t(b)].n_cells;
    }
  }
}

}  // namespace

std::vector<int> weld_roots(const std::vector<Vec3>& p, double tolerance) {
  LowestRootSets sets(p.size());
  if (p.empty()) return sets.parent;
  std::vector<int> distinct;  // the first vertex at each position
  {
    const auto position = [&](int v) {
      const Vec3& x = p[size_t(v)];
      return CellKey{x.x() + 0.0, x.y() + 0.0, x.z() + 0.0};  // −0 as 0
    };
    IndexTable<decltype(position)> first_at(p.size(), position);
    for (int v = 0; v < int(p.size()); ++v) {
      if (const int first = first_at.find_or_add(position(v), v); first >= 0)
        sets.unite(first, v);
      else
        distinct.push_back(v);
    }
  }
  if (tolerance > 0) {
    Vec3 lo = p[0];
    for (const Vec3& x : p) lo = lo.cwiseMin(x);
    weld_within_tolerance(p, distinct, lo, tolerance, sets);
  }
  std::vector<int> roots(p.size());
  for (int v = 0; v < int(p.size()); ++v) roots[size_t(v)] = sets.find(v);
  return roots;
}

}  // namespace gps
