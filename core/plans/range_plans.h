#pragma once
// The plans of a range of consecutive faces, built apart and merged in face order (docs/design.md §2):
// the whole tables are the same, bit for bit, however the faces are cut into ranges, so ranges build
// on all cores, and a sharpness change rebuilds only the ranges of the faces it reaches
// (core/plans/surface_replanner.h).
#include <functional>
#include <memory>
#include <vector>

#include "core/plans/plan_builder.h"
#include "core/plans/stencil_rows_merge.h"

namespace gps {

/// A range's tables with point indices and node offsets local to it: row r of its own stencil table is
/// point n_base + r, with no gap (that n_base may differ from the merged tables' where base vertices
/// past those it reads were added or removed since); an extraordinary node's table field indexes
/// `extraordinary_tables`, shared (by pointer) by every range built from the same table cache.
struct RangePlans {
  SurfaceTables tables;
  std::vector<std::shared_ptr<const std::vector<double>>> extraordinary_tables;
  std::vector<size_t> row_keys;  // per row of its stencils: StencilTableBuilder::row_key, kept by merge_ranges
  StencilRowFirsts row_firsts;   // what merge_ranges found of its rows, kept for the next merge
};

/// The tables of all ranges in order, as a single range over all faces gives them, their rows from
/// row_start_for(n_base) on (core/plans/patch_plans.h): a row is added where it is first used,
/// extraordinary tables are laid out in the order of first use. `release` frees each range's tables
/// once merged (the whole build's peak memory); a replanner keeps them. `previous`: tables merged
/// before over the same n_base step from ranges whose first `same_leading` were these, unchanged; their
/// part of the plans, which comes out the same, is copied from there. `storage`: tables no longer used,
/// whose plan arrays the merge writes into (their storage reused: none is allocated and filled first).
/// `storage_leading`: the first ranges whose part `storage` holds already as this merge writes it (it was
/// merged over the same n_base step from ranges whose first were these, as `previous` was), at most
/// `same_leading`; their part is not written again. `kept_rows`: where given, the stencil rows that kept
/// ranges hold, and their rows in the tables merged before from them (merge_stencil_rows). `same`:
/// where given, the records of the leading patches that are `previous`'s, bit for bit.
struct LeadingRecords {
  size_t patches = 0, nodes = 0;  // the first patches, and their nodes
};
SurfaceTables merge_ranges(std::vector<RangePlans>& ranges, int n_base, bool release,
                           const SurfaceTables* previous = nullptr, size_t same_leading = 0,
                           SurfaceTables* storage = nullptr, std::vector<KeptStencilRows>* kept_rows = nullptr,
                           size_t storage_leading = 0, LeadingRecords* same = nullptr);

/// The tables of faces [0, n_faces) over n_base vertices: `build_range(first, last)` builds each range of
/// kFacesPerRange faces, on all cores, and the ranges are merged (released). Rethrows the first range's
/// failure.
SurfaceTables build_in_ranges(int n_faces, int n_base, const std::function<RangePlans(int, int)>& build_range);

/// Patches [first, last) of `range` as the range their faces alone build: their nodes, corner points and
/// edges cut out, their rows and extraordinary tables numbered in the order the patches first read them
/// (each patch's nodes, then its corner points, then its edges' ends), which is the order the builders
/// add them in. False where the patches' nodes are not one run, each patch's root first: `piece` is then
/// unspecified and the faces must be built again.
bool cut_range(const RangePlans& range, int first, int last, RangePlans& piece);

/// Appends `next`, the plans of the faces right after `range`'s, to `range`: the range both runs of faces
/// build together, bit for bit where both are numbered on the same base (cut_range the other way).
/// next's records follow range's, its rows whose terms range holds already are dropped and the others
/// numbered after range's, and its extraordinary tables that range holds are not repeated. Over two
/// bases, the points are numbered on the larger. What the last merge found of the rows (row_firsts) is
/// kept where it found both, as range's. Returns next's rows as the range's (AppendedRows, empty where
/// nothing was kept): the ranges after them that named one of next's rows must name the range's
/// (rename_appended_rows) for a merge to follow what the last one found.
AppendedRows append_range(RangePlans& range, const RangePlans& next);

}  // namespace gps
