// The surface cache's edits (render/cache/surface_cache.h): a refresh brings the stale blocks up to
// date, their welded vertices evaluated again where their tessellation stays, the others captured
// again and copied into place or assembled with the clean blocks.
#include <glad/gl.h>

#include <algorithm>
#include <iterator>

#include "render/gl/gl_context.h"
#include "render/gl/gpu_layout.h"
#include "render/cache/surface_cache.h"

namespace gps {

bool SurfaceCache::refresh(const Key& key, const DrawPatches& draw_patches, const EvaluateWelded& evaluate_welded,
                           const LevelsChanged& levels_changed, const PatchTriangles& patch_triangles) {
  GLint capture_program = 0;  // the compute passes below change it
  glGetIntegerv(GL_CURRENT_PROGRAM, &capture_program);
  // A change of topology's blocks that keep patches at their ends: split there, where those patches'
  // triangles lie by their counts, so that only the patches between are captured again.
  if (topology_pending_ && patch_triangles_agree_ && patch_triangles && copy_pending_.empty()) {
    const std::vector<int> ends = blocks_.kept_end_patches();
    if (!ends.empty()) {
      const std::vector<int> counts = patch_triangles(ends);
      if (counts.size() == ends.size()) blocks_.split_kept_ends(counts);
    }
  }
  const std::vector<int> stale = blocks_.stale();
  const bool uniform = key.pixels <= 0.0f;
  // The stale blocks whose tessellation stays: all at uniform levels; at adaptive ones, those whose
  // patches keep their levels (the check also keeps the new levels of the others).
  // After a change of topology none do: their patches may be others (the check still keeps the levels).
  std::vector<char> kept(stale.size(), uniform && !topology_pending_ ? 1 : 0);
  if (!uniform && levels_changed) {
    std::vector<StoredPatchLevels::Block> patches;
    for (const int b : stale) patches.push_back({blocks_.first_patch(b), blocks_.patches_in(b)});
    const std::vector<char> changed = levels_changed(patches);
    for (size_t i = 0; i < stale.size(); ++i) kept[i] = !changed[i] && !topology_pending_;
  }
  // Kept blocks with welded vertices are evaluated again where they are (render/cache/stored_vertex_evaluation.h)
  // from uniform level evaluated_from_level() on, and at adaptive levels; the others captured again.
  const bool evaluate =
      evaluate_welded && stored_vertices_welded() && (!uniform || key.level >= evaluated_from_level());
  std::vector<int> evaluated, captured;
  bool captured_kept = true;
  int captured_patches = 0;
  for (size_t i = 0; i < stale.size(); ++i) {
    if (evaluate && kept[i]) {
      evaluated.push_back(stale[i]);
    } else {
      captured.push_back(stale[i]);
      captured_kept = captured_kept && kept[i];
      captured_patches += blocks_.patches_in(stale[i]);
    }
  }
  // Captured again: past half of the patches, little less than capturing them all (after a change of
  // topology, past a quarter: topology_changed() gives such changes up).
  if (2 * captured_patches > blocks_.n_patches()) return false;
  // A welded vertex on a block's edge may stand for copies in the blocks beside it, which are stale
  // too where it changed (core/plans/patch_readers.h: an edit's patches and their neighbours). So with
  // some blocks captured again, the welded vertices of all stale blocks are evaluated, that the
  // evaluated blocks' copies of them are current.
  if (!evaluated.empty())
    evaluate_again(captured.empty() ? evaluated : stale, uniform && key.level >= kThirdOfSlotsFromLevel,
                   evaluate_welded);
  // Blocks captured again are copied into place and welded from their captured vertices, beside
  // clean ones that may be assembled: all captured copies current first.
  if (!captured.empty()) copy_back_evaluated();
  // Blocks whose counts are not those stored (after a change of topology, or an adaptive edit that
  // changed levels): their counts from their patches' levels, where the count pass agrees with the
  // tessellator (counts_captures()): no query per block, which a GPU pays for with a pause of the
  // feedback each.
  const std::vector<long long> counted = !captured.empty() && !captured_kept && counts_captures() && patch_triangles
                                             ? counted_triangles(captured, patch_triangles)
                                             : std::vector<long long>{};
  glUseProgram(GLuint(capture_program));
  evaluated_patches_ = blocks_.stale_patches() - captured_patches;
  if (!captured.empty() && !capture_again(captured, draw_patches, captured_kept, counted)) return false;
  // A drag that evaluates keeps its vertices welded for its next edit.
  if (!evaluated.empty()) weld_pending();
  // A change of topology that left every block as it was (no patch added or changed): welded anew
  // all the same, since its patches were renumbered.
  if (topology_pending_ && captured.empty()) weld();
  check_gl_errors("refreshing the surface cache");
  return refreshed(key);
}

// The welded vertices of `blocks` evaluated again; their captured copies later (copy_back_evaluated()). A block's
// welded vertices are fewer than its capture slots; `third`: fewer than a third of them
// (kThirdOfSlotsFromLevel), the bound that sizes the evaluation's dispatches.
void SurfaceCache::evaluate_again(const std::vector<int>& blocks, bool third, const EvaluateWelded& evaluate_welded) {
  std::vector<StoredVertexEvaluation::Block> listed;
  for (const int b : blocks) {
    const long long first = 3 * blocks_.first_triangle(b), slots = 3 * blocks_.triangles(b);
    listed.push_back({b, first, third ? slots / 3 : slots, blocks_.first_patch(b), blocks_.patches_in(b)});
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedVertices, welded_);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gpu::kBindingWeldedParameters, parameters_);
  evaluate_welded(listed, weld_->welded_counts());
  std::vector<int> both;
  std::set_union(copy_pending_.begin(), copy_pending_.end(), blocks.begin(), blocks.end(), std::back_inserter(both));
  copy_pending_ = std::move(both);
}

// `blocks` captured again into the scratch buffer, under the capture's camera, and copied into
// place; where their counts changed (adaptive levels), assembled with the others in the spare buffer.
// `kept`: their levels, and so their counts, are those stored; else `counted`: their counts, where not
// empty, or none known.
bool SurfaceCache::capture_again(const std::vector<int>& blocks, const DrawPatches& draw_patches, bool kept,
                                 const std::vector<long long>& counted) {
  long long stale_triangles = 0, counted_total = 0;
  std::vector<long long> stored;
  for (const int b : blocks) {
    stale_triangles += blocks_.triangles(b);
    if (kept) stored.push_back(blocks_.triangles(b));
  }
  for (const long long c : counted) counted_total += c;
  const std::vector<long long>* known = kept ? &stored : counted.empty() ? nullptr : &counted;
  // Room for more where levels change.
  reserve(scratch_, scratch_capacity_, std::max({2 * stale_triangles, counted_total, 1024ll}));
  std::vector<long long> counts;
  while (!capture_blocks(scratch_, scratch_capacity_, blocks, draw_patches, counts, false, known)) {
    if (scratch_capacity_ >= most_triangles()) return false;
    reserve(scratch_, scratch_capacity_, std::min(2 * scratch_capacity_, most_triangles()));
  }
  bool same_counts = true;
  for (size_t i = 0; i < blocks.size(); ++i) same_counts = same_counts && counts[i] == blocks_.triangles(blocks[i]);
  if (!same_counts) return assemble(blocks, counts);
  copy_into_place(blocks, counts);
  // Their tessellation kept: their vertices keep their welded ones; else (levels changed, the counts
  // alike) welded anew.
  if (kept)
    weld(blocks);
  else
    weld();
  return true;
}

// One copy per run of consecutive blocks (their counts are those stored: they lie together in both buffers).
void SurfaceCache::copy_into_place(const std::vector<int>& blocks, const std::vector<long long>& counts) {
  long long from = 0;
  for (size_t i = 0; i < blocks.size();) {
    const size_t first = i;
    long long triangles = counts[i];
    for (++i; i < blocks.size() && blocks[i] == blocks[i - 1] + 1; ++i) triangles += counts[i];
    if (triangles > 0)
      glCopyNamedBufferSubData(scratch_, buffer_, GLintptr(from * 3 * kCapturedVertexBytes),
                               GLintptr(blocks_.first_triangle(blocks[first]) * 3 * kCapturedVertexBytes),
                               GLsizeiptr(triangles * 3 * kCapturedVertexBytes));
    from += triangles;
  }
}

bool SurfaceCache::refreshed(const Key& key) {
  ++refreshes_;
  topology_pending_ = false;
  refreshed_patches_ = blocks_.stale_patches();
  blocks_.clear_stale();
  key_ = key;
  return true;
}

// The spare buffer, made the stored one: the runs of clean blocks from the stored buffer, the new
// blocks from the scratch buffer, in patch order (or, where only the last blocks changed their counts,
// the stored buffer itself). The spare is kept for the next edit (an adaptive
// edit changes counts every time: no buffer of the whole surface created and deleted per edit; it
// holds up to the memory limit too while edits go on) and released by the next full capture.
bool SurfaceCache::assemble(const std::vector<int>& blocks, const std::vector<long long>& counts) {
  long long total = blocks_.total();
  for (size_t i = 0; i < blocks.size(); ++i) total += counts[i] - blocks_.triangles(blocks[i]);
  if (total >= most_triangles()) return false;
  // Where every block from the first whose count changed on was captured again (patches added at the
  // end), and the stored buffer holds them, the blocks before it stay where they are: written in place.
  size_t first_changed = 0;
  while (first_changed < blocks.size() && counts[first_changed] == blocks_.triangles(blocks[first_changed]))
    ++first_changed;
  if (first_changed < blocks.size() && total <= capacity_ &&
      blocks.size() - first_changed == size_t(blocks_.size() - blocks[first_changed])) {
    blocks_.replace_counts(blocks, counts);
    copy_into_place(blocks, counts);
    weld();
    return true;
  }
  reserve(spare_, spare_capacity_, total + total / 8 + 64);
  const auto copy = [&](unsigned source, long long from, long long to, long long n) {
    if (n > 0)
      glCopyNamedBufferSubData(source, spare_, GLintptr(from * 3 * kCapturedVertexBytes),
                               GLintptr(to * 3 * kCapturedVertexBytes), GLsizeiptr(n * 3 * kCapturedVertexBytes));
  };
  long long to = 0, scratch_from = 0;
  int clean = 0;  // the first block not yet copied
  for (size_t i = 0; i < blocks.size(); ++i) {
    const long long run = blocks_.first_triangle(blocks[i]) - blocks_.first_triangle(clean);
    copy(buffer_, blocks_.first_triangle(clean), to, run);
    to += run;
    copy(scratch_, scratch_from, to, counts[i]);
    to += counts[i];
    scratch_from += counts[i];
    clean = blocks[i] + 1;
  }
  copy(buffer_, blocks_.first_triangle(clean), to, blocks_.total() - blocks_.first_triangle(clean));
  std::swap(buffer_, spare_);
  std::swap(capacity_, spare_capacity_);
  glVertexArrayVertexBuffer(vao_, 0, buffer_, 0, kCapturedVertexBytes);
  blocks_.replace_counts(blocks, counts);
  weld();
  return true;
}

}  // namespace gps
