#pragma once
// Which patches of new tables continue patches of the tables before a change.
#include <algorithm>
#include <vector>

namespace gps {

/// Patches [first, first + count) of a replanner's tables are patches [old_first, old_first + count) of
/// its tables before the last change, their plans kept and renumbered, or built again for faces whose
/// pieces did not change (a plan is a function of its face's piece: the same plan, renumbered).
struct KeptPatches {
  int first = 0, old_first = 0, count = 0;
  bool operator==(const KeptPatches&) const = default;
};

/// Whether every run keeps its numbers (first = old_first): the patches kept are where they were.
inline bool keep_numbers(const std::vector<KeptPatches>& kept) {
  return std::all_of(kept.begin(), kept.end(), [](const KeptPatches& run) { return run.first == run.old_first; });
}

}  // namespace gps
