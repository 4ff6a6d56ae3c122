#include "core/plans/stencil_rows_merge.h"

#include <algorithm>

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace gps {

namespace {

// Fewer rows are merged on one core: starting the others costs more.
constexpr size_t kParallelRows = 1 << 14;

// splitmix64's finaliser: every bit of a row key reaches the low ones and the high ones.
size_t mixed(size_t key) {
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ull;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebull;
  return key ^ (key >> 31);
}

// Whether two rows have the same nonzero terms, in the same order (as StencilTableBuilder compares).
bool same_terms(const StencilTable& a, int row_a, const StencilTable& b, int row_b) {
  int i = a.offsets[size_t(row_a)], j = b.offsets[size_t(row_b)];
  const int end_a = a.offsets[size_t(row_a) + 1], end_b = b.offsets[size_t(row_b) + 1];
  while (true) {
    while (i < end_a && a.weights[size_t(i)] == 0.0) ++i;
    while (j < end_b && b.weights[size_t(j)] == 0.0) ++j;
    if (i == end_a || j == end_b) return i == end_a && j == end_b;
    if (a.indices[size_t(i)] != b.indices[size_t(j)] || a.weights[size_t(i)] != b.weights[size_t(j)]) return false;
    ++i, ++j;
  }
}

}  // namespace

MergedStencilRows merge_stencil_rows(const std::vector<const StencilTable*>& tables,
                                     const std::vector<const std::vector<size_t>*>& keys, int n_base, int first_row) {
  const size_t n_tables = tables.size();
  std::vector<size_t> start(n_tables + 1, 0);  // where each table's rows start in the sequence of all rows
  for (size_t t = 0; t < n_tables; ++t) start[t + 1] = start[t] + size_t(tables[t]->n_rows());
  const size_t n = start.back();
  const auto table_of = [&](size_t i) {
    return size_t(std::upper_bound(start.begin(), start.end(), i) - start.begin()) - 1;
  };

  // Per row of the sequence, the first row with the same terms (itself for the first). The keys are
  // shared out among the cores by their hash; each core finds the first rows of its keys in sequence
  // order, so the result is that of adding the rows one after another.
  std::vector<int> first(n), previous_same_key(n, -1);
#pragma omp parallel if (n >= kParallelRows)
  {
    size_t shard = 0, shards = 1;
#if defined(_OPENMP)
    shard = size_t(omp_get_thread_num());
    shards = size_t(omp_get_num_threads());
#endif
    size_t slots = 64;
    while (slots < 2 * (n / shards + 1)) slots *= 2;
    const size_t mask = slots - 1;
    struct Slot {
      size_t key;
      int newest;  // the newest first row of the key (−1: a free slot), chaining back
    };
    std::vector<Slot> slot(slots, Slot{0, -1});
    for (size_t t = 0; t < n_tables; ++t)
      for (int r = 0; r < tables[t]->n_rows(); ++r) {
        const size_t key = (*keys[t])[size_t(r)], hash = mixed(key);
        if (hash % shards != shard) continue;
        const size_t i = start[t] + size_t(r);
        size_t at = (hash / shards) & mask;
        while (slot[at].newest >= 0 && slot[at].key != key) at = (at + 1) & mask;
        int found = -1;
        for (int j = slot[at].newest; j >= 0 && found < 0; j = previous_same_key[size_t(j)]) {
          const size_t u = table_of(size_t(j));
          if (same_terms(*tables[t], r, *tables[u], int(size_t(j) - start[u]))) found = j;
        }
        if (found >= 0) {
          first[i] = found;
          continue;
        }
        first[i] = int(i);
        previous_same_key[i] = slot[at].newest;
        slot[at] = {key, int(i)};
      }
  }

  // The first rows numbered in sequence order, with where their nonzero terms go.
  MergedStencilRows out;
  StencilTable& table = out.table;
  table.n_base = n_base;
  table.row_gap = std::max(0, first_row - n_base);
  out.points.resize(n_tables);
  std::vector<int>& number = previous_same_key;  // reused: per first row, its row in the table
  table.offsets.assign(1, 0);
  int terms = 0;
  for (size_t t = 0; t < n_tables; ++t) {
    const StencilTable& s = *tables[t];
    out.points[t].resize(size_t(s.n_rows()));
    for (int r = 0; r < s.n_rows(); ++r) {
      const size_t i = start[t] + size_t(r);
      if (first[i] == int(i)) {
        number[i] = table.n_rows();
        for (int k = s.offsets[size_t(r)]; k < s.offsets[size_t(r) + 1]; ++k) terms += s.weights[size_t(k)] != 0.0;
        table.offsets.push_back(terms);
      }
      out.points[t][size_t(r)] = table.first_row() + number[size_t(first[i])];
    }
  }
  table.indices.resize(size_t(terms));
  table.weights.resize(size_t(terms));
#pragma omp parallel for schedule(dynamic) if (n >= kParallelRows)
  for (size_t t = 0; t < n_tables; ++t) {
    const StencilTable& s = *tables[t];
    for (int r = 0; r < s.n_rows(); ++r) {
      const size_t i = start[t] + size_t(r);
      if (first[i] != int(i)) continue;
      int out_at = table.offsets[size_t(number[i])];
      for (int k = s.offsets[size_t(r)]; k < s.offsets[size_t(r) + 1]; ++k)
        if (s.weights[size_t(k)] != 0.0) {
          table.indices[size_t(out_at)] = s.indices[size_t(k)];
          table.weights[size_t(out_at++)] = s.weights[size_t(k)];
        }
    }
  }
  return out;
}

}  // namespace gps
