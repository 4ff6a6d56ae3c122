#include "render/pipeline/plan_buffers.h"

#include <glad/gl.h>

#include <Eigen/LU>
#include <algorithm>

#include "render/gl/compute_limits.h"
#include "render/gl/gl_context.h"

namespace gps {

using namespace gpu;

PlanBuffers::PlanBuffers() = default;

template <class T>
void PlanBuffers::upload(int binding, const std::vector<T>& data) {
  // Empty buffers still need storage to be bound.
  sizes_[binding] = std::max<size_t>(sizeof(T), data.size() * sizeof(T));
  glNamedBufferData(buffers_[binding], GLsizeiptr(sizes_[binding]), data.empty() ? nullptr : data.data(),
                    GL_DYNAMIC_DRAW);
}

// Two vec4 per patch corner: limit point and node kind, normal (shaders/corner_limit_comp.glsl).
size_t PlanBuffers::corner_limit_floats(const PatchPlans& plans) {
  return size_t(plans.corners()) * size_t(plans.n_patches()) * 8;
}

void PlanBuffers::check_fits(const SurfaceTables& tables, int n_vertices, int n_faces, long long storage_limit) {
  check_storage_fits("plan points", size_t(tables.stencils.n_points()) * kVec4PerPoint * 4 * sizeof(float), n_vertices,
                     n_faces, storage_limit);
  check_storage_fits("stencil weights", tables.stencils.weights.size() * sizeof(float), n_vertices, n_faces,
                     storage_limit);
  check_storage_fits("plan nodes", tables.plans.nodes.size() * sizeof(tables.plans.nodes[0]), n_vertices, n_faces,
                     storage_limit);
  check_storage_fits("corner limits", corner_limit_floats(tables.plans) * sizeof(float), n_vertices, n_faces,
                     storage_limit);
}

void PlanBuffers::upload_tables(const SurfaceTables& tables) {
  const StencilTable& s = tables.stencils;
  const PatchPlans& p = tables.plans;
  upload(kBindingOffsets, s.offsets);
  upload(kBindingIndices, s.indices);
  upload(kBindingWeights, std::vector<float>(s.weights.begin(), s.weights.end()));
  upload(kBindingNodes, p.nodes);
  upload(kBindingRoots, p.patch_roots);
  upload(kBindingCorners, p.patch_corner_points);
  upload(kBindingExtraordinaryTables, std::vector<float>(p.extraordinary_tables.begin(), p.extraordinary_tables.end()));
  upload(kBindingPatchEdges, p.patch_edges);
  upload(kBindingPatchNeighbours, p.patch_neighbours);
  upload(kBindingCornerOwners, p.corner_owners);
  upload(kBindingPoints, std::vector<float>(size_t(s.n_points()) * kVec4PerPoint * 4, 0.0f));
  upload(kBindingCornerLimits, std::vector<float>(corner_limit_floats(p), 0.0f));
}

// μ, then Σ⁻¹'s xx xy xz yy yz zz (shaders/dual_map_comp.glsl). The inverse is taken in double and
// rounded once: inverted in float, a thin Gaussian's Σ (condition κ) loses κ times float's precision in
// Σ⁻¹, its thin directions' precision first, where the surface's shape is.
static void gaussian_of(const CovarianceMesh& mesh, size_t v, float* out) {
  const Vec3 m = mesh.mean(v);
  const Mat3 p = mesh.covariance(v).inverse();
  const double values[9] = {m.x(), m.y(), m.z(), p(0, 0), p(0, 1), p(0, 2), p(1, 1), p(1, 2), p(2, 2)};
  std::copy(values, values + 9, out);
}

void PlanBuffers::upload_gaussians(const CovarianceMesh& mesh) {
  std::vector<float> g(mesh.n_vertices() * 9);
  for (size_t i = 0; i < mesh.n_vertices(); ++i) gaussian_of(mesh, i, &g[9 * i]);
  if (sizes_[kBindingGaussians] == std::max<size_t>(sizeof(float), g.size() * sizeof(float)))
    glNamedBufferSubData(buffers_[kBindingGaussians], 0, GLsizeiptr(g.size() * sizeof(float)), g.data());
  else
    upload(kBindingGaussians, g);
}

void PlanBuffers::update_gaussians(const CovarianceMesh& mesh, const std::vector<int>& changed) {
  for (const int v : changed) {
    float values[9];
    gaussian_of(mesh, size_t(v), values);
    glNamedBufferSubData(buffers_[kBindingGaussians], GLintptr(9 * sizeof(float) * size_t(v)), sizeof values, values);
  }
}

void PlanBuffers::upload_edit(const std::vector<int>& changed, const std::vector<int>& rows) {
  upload(kBindingChanged, changed);
  upload(kBindingRows, rows);
}

void PlanBuffers::upload_corner_list(const std::vector<int>& slots) { upload(kBindingCornerList, slots); }

void PlanBuffers::bind() const {
  for (int b = 0; b < kBindingCount; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), buffers_[b]);
}

std::vector<float> PlanBuffers::read_points(int n_points) const {
  std::vector<float> points(size_t(n_points) * kVec4PerPoint * 4);
  glGetNamedBufferSubData(buffers_[kBindingPoints], 0, GLsizeiptr(points.size() * sizeof(float)), points.data());
  check_gl_errors("reading the plan points");
  return points;
}

size_t PlanBuffers::bytes() const {
  size_t total = 0;
  for (const size_t s : sizes_) total += s;
  return total;
}

}  // namespace gps
