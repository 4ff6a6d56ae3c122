#include "core/plans/stencil_table.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

#include "core/mesh/sparse_lists.h"
#include "core/support/hash_mix.h"

namespace gps {

namespace {
constexpr int kEmptySlot = -2;
// The slot a key starts at.
size_t slot_of(size_t key, size_t mask) { return size_t(mixed_hash(key)) & mask; }
}  // namespace

StencilTableBuilder::StencilTableBuilder(int n_base, int first_row) {
  table_.n_base = n_base;
  table_.row_gap = std::max(0, first_row - n_base);
  table_.offsets.push_back(0);
  grow_lookup(64);
}

void StencilTableBuilder::grow_lookup(size_t slots) {
  std::vector<size_t> keys(slots, 0);
  std::vector<int> rows(slots, kEmptySlot);
  for (size_t i = 0; i < slot_rows_.size(); ++i) {
    if (slot_rows_[i] == kEmptySlot) continue;
    size_t at = slot_of(slot_keys_[i], slots - 1);
    while (rows[at] != kEmptySlot) at = (at + 1) & (slots - 1);
    keys[at] = slot_keys_[i];
    rows[at] = slot_rows_[i];
  }
  slot_keys_ = std::move(keys);
  slot_rows_ = std::move(rows);
}

int& StencilTableBuilder::last_row_of(size_t key) {
  if (2 * (used_slots_ + 1) > slot_rows_.size()) grow_lookup(2 * slot_rows_.size());
  const size_t mask = slot_rows_.size() - 1;
  size_t at = slot_of(key, mask);
  while (slot_rows_[at] != kEmptySlot && slot_keys_[at] != key) at = (at + 1) & mask;
  if (slot_rows_[at] == kEmptySlot) {
    slot_keys_[at] = key;
    slot_rows_[at] = -1;
    ++used_slots_;
  }
  return slot_rows_[at];
}

namespace {
// The (index, weight) terms of one row of a table, as a range.
struct RowTerms {
  struct Iterator {
    const int32_t* index;
    const double* weight;
    std::pair<int, double> operator*() const { return {*index, *weight}; }
    Iterator& operator++() {
      ++index, ++weight;
      return *this;
    }
    bool operator!=(const Iterator& o) const { return index != o.index; }
  };
  const StencilTable& table;
  int row;
  Iterator begin() const { return at(table.offsets[size_t(row)]); }
  Iterator end() const { return at(table.offsets[size_t(row) + 1]); }
  Iterator at(int k) const { return {table.indices.data() + k, table.weights.data() + k}; }
};
}  // namespace

int StencilTableBuilder::add(const Stencil& s) {
  if (const int v = s.as_vertex(); v >= 0) return v;
  assert(!s.empty() && std::abs(s.weight_sum() - 1.0) < 1e-9);
  return add_terms(s.terms(), key_of(s.terms()));
}

size_t StencilTableBuilder::row_key(const StencilTable& table, int row) { return key_of(RowTerms{table, row}); }

// A hash of the nonzero terms, and their number.
template <class Terms>
size_t StencilTableBuilder::key_of(const Terms& terms) {
  size_t hash = 0, n_terms = 0;
  for (const auto& [index, weight] : terms)
    if (weight != 0.0) {
      hash = (hash * 0x9e3779b97f4a7c15ull) ^ (size_t(index) * 31 + std::bit_cast<size_t>(weight));
      ++n_terms;
    }
  return hash ^ n_terms;
}

template <class Terms>
int StencilTableBuilder::add_terms(const Terms& terms, size_t key) {
  // Zero weights are skipped in the key, the comparison and the row alike (no copy of the terms).
  size_t n_terms = 0;
  for (const auto& term : terms) n_terms += term.second != 0.0 ? 1 : 0;
  int& last = last_row_of(key);
  for (int row = last; row >= 0; row = previous_same_hash_[size_t(row)]) {
    const int b = table_.offsets[size_t(row)], e = table_.offsets[size_t(row) + 1];
    if (e - b != int(n_terms)) continue;
    bool same = true;
    int k = b;
    for (const auto& [index, weight] : terms) {
      if (weight == 0.0) continue;
      same = table_.indices[size_t(k)] == index && table_.weights[size_t(k)] == weight;
      if (!same) break;
      ++k;
    }
    if (same) return table_.first_row() + row;
  }
  const int row = table_.n_rows();
  for (const auto& [index, weight] : terms) {
    if (weight == 0.0) continue;
    table_.indices.push_back(index);
    table_.weights.push_back(weight);
  }
  table_.offsets.push_back(int(table_.indices.size()));
  previous_same_hash_.push_back(last);
  last = row;
  return table_.first_row() + row;
}

std::vector<Dual> apply_stencils(const StencilTable& t, const std::vector<Dual>& base) {
  std::vector<Dual> points(size_t(t.n_points()));
  std::copy(base.begin(), base.end(), points.begin());
  std::fill(points.begin() + t.n_base, points.begin() + t.first_row(), Dual::Zero());
  for (int r = 0; r < t.n_rows(); ++r) {
    Dual sum = Dual::Zero();
    for (int k = t.offsets[size_t(r)]; k < t.offsets[size_t(r) + 1]; ++k)
      sum += t.weights[size_t(k)] * base[size_t(t.indices[size_t(k)])];
    points[size_t(t.first_row() + r)] = sum;
  }
  return points;
}

StencilDependents stencil_dependents(const StencilTable& t) {
  StencilDependents d;
  transpose_lists(t.offsets, t.indices, t.n_base, d.offsets, d.rows);
  return d;
}

void update_stencils(const StencilTable& t, const StencilDependents& d, const std::vector<int>& changed,
                     std::vector<Dual>& points) {
  const auto apply_row = [&](int r) {
    Dual sum = Dual::Zero();
    for (int k = t.offsets[size_t(r)]; k < t.offsets[size_t(r) + 1]; ++k)
      sum += t.weights[size_t(k)] * points[size_t(t.indices[size_t(k)])];
    points[size_t(t.first_row() + r)] = sum;
  };
  size_t n_dependents = 0;
  for (const int v : changed) n_dependents += size_t(d.offsets[size_t(v) + 1] - d.offsets[size_t(v)]);
  if (update_everything(n_dependents, size_t(t.n_rows()))) {
    for (int r = 0; r < t.n_rows(); ++r) apply_row(r);
    return;
  }
  if (changed.size() == 1) {  // one vertex's rows are already sorted and unique
    const int v = changed[0];
    for (int i = d.offsets[size_t(v)]; i < d.offsets[size_t(v) + 1]; ++i) apply_row(d.rows[size_t(i)]);
    return;
  }
  for (const int r : rows_reading(d, changed)) apply_row(r);
}

std::vector<int> rows_reading(const StencilDependents& dependents, const std::vector<int>& vertices) {
  return union_of_lists(dependents.offsets, dependents.rows, vertices);
}

}  // namespace gps
