// A range's plans cut down to a run of its faces (core/plans/range_plans.h, cut_range), and two ranges
// joined (append_range), are what building those faces alone gives, bit for bit, on quad, triangle,
// split-face, open and creased meshes: the replanner keeps the untouched runs of a range that a change
// reaches, and joins the short ranges changes leave.
#include <gtest/gtest.h>

#include <random>

#include "core/extraordinary/loop_crease_tables.h"
#include "core/extraordinary/loop_extraordinary_tables.h"
#include "core/extraordinary/quad_extraordinary_tables.h"
#include "core/plans/loop_crease_plan_builder.h"
#include "core/plans/loop_plan_builder.h"
#include "core/plans/range_plans.h"
#include "core/plans/stencil_table.h"
#include "tests/support/plan_tables.h"
#include "tests/support/random_operations.h"

namespace gps {
namespace {

void expect_same_range(const RangePlans& a, const RangePlans& b, const std::string& where) {
  test::expect_same_tables(a.tables, b.tables, where);
  EXPECT_EQ(a.extraordinary_tables, b.extraordinary_tables) << where;  // the same tables, by pointer
}

// The ranges of a test case's faces: Catmull-Clark's exact nodes at depth 2 and the thesis' Bézier
// patches at depth 3 by turns (`trial`), or Loop's, smooth or creased.
class RangeBuilder {
public:
  explicit RangeBuilder(const test::RandomOperationCase& c)
      : loop_(c.scheme == Scheme::loop), base_(base_local_mesh(c.mesh.topology(), c.mesh.sharpness)) {}
  RangePlans build(int first, int last, int trial) {
    const bool bezier = trial % 2 == 1;
    if (loop_ && !base_.has_creases())
      return build_loop_range(base_.topology(), base_.connectivity(), first, last, LoopBeta::loop, smooth_tables_);
    return loop_
               ? build_creased_loop_range(base_, first, last, LoopBeta::loop, loop_tables_)
               : build_quad_range(base_, first, last, bezier ? 3 : 2,
                                  bezier ? ExtraordinaryNodes::bezier : ExtraordinaryNodes::exact, true, quad_tables_);
  }

private:
  bool loop_;
  LocalMesh base_;
  QuadExtraordinaryTableCache quad_tables_;
  LoopCreaseTables loop_tables_{LoopBeta::loop};
  LoopExtraordinaryTableCache smooth_tables_{LoopBeta::loop};
};

TEST(RangePlans, ARunCutFromARangeIsWhatItsFacesBuildAlone) {
  for (const test::RandomOperationCase& c : test::random_operation_cases()) {
    const PolygonTopology& t = c.mesh.topology();
    const bool loop = c.scheme == Scheme::loop;
    RangeBuilder ranges(c);
    int trial = 0;
    const auto build = [&](int first, int last) { return ranges.build(first, last, trial); };
    const auto patches = [&](int first, int last) {
      int n = 0;
      for (int f = first; f < last; ++f) n += loop || t.face_size(f) == 4 ? 1 : t.face_size(f);
      return n;
    };
    std::mt19937 random(7);
    const int n_faces = t.n_faces();
    for (; trial < 12; ++trial) {
      // A range [a, b) and a run [i, j) inside it; the first trial cuts a range whole.
      std::uniform_int_distribution<int> pick(0, n_faces);
      int a = pick(random), b = pick(random);
      if (a > b) std::swap(a, b);
      if (a == b) continue;
      int i = std::uniform_int_distribution<int>(a, b - 1)(random);
      int j = std::uniform_int_distribution<int>(i + 1, b)(random);
      if (trial == 0) a = i = 0, b = j = n_faces;
      const std::string where = c.name + ": faces [" + std::to_string(i) + ", " + std::to_string(j) + ") of [" +
                                std::to_string(a) + ", " + std::to_string(b) + ")";
      const RangePlans range = build(a, b);
      RangePlans piece;
      ASSERT_TRUE(cut_range(range, patches(a, i), patches(a, j), piece)) << where;
      expect_same_range(piece, build(i, j), where);
    }
  }
}

// Two neighbouring ranges appended one to the other are what their faces build as one range, bit for
// bit, their row keys included: the replanner joins the short ranges that changes leave.
TEST(RangePlans, ARangeAppendedToTheOneBeforeIsWhatTheirFacesBuildTogether) {
  for (const test::RandomOperationCase& c : test::random_operation_cases()) {
    const PolygonTopology& t = c.mesh.topology();
    RangeBuilder ranges(c);
    std::mt19937 random(11);
    for (int trial = 0; trial < 12; ++trial) {
      const auto build = [&](int first, int last) { return ranges.build(first, last, trial); };
      const int n_faces = t.n_faces();
      // Faces [a, i) and [i, b), hashed or not by turns; the first trial starts from an empty range.
      std::uniform_int_distribution<int> pick(0, n_faces);
      int a = pick(random), b = pick(random);
      if (a > b) std::swap(a, b);
      const int i = trial == 0 ? a : std::uniform_int_distribution<int>(a, b)(random);
      const std::string where = c.name + ": faces [" + std::to_string(a) + ", " + std::to_string(i) + ") and [" +
                                std::to_string(i) + ", " + std::to_string(b) + ")";
      std::vector<RangePlans> parts = {build(a, i), build(i, b)};
      const bool merged = trial % 3 != 2;  // keys and firsts, as a replanner keeps them
      const SurfaceTables before = merged ? merge_ranges(parts, t.n_vertices, false) : SurfaceTables{};
      append_range(parts[0], parts[1]);
      const RangePlans whole = build(a, b);
      expect_same_range(parts[0], whole, where);
      std::vector<RangePlans> hashed = {whole};
      const SurfaceTables anew = merge_ranges(hashed, t.n_vertices, false);
      EXPECT_EQ(parts[0].row_keys.empty() ? hashed[0].row_keys : parts[0].row_keys, hashed[0].row_keys) << where;
      if (!merged || i == a) continue;
      // What the merge of the parts found is kept: merged again, the joined range follows it, and every
      // row is kept from the merge of the parts, in place.
      std::vector<KeptStencilRows> kept;
      std::vector<RangePlans> joined = {parts[0]};
      ASSERT_NE(joined[0].row_firsts.table, 0) << where;
      test::expect_same_tables(merge_ranges(joined, t.n_vertices, false, nullptr, 0, nullptr, &kept), anew, where);
      const int n_rows = before.stencils.n_rows();
      std::vector<KeptStencilRows> every_row;
      if (n_rows > 0) every_row.push_back({0, 0, n_rows});
      EXPECT_EQ(kept, every_row) << where;
    }
  }
}

// Ranges numbered on two bases are joined on the larger: the same points as each read before.
TEST(RangePlans, RangesOverTwoBasesAreJoinedOnTheLarger) {
  const CovarianceMesh mesh = make_sample("cylinder");
  const PolygonTopology& t = mesh.topology();
  const LocalMesh base = base_local_mesh(t, mesh.sharpness);
  QuadExtraordinaryTableCache tables;
  const int half = t.n_faces() / 2, extra = 5;
  RangePlans first = build_quad_range(base, 0, half, 2, ExtraordinaryNodes::exact, true, tables);
  const RangePlans second = build_quad_range(base, half, t.n_faces(), 2, ExtraordinaryNodes::exact, true, tables);
  RangePlans later = second;  // as if numbered on a base with more vertices since
  const int own = t.n_vertices;
  for_each_point(later.tables.plans, [&](int32_t& x) { x = x < own ? x : x + extra; });
  later.tables.stencils.n_base += extra;
  RangePlans joined = first;
  append_range(joined, later);
  std::vector<RangePlans> apart = {first, second}, together = {joined};
  const SurfaceTables a = merge_ranges(apart, own + extra, true), b = merge_ranges(together, own + extra, true);
  test::expect_same_tables(a, b, "joined over two bases");
}

// The row keys a merge stored go with the rows they key.
TEST(RangePlans, ACutKeepsTheKeysOfItsRows) {
  const CovarianceMesh mesh = make_sample("cylinder");
  const PolygonTopology& t = mesh.topology();
  const LocalMesh base = base_local_mesh(t, mesh.sharpness);
  QuadExtraordinaryTableCache tables;
  std::vector<RangePlans> ranges = {build_quad_range(base, 0, t.n_faces(), 2, ExtraordinaryNodes::exact, true, tables)};
  merge_ranges(ranges, t.n_vertices, false);
  RangePlans piece;
  ASSERT_TRUE(cut_range(ranges[0], 3, ranges[0].tables.plans.n_patches() - 2, piece));
  ASSERT_EQ(piece.row_keys.size(), size_t(piece.tables.stencils.n_rows()));
  for (int row = 0; row < piece.tables.stencils.n_rows(); ++row)
    EXPECT_EQ(piece.row_keys[size_t(row)], StencilTableBuilder::row_key(piece.tables.stencils, row)) << row;
}

// Patches whose nodes are not one run, root first, are refused, not cut wrongly.
TEST(RangePlans, NodesOutOfTheirRunAreRefused) {
  const CovarianceMesh mesh = make_sample("sphere", 96);
  const LocalMesh base = base_local_mesh(mesh.topology(), mesh.sharpness);
  QuadExtraordinaryTableCache tables;
  RangePlans range = build_quad_range(base, 0, 10, 3, ExtraordinaryNodes::exact, true, tables);
  int internal = -1;  // a patch refined around an extraordinary vertex
  for (int p = 0; p < range.tables.plans.n_patches() && internal < 0; ++p)
    if (node_kind(range.tables.plans.nodes[size_t(range.tables.plans.patch_roots[size_t(p)])]) == kNodeInternal)
      internal = p;
  ASSERT_GE(internal, 0);
  RangePlans piece;
  EXPECT_TRUE(cut_range(range, internal, internal + 1, piece));
  // Its first child pointed back to its root: outside the run that follows the root.
  const size_t root = size_t(range.tables.plans.patch_roots[size_t(internal)]);
  range.tables.plans.nodes[root + 1] = int32_t(root);
  EXPECT_FALSE(cut_range(range, internal, internal + 1, piece));
}

}  // namespace
}  // namespace gps
