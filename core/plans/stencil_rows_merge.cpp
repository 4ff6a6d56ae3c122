#include "core/plans/stencil_rows_merge.h"

#include <algorithm>
#include <atomic>
#include <optional>
#include <unordered_map>

#if defined(_OPENMP)
#include <omp.h>
#endif

#include "core/plans/stencil_table.h"
#include "core/support/hash_mix.h"

namespace gps {

namespace {

// Fewer rows are merged on one core: starting the others costs more.
constexpr size_t kParallelRows = 1 << 14;

// Appends the rows of `run` to `kept` as one row after another: a row that is behind the last run's
// end in either numbering is left out, one at its end in both extends it, any other starts a run.
void join_kept_rows(std::vector<KeptStencilRows>& kept, KeptStencilRows run) {
  if (!kept.empty()) {
    KeptStencilRows& last = kept.back();
    const int behind = std::max({0, last.first + last.count - run.first, last.old_first + last.count - run.old_first});
    if (behind >= run.count) return;
    run = {run.first + behind, run.old_first + behind, run.count - behind};
    if (last.first + last.count == run.first && last.old_first + last.count == run.old_first) {
      last.count += run.count;
      return;
    }
  }
  kept.push_back(run);
}

long long new_table_id() {
  static std::atomic<long long> last{0};
  return ++last;
}

// The rows of all tables as one sequence, row r of table t at start[t] + r.
class RowSequence {
public:
  RowSequence(const std::vector<const StencilTable*>& tables, const std::vector<const std::vector<size_t>*>& keys)
      : tables_(tables), keys_(keys), start_(tables.size() + 1, 0) {
    for (size_t t = 0; t < tables.size(); ++t) start_[t + 1] = start_[t] + size_t(tables[t]->n_rows());
  }
  size_t size() const { return start_.back(); }
  size_t n_tables() const { return tables_.size(); }
  size_t start(size_t t) const { return start_[t]; }
  int n_rows(size_t t) const { return tables_[t]->n_rows(); }
  const StencilTable& table(size_t t) const { return *tables_[t]; }
  size_t key(size_t t, int r) const { return (*keys_[t])[size_t(r)]; }
  size_t table_of(size_t i) const {
    return size_t(std::upper_bound(start_.begin(), start_.end(), i) - start_.begin()) - 1;
  }
  bool same_terms_at(size_t i, size_t j) const {
    const size_t t = table_of(i), u = table_of(j);
    return same_row_terms(table(t), int(i - start_[t]), table(u), int(j - start_[u]));
  }

private:
  const std::vector<const StencilTable*>& tables_;
  const std::vector<const std::vector<size_t>*>& keys_;
  std::vector<size_t> start_;
};

// Per row of the sequence, the first row with the same terms (itself for the first). The keys are
// shared out among the cores by their hash; each core finds the first rows of its keys in sequence
// order, so the result is that of adding the rows one after another.
std::vector<int> first_rows_found_anew(const RowSequence& rows) {
  const size_t n = rows.size();
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
    for (size_t t = 0; t < rows.n_tables(); ++t)
      for (int r = 0; r < rows.n_rows(t); ++r) {
        const size_t key = rows.key(t, r), hash = size_t(mixed_hash(key));
        if (hash % shards != shard) continue;
        const size_t i = rows.start(t) + size_t(r);
        size_t at = (hash / shards) & mask;
        while (slot[at].newest >= 0 && slot[at].key != key) at = (at + 1) & mask;
        int found = -1;
        for (int j = slot[at].newest; j >= 0 && found < 0; j = previous_same_key[size_t(j)])
          if (rows.same_terms_at(i, size_t(j))) found = j;
        if (found >= 0) {
          first[i] = found;
          continue;
        }
        first[i] = int(i);
        previous_same_key[i] = slot[at].newest;
        slot[at] = {key, int(i)};
      }
  }
  return first;
}

// The same from what the last merge found, where the tables kept from it (a usable `firsts`, in the
// order they had) hold most rows; empty otherwise. A row whose first row is still there keeps it unless
// a new table has its terms before it; a row whose first row is gone is placed again among those of its
// terms, which all named the same first row and so are all such rows.
std::vector<int> first_rows_followed(const RowSequence& rows, const std::vector<StencilRowFirsts*>& firsts,
                                     std::vector<size_t>& placed_rows) {
  const size_t n_tables = rows.n_tables();
  if (firsts.size() != n_tables) return {};
  const auto kept = [&](size_t t) {
    return firsts[t] && firsts[t]->table != 0 && firsts[t]->of_row.size() == size_t(rows.n_rows(t)) &&
           firsts[t]->of_table.size() == firsts[t]->of_row.size();
  };
  std::unordered_map<long long, size_t> position;  // a kept table's id → its place now
  size_t fresh_rows = 0;
  int last_position = -1;
  for (size_t t = 0; t < n_tables; ++t) {
    if (!kept(t)) {
      fresh_rows += size_t(rows.n_rows(t));
      continue;
    }
    if (firsts[t]->position <= last_position) return {};  // kept tables out of their order
    last_position = firsts[t]->position;
    position.emplace(firsts[t]->table, t);
  }
  if (position.empty() || 4 * fresh_rows > rows.size()) return {};

  // The terms of the rows to place, each kind once: a row of it, and the first row found so far.
  struct Terms {
    size_t row;
    int first;
  };
  std::vector<Terms> terms;
  std::unordered_map<size_t, std::vector<int>> terms_of_key;
  // The keys in terms_of_key as bits of their hash: most kept rows share no key with a row to place,
  // and are passed over without a look in the map.
  size_t key_bits_size = 64;
  while (key_bits_size < 64 * (fresh_rows + 64)) key_bits_size *= 2;
  std::vector<uint64_t> key_bits(key_bits_size / 64, 0);
  const auto key_bit = [mask = key_bits_size - 1](size_t key) { return size_t(mixed_hash(key)) & mask; };
  const auto find = [&](size_t i, size_t key) {
    if (const size_t bit = key_bit(key); !((key_bits[bit / 64] >> (bit % 64)) & 1)) return -1;
    if (const auto at = terms_of_key.find(key); at != terms_of_key.end())
      for (const int c : at->second)
        if (rows.same_terms_at(i, terms[size_t(c)].row)) return c;
    return -1;
  };
  const auto place = [&](size_t i, size_t key, int first) {
    int c = find(i, key);
    if (c < 0) {
      c = int(terms.size());
      terms.push_back({i, first});
      terms_of_key[key].push_back(c);
      const size_t bit = key_bit(key);
      key_bits[bit / 64] |= uint64_t(1) << (bit % 64);
    }
    terms[size_t(c)].first = std::min(terms[size_t(c)].first, first);
    return c;
  };
  std::vector<std::pair<size_t, int>> placed;  // a row and its terms
  for (size_t t = 0; t < n_tables; ++t)
    if (!kept(t))
      for (int r = 0; r < rows.n_rows(t); ++r) {
        const size_t i = rows.start(t) + size_t(r);
        placed.emplace_back(i, place(i, rows.key(t, r), int(i)));
      }

  // The kept rows on all cores: their first row where it stands; the others listed per table.
  std::vector<int> first(rows.size());
  std::vector<std::vector<std::pair<size_t, int>>> beside_new(n_tables);  // a row, and where its first row is
  std::vector<std::vector<size_t>> first_gone(n_tables);
#pragma omp parallel for schedule(dynamic) if (rows.size() >= kParallelRows)
  for (size_t t = 0; t < n_tables; ++t) {
    if (!kept(t)) continue;
    const StencilRowFirsts& f = *firsts[t];
    // A table's rows name few tables, mostly in runs: the last one's place is looked up once.
    long long last_table = 0;  // no table has id 0
    std::optional<size_t> last_place;
    for (int r = 0; r < rows.n_rows(t); ++r) {
      const size_t i = rows.start(t) + size_t(r);
      if (const long long table = f.of_table[size_t(r)]; table != last_table) {
        const auto at = position.find(table);
        last_table = table;
        last_place = at == position.end() ? std::nullopt : std::optional<size_t>(at->second);
      }
      if (!last_place) {
        first_gone[t].push_back(i);
        continue;
      }
      const int was = int(rows.start(*last_place)) + f.of_row[size_t(r)];
      if (const int c = find(i, rows.key(t, r)); c >= 0)
        beside_new[t].emplace_back(i, was);
      else
        first[i] = was;
    }
  }
  for (size_t t = 0; t < n_tables; ++t) {
    for (const auto& [i, was] : beside_new[t])
      placed.emplace_back(i, place(i, rows.key(t, int(i - rows.start(t))), was));
    for (const size_t i : first_gone[t]) placed.emplace_back(i, place(i, rows.key(t, int(i - rows.start(t))), int(i)));
  }
  placed_rows.clear();
  for (const auto& [i, c] : placed) {
    first[i] = terms[size_t(c)].first;
    placed_rows.push_back(i);
  }
  return first;
}

}  // namespace

MergedStencilRows merge_stencil_rows(const std::vector<const StencilTable*>& tables,
                                     const std::vector<const std::vector<size_t>*>& keys, int n_base, int first_row,
                                     const std::vector<StencilRowFirsts*>& firsts, StencilTable* storage,
                                     size_t storage_leading) {
  const RowSequence rows(tables, keys);
  const size_t n_tables = tables.size(), n = rows.size();
  std::vector<size_t> placed;  // where the last merge's firsts were followed: the rows whose first row was found again
  std::vector<int> first = first_rows_followed(rows, firsts, placed);
  const bool followed = n > 0 && first.size() == n;  // empty: not followed
  if (!followed) first = first_rows_found_anew(rows);

  // The first rows numbered in sequence order, with where their terms go: counted per table, then
  // numbered and copied on all cores.
  MergedStencilRows out;
  StencilTable& table = out.table;
  size_t held_offsets = 0, held_terms = 0;
  if (storage) {  // every element past its leading tables' rows is written
    held_offsets = storage->offsets.size();
    held_terms = std::min(storage->indices.size(), storage->weights.size());
    table.offsets = std::move(storage->offsets);
    table.indices = std::move(storage->indices);
    table.weights = std::move(storage->weights);
  }
  table.n_base = n_base;
  table.row_gap = std::max(0, first_row - n_base);
  std::vector<int> table_rows(n_tables + 1, 0), table_terms(n_tables + 1, 0);
#pragma omp parallel for schedule(dynamic) if (n >= kParallelRows)
  for (size_t t = 0; t < n_tables; ++t) {
    const StencilTable& s = rows.table(t);
    int n_rows = 0, n_terms = 0;  // counted here, written once: the cores' counts share cache lines
    for (int r = 0; r < s.n_rows(); ++r)
      if (const size_t i = rows.start(t) + size_t(r); first[i] == int(i)) {
        ++n_rows;
        n_terms += s.offsets[size_t(r) + 1] - s.offsets[size_t(r)];
      }
    table_rows[t + 1] = n_rows;
    table_terms[t + 1] = n_terms;
  }
  for (size_t t = 0; t < n_tables; ++t) {
    table_rows[t + 1] += table_rows[t];
    table_terms[t + 1] += table_terms[t];
  }
  storage_leading = std::min(storage_leading, n_tables);
  if (!storage || held_offsets < size_t(table_rows[storage_leading]) ||
      held_terms < size_t(table_terms[storage_leading]))
    storage_leading = 0;
  table.offsets.resize(size_t(table_rows.back()) + 1);
  table.offsets.back() = table_terms.back();
  table.indices.resize(size_t(table_terms.back()));
  table.weights.resize(size_t(table_terms.back()));
  std::vector<int> number(n);  // per first row: its row in the table
#pragma omp parallel for schedule(dynamic) if (n >= kParallelRows)
  for (size_t t = 0; t < n_tables; ++t) {
    const StencilTable& s = rows.table(t);
    int row = table_rows[t], at = table_terms[t];
    if (t < storage_leading) {  // its rows are in the storage already: numbered only
      for (int r = 0; r < s.n_rows(); ++r)
        if (const size_t i = rows.start(t) + size_t(r); first[i] == int(i)) number[i] = row++;
      continue;
    }
    for (int r = 0; r < s.n_rows(); ++r) {
      const size_t i = rows.start(t) + size_t(r);
      if (first[i] != int(i)) continue;
      number[i] = row;
      table.offsets[size_t(row++)] = at;
      const int from = s.offsets[size_t(r)], count = s.offsets[size_t(r) + 1] - from;
      std::copy_n(s.indices.begin() + from, count, table.indices.begin() + at);
      std::copy_n(s.weights.begin() + from, count, table.weights.begin() + at);
      at += count;
    }
  }
  out.points.resize(n_tables);
#pragma omp parallel for schedule(dynamic) if (n >= kParallelRows)
  for (size_t t = 0; t < n_tables; ++t) {
    out.points[t].resize(size_t(rows.n_rows(t)));
    for (int r = 0; r < rows.n_rows(t); ++r)
      out.points[t][size_t(r)] = table.first_row() + number[size_t(first[rows.start(t) + size_t(r)])];
  }
  // The rows of the tables kept from the merge before, each with its row then (both in order): each
  // table's in runs consecutive in both, on all cores, then the runs joined in table order.
  if (followed) {
    std::vector<std::vector<KeptStencilRows>> table_runs(n_tables);
#pragma omp parallel for schedule(dynamic) if (n >= kParallelRows)
    for (size_t t = 0; t < n_tables; ++t) {
      const StencilRowFirsts& f = *firsts[t];
      if (f.table == 0 || f.merged_row.size() != size_t(rows.n_rows(t))) continue;
      std::vector<KeptStencilRows> runs;
      for (int r = 0; r < rows.n_rows(t); ++r) {
        const size_t i = rows.start(t) + size_t(r);
        if (first[i] != int(i)) continue;
        const int now = number[i], then = f.merged_row[size_t(r)];
        if (!runs.empty() && runs.back().first + runs.back().count == now &&
            runs.back().old_first + runs.back().count == then)
          ++runs.back().count;
        else
          runs.push_back({now, then, 1});
      }
      table_runs[t] = std::move(runs);
    }
    for (const std::vector<KeptStencilRows>& runs : table_runs)
      for (const KeptStencilRows& run : runs) join_kept_rows(out.kept, run);
  }

  // What this merge found, for the next: of every row where found anew (or of a table merged first),
  // else of the rows placed again.
  if (firsts.size() != n_tables) return out;
  std::vector<char> whole(n_tables, !followed);
  for (size_t t = 0; t < n_tables; ++t) {
    if (!firsts[t]) continue;
    StencilRowFirsts& f = *firsts[t];
    if (f.table == 0 || f.of_row.size() != size_t(rows.n_rows(t))) {
      f = {new_table_id(),
           -1,
           std::vector<long long>(size_t(rows.n_rows(t))),
           std::vector<int>(size_t(rows.n_rows(t))),
           {}};
      whole[t] = 1;
    }
    f.position = int(t);
    f.merged_row.resize(size_t(rows.n_rows(t)));
  }
  const auto note = [&](size_t t, size_t i) {
    const size_t j = size_t(first[i]), u = j >= rows.start(t) && j < rows.start(t + 1) ? t : rows.table_of(j);
    StencilRowFirsts& f = *firsts[t];
    f.of_table[i - rows.start(t)] = firsts[u] ? firsts[u]->table : 0;
    f.of_row[i - rows.start(t)] = int(j - rows.start(u));
  };
#pragma omp parallel for schedule(dynamic) if (n >= kParallelRows)
  for (size_t t = 0; t < n_tables; ++t) {
    if (!firsts[t]) continue;
    for (int r = 0; r < rows.n_rows(t); ++r) firsts[t]->merged_row[size_t(r)] = out.points[t][size_t(r)] - first_row;
    if (whole[t])
      for (int r = 0; r < rows.n_rows(t); ++r) note(t, rows.start(t) + size_t(r));
  }
  for (const size_t i : placed)
    if (const size_t t = rows.table_of(i); firsts[t] && !whole[t]) note(t, i);
  return out;
}

void rename_appended_rows(StencilRowFirsts& firsts, const std::vector<AppendedRows>& appended) {
  // A table's rows name few tables, mostly in runs: the last one's entry is looked up once.
  long long last_table = 0;  // no table has id 0
  const AppendedRows* entry = nullptr;
  for (size_t r = 0; r < firsts.of_table.size() && r < firsts.of_row.size(); ++r) {
    if (const long long table = firsts.of_table[r]; table != last_table) {
      last_table = table;
      const auto at =
          std::find_if(appended.begin(), appended.end(), [&](const AppendedRows& a) { return a.from == table; });
      entry = at == appended.end() ? nullptr : &*at;
    }
    if (!entry) continue;
    firsts.of_table[r] = entry->to;
    firsts.of_row[r] = entry->rows[size_t(firsts.of_row[r])];
  }
}

}  // namespace gps
