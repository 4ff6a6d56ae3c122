#include "render/pipeline/plan_buffers.h"

#include <glad/gl.h>

#include <Eigen/LU>
#include <algorithm>
#include <type_traits>
#include <utility>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"
#include "render/pipeline/upload_runs.h"
#include "core/mesh/dual_map.h"
#include "core/support/error.h"

namespace gps {

using namespace gpu;

namespace {

// A run of base vertices copied from one buffer to another: `count` from vertex `from` on to `to` on.
struct CopyRun {
  size_t from = 0, to = 0, count = 0;
};

// The runs of vertices not among `changed` whose origins are consecutive too: what a change of
// topology carries over from the buffers before it.
std::vector<CopyRun> carried_runs(size_t n, const std::vector<int>& origin, const std::vector<int>& changed) {
  std::vector<char> is_changed(n, 0);
  for (const int v : changed) is_changed[size_t(v)] = 1;
  const auto origin_of = [&](size_t v) { return origin.empty() ? long(v) : long(origin[v]); };
  std::vector<CopyRun> runs;
  for (size_t v = 0; v < n;) {
    if (is_changed[v]) {
      ++v;
      continue;
    }
    size_t end = v + 1;
    while (end < n && !is_changed[end] && origin_of(end) == origin_of(end - 1) + 1) ++end;
    runs.push_back({size_t(origin_of(v)), v, end - v});
    v = end;
  }
  return runs;
}

void copy_runs(GLuint from, GLuint to, const std::vector<CopyRun>& runs, size_t stride) {
  for (const CopyRun& run : runs)
    glCopyNamedBufferSubData(from, to, GLintptr(stride * run.from), GLintptr(stride * run.to),
                             GLsizeiptr(stride * run.count));
}

}  // namespace

PlanBuffers::PlanBuffers() {
  GLint64 max_block = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_block);
  max_block_ = size_t(std::max<GLint64>(max_block, 0));
}

template <class T, class Source>
void PlanBuffers::upload_as(int binding, const std::vector<Source>& data, const std::vector<Source>* held,
                            const std::vector<int>* listed, size_t stride, size_t same) {
  // Empty buffers still need storage to be bound.
  const bool stays = reserve(binding, std::max<size_t>(sizeof(T), data.size() * sizeof(T)));
  const std::vector<std::pair<size_t, size_t>> runs =
      stays && held && listed ? listed_runs(*listed, stride, held->size(), data.size())
      : stays && held         ? differing_runs(data, *held, same)
                              : std::vector<std::pair<size_t, size_t>>{{0, data.size()}};
  for (const auto& [begin, end] : runs) {
    if (begin >= end) continue;
    if constexpr (std::is_same_v<T, Source>) {
      glNamedBufferSubData(buffers_[binding], GLintptr(begin * sizeof(T)), GLsizeiptr((end - begin) * sizeof(T)),
                           data.data() + begin);
    } else {
      const std::vector<T> converted(data.begin() + ptrdiff_t(begin), data.begin() + ptrdiff_t(end));
      glNamedBufferSubData(buffers_[binding], GLintptr(begin * sizeof(T)), GLsizeiptr((end - begin) * sizeof(T)),
                           converted.data());
    }
  }
}

bool PlanBuffers::keeps_storage(int binding, size_t bytes) const {
  const size_t capacity = capacities_[binding];
  return bytes <= capacity && capacity / 2 <= bytes;
}

// Storage of at least `bytes` at `binding`, its contents undefined. The storage there is kept where it
// holds them and is not twice as large: tables of about the same size again, as after a modelling
// operation, are written into it instead of a store the driver allocates again. False where new
// storage was allocated.
bool PlanBuffers::reserve(int binding, size_t bytes) {
  sizes_[binding] = bytes;
  size_t& capacity = capacities_[binding];
  if (keeps_storage(binding, bytes)) return true;
  // Room for the tables an operation adds to, within what a shader may see of a buffer bound whole.
  capacity = std::max(bytes, std::min(bytes + bytes / 16, max_block_));
  glNamedBufferData(buffers_[binding], GLsizeiptr(capacity), nullptr, GL_DYNAMIC_DRAW);
  return false;
}

// Gives `binding` the storage of its spare, at least `bytes`, its contents undefined, and keeps the
// buffer it had as the spare; returns that buffer, whose contents the caller copies from. The two
// storages take turns: a change of topology copies what it keeps from one into the other, where the
// driver would otherwise allocate (and clear) a new one every time.
GLuint PlanBuffers::swap_in_spare(int binding, size_t bytes) {
  if (spares_[binding] == 0) spares_[binding] = GlBuffer();
  std::swap(buffers_[binding], spares_[binding]);
  std::swap(capacities_[binding], spare_capacities_[binding]);
  reserve(binding, std::max<size_t>(sizeof(float), bytes));
  return spares_[binding];
}

// Two vec4 per patch corner: limit point and node kind, normal; then one per patch corner: the limit
// point halfway along the edge that starts there (shaders/corner_limit_comp.glsl).
size_t PlanBuffers::corner_limit_floats(const PatchPlans& plans) {
  return size_t(plans.corners()) * size_t(plans.n_patches()) * 8;
}

size_t PlanBuffers::curve_midpoint_floats(const PatchPlans& plans) {
  return size_t(plans.corners()) * size_t(plans.n_patches()) * 4;
}

// Bytes of a point's scalars.
static size_t real_bytes(PointPrecision precision) {
  return precision == PointPrecision::double_float ? sizeof(double) : sizeof(float);
}

void PlanBuffers::check_fits(const SurfaceTables& tables, int n_vertices, int n_faces, long long storage_limit,
                             PointPrecision precision) {
  check_storage_fits("plan points", size_t(tables.stencils.n_points()) * kVec4PerPoint * 4 * real_bytes(precision),
                     n_vertices, n_faces, storage_limit);
  check_storage_fits("stencil weights", tables.stencils.weights.size() * sizeof(float), n_vertices, n_faces,
                     storage_limit);
  check_storage_fits("plan nodes", tables.plans.nodes.size() * sizeof(tables.plans.nodes[0]), n_vertices, n_faces,
                     storage_limit);
  check_storage_fits("corner limits", corner_limit_floats(tables.plans) * sizeof(float), n_vertices, n_faces,
                     storage_limit);
  check_storage_fits("curve midpoints", curve_midpoint_floats(tables.plans) * sizeof(float), n_vertices, n_faces,
                     storage_limit);
}

void PlanBuffers::upload_tables(const SurfaceTables& tables, const std::vector<KeptPatches>& kept,
                                const CarriedPoints* carried, const SurfaceTables* held, const PlanChange* change) {
  const StencilTable& s = tables.stencils;
  const PatchPlans& p = tables.plans;
  const StencilTable* hs = held ? &held->stencils : nullptr;
  const PatchPlans* hp = held ? &held->plans : nullptr;
  upload_as<int32_t>(kBindingOffsets, s.offsets, hs ? &hs->offsets : nullptr);
  upload_as<int32_t>(kBindingIndices, s.indices, hs ? &hs->indices : nullptr);
  upload_as<float>(kBindingWeights, s.weights, hs ? &hs->weights : nullptr);
  // The records of the leading patches that the change left as they were are not compared.
  const LeadingRecords same = hp && change ? change->same_leading : LeadingRecords{};
  const size_t patch_corners = size_t(p.corners()) * same.patches;
  upload_as<int32_t>(kBindingNodes, p.nodes, hp ? &hp->nodes : nullptr, nullptr, 0, same.nodes);
  upload_as<int32_t>(kBindingRoots, p.patch_roots, hp ? &hp->patch_roots : nullptr, nullptr, 0, same.patches);
  upload_as<int32_t>(kBindingCorners, p.patch_corner_points, hp ? &hp->patch_corner_points : nullptr, nullptr, 0,
                     patch_corners);
  upload_as<float>(kBindingExtraordinaryTables, p.extraordinary_tables, hp ? &hp->extraordinary_tables : nullptr);
  upload_as<int32_t>(kBindingPatchEdges, p.patch_edges, hp ? &hp->patch_edges : nullptr, nullptr, 0,
                     p.patch_edges.empty() ? 0 : kPatchEdgeStride * same.patches);
  // The change's lists of the patches whose adjacency records it wrote, where it made these plans from held's.
  const bool listed = hp && change && hp->shape == p.shape;
  const std::vector<int>* neighbours_written =
      listed && change->neighbours_written ? &*change->neighbours_written : nullptr;
  const std::vector<int>* owners_written = listed && change->owners_written ? &*change->owners_written : nullptr;
  const size_t corners = size_t(p.corners());
  upload_as<int32_t>(kBindingPatchNeighbours, p.patch_neighbours, hp ? &hp->patch_neighbours : nullptr,
                     neighbours_written, 4 * corners);
  upload_as<int32_t>(kBindingCornerOwners, p.corner_owners, hp ? &hp->corner_owners : nullptr, owners_written,
                     2 * corners);
  // Every point is written by the compute pass that follows every upload of the tables, but those carried:
  // where each stays where it was, in the storage that holds it (an operation that only adds vertices,
  // or its undo), else copied into the spare storage.
  const size_t point_bytes = kVec4PerPoint * 4 * real_bytes(precision_),
               points_size = size_t(s.n_points()) * point_bytes;
  if (carried) {
    std::vector<CopyRun> runs = carried_runs(size_t(s.n_base), carried->origin, carried->changed);
    for (const KeptStencilRows& rows : carried->rows)
      runs.push_back(
          {size_t(carried->old_first_row + rows.old_first), size_t(s.first_row() + rows.first), size_t(rows.count)});
    const bool in_place = keeps_storage(kBindingPoints, points_size) &&
                          std::all_of(runs.begin(), runs.end(), [](const CopyRun& run) { return run.from == run.to; });
    if (in_place) {
      reserve(kBindingPoints, points_size);
    } else {
      const GLuint before = swap_in_spare(kBindingPoints, points_size);
      copy_runs(before, buffers_[kBindingPoints], runs, point_bytes);
    }
  } else {
    reserve(kBindingPoints, points_size);
  }
  // The points between the base vertices and the first row are read by nothing; zero, as the CPU's.
  if (s.row_gap > 0)
    glClearNamedBufferSubData(buffers_[kBindingPoints], GL_R32UI, GLintptr(size_t(s.n_base) * point_bytes),
                              GLsizeiptr(size_t(s.row_gap) * point_bytes), GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
  // Not cleared here: a pass over every corner clears them first (clear_corner_pass); an edit's pass
  // writes every value of the slots it lists, and that is every slot but those of the kept runs,
  // copied below from the buffers before (zero where a patch does not evaluate it), or left where
  // they are where every kept patch keeps its number and the storage stays.
  const size_t limits_size = corner_limit_floats(p) * sizeof(float),
               midpoints_size = curve_midpoint_floats(p) * sizeof(float);
  const bool kept_in_place =
      keeps_storage(kBindingCornerLimits, limits_size) && keeps_storage(kBindingCurveMidpoints, midpoints_size) &&
      std::all_of(kept.begin(), kept.end(), [](const KeptPatches& run) { return run.first == run.old_first; });
  if (kept.empty() || kept_in_place) {
    reserve(kBindingCornerLimits, limits_size);
    reserve(kBindingCurveMidpoints, midpoints_size);
    return;
  }
  const GLuint limits = swap_in_spare(kBindingCornerLimits, limits_size),
               midpoints = swap_in_spare(kBindingCurveMidpoints, midpoints_size);
  const size_t limit_bytes = size_t(p.corners()) * 8 * sizeof(float),
               midpoint_bytes = size_t(p.corners()) * 4 * sizeof(float);
  for (const KeptPatches& run : kept) {
    glCopyNamedBufferSubData(limits, buffers_[kBindingCornerLimits], GLintptr(limit_bytes * size_t(run.old_first)),
                             GLintptr(limit_bytes * size_t(run.first)), GLsizeiptr(limit_bytes * size_t(run.count)));
    glCopyNamedBufferSubData(
        midpoints, buffers_[kBindingCurveMidpoints], GLintptr(midpoint_bytes * size_t(run.old_first)),
        GLintptr(midpoint_bytes * size_t(run.first)), GLsizeiptr(midpoint_bytes * size_t(run.count)));
  }
}

// Float points: μ, then Σ⁻¹'s xx xy xz yy yz zz (shaders/dual_map_comp.glsl). The inverse is taken
// in double and rounded once: inverted in float, a thin Gaussian's Σ (condition κ) loses κ times
// float's precision in Σ⁻¹, its thin directions' precision first, where the surface's shape is.
static void gaussian_of(const FramedGaussians& gaussians, size_t v, float* out) {
  const Vec3 m = gaussians.mean(v);
  const Mat3 p = gaussians.covariance(v).inverse();
  const double values[9] = {m.x(), m.y(), m.z(), p(0, 0), p(0, 1), p(0, 2), p(1, 1), p(1, 2), p(2, 2)};
  std::copy(values, values + 9, out);
}

// Double points: core's own 9D point q = (Σ⁻¹, q̄) (core/mesh/dual_map.h), kept about μ: μ, Σ⁻¹'s six,
// y = q̄ − Σ⁻¹ μ. Past condition 1e8 a needle's surface follows the rounding of Σ⁻¹ and q̄ (two
// double inverses of one Σ put it apart by a thousandth of the mesh), so the GPU takes the very
// doubles the CPU evaluator sums.
static void gaussian_of(const FramedGaussians& gaussians, size_t v, double* out) {
  const Vec3 m = gaussians.mean(v);
  const Dual q = to_dual(m, gaussians.covariance(v));
  const Vec3 y = Vec3(q.tail<3>()) - unvech(q) * m;
  const double values[12] = {m.x(), m.y(), m.z(), q[0], q[1], q[2], q[3], q[4], q[5], y.x(), y.y(), y.z()};
  std::copy(values, values + 12, out);
}

// Reals per base vertex (shaders/dual_map_comp.glsl, kGaussianReals).
template <class Real>
static constexpr size_t kGaussianReals = sizeof(Real) == sizeof(double) ? 12 : 9;

template <class Real>
void PlanBuffers::upload_gaussians_as(const FramedGaussians& gaussians) {
  std::vector<Real> g(gaussians.n_vertices() * kGaussianReals<Real>);
  for (size_t i = 0; i < gaussians.n_vertices(); ++i) gaussian_of(gaussians, i, &g[kGaussianReals<Real> * i]);
  upload(kBindingGaussians, g);
}

void PlanBuffers::upload_gaussians(const FramedGaussians& gaussians) {
  if (precision_ == PointPrecision::double_float)
    upload_gaussians_as<double>(gaussians);
  else
    upload_gaussians_as<float>(gaussians);
}

template <class Real>
void PlanBuffers::carry_gaussians_as(const FramedGaussians& gaussians, const std::vector<int>& origin,
                                     const std::vector<int>& changed) {
  constexpr size_t stride = kGaussianReals<Real> * sizeof(Real);
  const size_t n = gaussians.n_vertices();
  const std::vector<CopyRun> runs = carried_runs(n, origin, changed);
  // Where every carried vertex keeps its number (an operation that only adds vertices, or its undo),
  // the storage that holds them stays; only the changed ones are written.
  const bool in_place = keeps_storage(kBindingGaussians, n * stride) &&
                        std::all_of(runs.begin(), runs.end(), [](const CopyRun& run) { return run.from == run.to; });
  if (in_place) {
    reserve(kBindingGaussians, n * stride);
  } else {
    const GLuint before = swap_in_spare(kBindingGaussians, n * stride);
    copy_runs(before, buffers_[kBindingGaussians], runs, stride);
  }
  update_gaussians_as<Real>(gaussians, changed);
}

void PlanBuffers::carry_gaussians(const FramedGaussians& gaussians, const std::vector<int>& origin,
                                  const std::vector<int>& changed) {
  if (precision_ == PointPrecision::double_float)
    carry_gaussians_as<double>(gaussians, origin, changed);
  else
    carry_gaussians_as<float>(gaussians, origin, changed);
}

template <class Real>
void PlanBuffers::update_gaussians_as(const FramedGaussians& gaussians, const std::vector<int>& changed) {
  // Runs of consecutive vertices, one upload each.
  std::vector<Real> values;
  for (size_t i = 0; i < changed.size();) {
    size_t j = i + 1;
    while (j < changed.size() && changed[j] == changed[j - 1] + 1) ++j;
    values.resize((j - i) * kGaussianReals<Real>);
    for (size_t k = i; k < j; ++k) gaussian_of(gaussians, size_t(changed[k]), &values[(k - i) * kGaussianReals<Real>]);
    glNamedBufferSubData(buffers_[kBindingGaussians],
                         GLintptr(kGaussianReals<Real> * sizeof(Real) * size_t(changed[i])),
                         GLsizeiptr(values.size() * sizeof(Real)), values.data());
    i = j;
  }
}

void PlanBuffers::update_gaussians(const FramedGaussians& gaussians, const std::vector<int>& changed) {
  if (precision_ == PointPrecision::double_float)
    update_gaussians_as<double>(gaussians, changed);
  else
    update_gaussians_as<float>(gaussians, changed);
}

void PlanBuffers::upload_edit(const std::vector<int>& changed, const std::vector<int>& rows) {
  upload(kBindingChanged, changed);
  upload(kBindingRows, rows);
}

void PlanBuffers::upload_corner_list(const std::vector<int>& items) { upload(kBindingCornerList, items); }

void PlanBuffers::clear_corner_pass(const PatchPlans& plans) {
  glClearNamedBufferSubData(buffers_[kBindingCornerLimits], GL_R32UI, 0,
                            GLsizeiptr(corner_limit_floats(plans) * sizeof(float)), GL_RED_INTEGER, GL_UNSIGNED_INT,
                            nullptr);
  glClearNamedBufferSubData(buffers_[kBindingCurveMidpoints], GL_R32UI, 0,
                            GLsizeiptr(curve_midpoint_floats(plans) * sizeof(float)), GL_RED_INTEGER, GL_UNSIGNED_INT,
                            nullptr);
  check_gl_errors("clearing the corner pass's output");
}

void PlanBuffers::bind() const {
  for (int b = 0; b < kBindingCount; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), buffers_[b]);
}

std::vector<uint32_t> PlanBuffers::read_words(int binding) const {
  std::vector<uint32_t> words(sizes_[binding] / sizeof(uint32_t));
  glGetNamedBufferSubData(buffers_[binding], 0, GLsizeiptr(words.size() * sizeof(uint32_t)), words.data());
  check_gl_errors("reading a table's buffer");
  return words;
}

std::vector<float> PlanBuffers::read_points(int n_points) const {
  std::vector<float> points(size_t(n_points) * kVec4PerPoint * 4);
  if (precision_ == PointPrecision::double_float) {
    std::vector<double> stored(points.size());
    glGetNamedBufferSubData(buffers_[kBindingPoints], 0, GLsizeiptr(stored.size() * sizeof(double)), stored.data());
    std::copy(stored.begin(), stored.end(), points.begin());
  } else {
    glGetNamedBufferSubData(buffers_[kBindingPoints], 0, GLsizeiptr(points.size() * sizeof(float)), points.data());
  }
  check_gl_errors("reading the plan points");
  return points;
}

void PlanBuffers::read_corner_limits(const std::function<void(const float*)>& read) const {
  // Mapped, not copied: a mesh of a million faces has 128 MB of them.
  const auto* limits = static_cast<const float*>(glMapNamedBuffer(buffers_[kBindingCornerLimits], GL_READ_ONLY));
  check_gl_errors("mapping the corner limits");
  if (!limits) throw Error("the driver did not map the corner limits");
  read(limits);
  glUnmapNamedBuffer(buffers_[kBindingCornerLimits]);
}

std::vector<float> PlanBuffers::read_corner_pass() const {
  const size_t limits = sizes_[kBindingCornerLimits] / sizeof(float),
               midpoints = sizes_[kBindingCurveMidpoints] / sizeof(float);
  std::vector<float> out(limits + midpoints);
  glGetNamedBufferSubData(buffers_[kBindingCornerLimits], 0, GLsizeiptr(limits * sizeof(float)), out.data());
  glGetNamedBufferSubData(buffers_[kBindingCurveMidpoints], 0, GLsizeiptr(midpoints * sizeof(float)),
                          out.data() + limits);
  check_gl_errors("reading the corner pass's output");
  return out;
}

size_t PlanBuffers::bytes() const {
  size_t total = 0;
  for (const size_t s : capacities_) total += s;
  for (const size_t s : spare_capacities_) total += s;
  return total;
}

}  // namespace gps
