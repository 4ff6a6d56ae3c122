#pragma once
// Building and applying the stencil table of core/plans/patch_plans.h (docs/design.md §2 steps 3–4).
#include <algorithm>
#include <vector>

#include "core/mesh/linalg.h"
#include "core/plans/patch_plans.h"
#include "core/patches/stencil.h"

namespace gps {

/// Collects the points plans read: a stencil that is a single base vertex is that vertex's index;
/// any other becomes a row, rows with identical stencils shared.
class StencilTableBuilder {
public:
  /// Rows numbered from point `first_row` on (n_base where negative).
  explicit StencilTableBuilder(int n_base, int first_row = -1);
  /// The point index of `s` (a base vertex index, or first_row + row).
  int add(const Stencil& s);
  /// The key a row of a builder's table (no zero weights) is found by (core/plans/stencil_rows_merge.h
  /// merges rows by it).
  static size_t row_key(const StencilTable& table, int row);
  StencilTable finish() { return std::move(table_); }

private:
  template <class Terms>
  static size_t key_of(const Terms& terms);
  template <class Terms>
  int add_terms(const Terms& terms, size_t key);

  // The newest row of `key` (−1: none yet), in an open-addressing table (no allocation per row).
  int& last_row_of(size_t key);
  void grow_lookup(size_t slots);

  StencilTable table_;
  std::vector<size_t> slot_keys_;       // per slot: its key
  std::vector<int> slot_rows_;          // per slot: the newest row of that key, chaining through
                                        // previous_same_hash_; kEmptySlot where the slot is free
  size_t used_slots_ = 0;
  std::vector<int> previous_same_hash_;  // per row: the previous row of equal key, or −1
};

/// Whether two rows have the same terms in the same order (as StencilTableBuilder compares them).
/// Inline: the merges call it for every row they place.
inline bool same_row_terms(const StencilTable& a, int row_a, const StencilTable& b, int row_b) {
  const int i = a.offsets[size_t(row_a)], j = b.offsets[size_t(row_b)];
  const int n = a.offsets[size_t(row_a) + 1] - i;
  return n == b.offsets[size_t(row_b) + 1] - j &&
         std::equal(a.indices.begin() + i, a.indices.begin() + i + n, b.indices.begin() + j) &&
         std::equal(a.weights.begin() + i, a.weights.begin() + i + n, b.weights.begin() + j);
}

/// All points: q of the base vertices, zero in the gap, then every row (one sparse matrix-vector
/// product over 9D).
std::vector<Dual> apply_stencils(const StencilTable& table, const std::vector<Dual>& base);

/// For incremental updates: which rows read each base vertex (the transposed table).
struct StencilDependents {
  std::vector<int> offsets, rows;
};
StencilDependents stencil_dependents(const StencilTable& table);
/// The rows that read any of `vertices`, sorted, without repeats.
std::vector<int> rows_reading(const StencilDependents& dependents, const std::vector<int>& vertices);

/// An edit whose part of the work (dependent rows of all rows, changed vertices of all vertices)
/// reaches 1/kWholeUpdateDivisor updates everything at once: past that share, gathering and sorting
/// the parts costs more than the whole update. The CPU update and the renderer's compute passes both follow it.
constexpr size_t kWholeUpdateDivisor = 4;
inline bool update_everything(size_t part, size_t whole) { return part * kWholeUpdateDivisor >= whole; }

/// Re-applies only the rows that read the changed base vertices (every row past update_everything);
/// `points` holds every point and must already carry the changed vertices' new q in its first
/// n_base entries.
void update_stencils(const StencilTable& table, const StencilDependents& dependents,
                     const std::vector<int>& changed_vertices, std::vector<Dual>& points);

}  // namespace gps
