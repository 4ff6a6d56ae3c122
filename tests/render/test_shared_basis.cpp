// core/patches/patch_basis.h, core/plans/plan_descent.h and render/gl/gpu_layout.h are one source for C++ and GLSL:
// compiled both ways, they must give the same results and constants (compute shaders against the
// C++ functions and values), and the pipeline's shaders must take their bindings and work-group
// size from them.
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <vector>

#include "core/patches/patch_basis.h"
#include "core/plans/plan_descent.h"
#include "core/plans/planned_surface.h"
#include "render/gl/gl_context.h"
#include "render/gl/gl_object.h"
#include "render/gl/gpu_layout.h"
#include "render/gl/shader_program.h"
#include "shaders/embedded_shaders.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

// Per input (u, v): 36 Loop weights and derivatives, 16 cubic values, the child, sign, the turned
// (s, t) of corner 1 and 2, the extraordinary block and scale, then a quad leaf's 48 weights and
// derivatives (regular for even inputs, terminal for odd): 112 floats.
constexpr int kOut = 112;
constexpr const char* kProbe = R"glsl(
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer In { vec2 inputs[]; };
layout(std430, binding = 1) writeonly buffer Out { float outputs[]; };
void main() {
  int i = int(gl_GlobalInvocationID.x), o = 112 * i;
  float u = inputs[i].x, v = inputs[i].y;
  float w[12], wu[12], wv[12];
  loop_box_spline_basis(u, v, w, wu, wv);
  for (int k = 0; k < 12; ++k) { outputs[o + k] = w[k]; outputs[o + 12 + k] = wu[k]; outputs[o + 24 + k] = wv[k]; }
  float c[4], dc[4];
  bspline_basis(u, c, dc);
  for (int k = 0; k < 4; ++k) { outputs[o + 36 + k] = c[k]; outputs[o + 40 + k] = dc[k]; }
  bezier_basis(v, c, dc);
  for (int k = 0; k < 4; ++k) { outputs[o + 44 + k] = c[k]; outputs[o + 48 + k] = dc[k]; }
  float cu = u, cv = v, sign;
  outputs[o + 52] = float(triangle_child(cu, cv, sign));
  outputs[o + 53] = cu; outputs[o + 54] = cv; outputs[o + 55] = sign;
  float s, t, scale;
  triangle_turn_to_corner(1, u, v, s, t);
  outputs[o + 56] = s; outputs[o + 57] = t;
  triangle_turn_to_corner(2, u, v, s, t);
  outputs[o + 58] = s; outputs[o + 59] = t;
  s = 0.001 * u; t = 0.001 * v;
  int steps;
  outputs[o + 60] = float(loop_extraordinary_locate(s, t, scale, steps));
  outputs[o + 61] = s; outputs[o + 62] = t; outputs[o + 63] = scale;
  float q[16], qu[16], qv[16];
  quad_leaf_basis(i % 2 == 0 ? kNodeRegular : kNodeTerminal, i % 4 == 0 ? kBoundaryV0 | kBoundaryU1 : 0, u, v, q, qu, qv);
  for (int k = 0; k < 16; ++k) { outputs[o + 64 + k] = q[k]; outputs[o + 80 + k] = qu[k]; outputs[o + 96 + k] = qv[k]; }
}
)glsl";

std::vector<double> cpu_probe(int i, double u, double v) {
  std::vector<double> out(kOut);
  double w[12], wu[12], wv[12];
  loop_box_spline_basis(u, v, w, wu, wv);
  for (int k = 0; k < 12; ++k) out[size_t(k)] = w[k], out[size_t(12 + k)] = wu[k], out[size_t(24 + k)] = wv[k];
  double c[4], dc[4];
  bspline_basis(u, c, dc);
  for (int k = 0; k < 4; ++k) out[size_t(36 + k)] = c[k], out[size_t(40 + k)] = dc[k];
  bezier_basis(v, c, dc);
  for (int k = 0; k < 4; ++k) out[size_t(44 + k)] = c[k], out[size_t(48 + k)] = dc[k];
  double cu = u, cv = v, sign;
  out[52] = triangle_child(cu, cv, sign);
  out[53] = cu, out[54] = cv, out[55] = sign;
  double s, t, scale;
  triangle_turn_to_corner(1, u, v, s, t);
  out[56] = s, out[57] = t;
  triangle_turn_to_corner(2, u, v, s, t);
  out[58] = s, out[59] = t;
  s = 0.001 * u, t = 0.001 * v;
  int steps;
  out[60] = loop_extraordinary_locate(s, t, scale, steps);
  out[61] = s, out[62] = t, out[63] = scale;
  double q[16], qu[16], qv[16];
  quad_leaf_basis(i % 2 == 0 ? kNodeRegular : kNodeTerminal, i % 4 == 0 ? kBoundaryV0 | kBoundaryU1 : 0, u, v, q, qu,
                  qv);
  for (int k = 0; k < 16; ++k) out[size_t(64 + k)] = q[k], out[size_t(80 + k)] = qu[k], out[size_t(96 + k)] = qv[k];
  return out;
}

using SharedPatchBasis = test::GlTest;

TEST_F(SharedPatchBasis, GlslAndCppAgreeOnTheSameInputs) {
  const ShaderProgram probe("basis_probe", {{GL_COMPUTE_SHADER, {shaders::patch_basis, kProbe}}});
  std::vector<float> inputs;
  for (const auto& [u, v] : {std::pair{0.0, 0.0},
                             {1.0, 0.0},
                             {0.0, 1.0},
                             {0.5, 0.5},
                             {0.25, 0.125},
                             {0.6, 0.1},
                             {0.1, 0.7},
                             {0.3, 0.3},
                             {0.2, 0.2},
                             {0.75, 0.25},
                             {0.01, 0.02},
                             {1.0 / 3, 1.0 / 3}})
    inputs.insert(inputs.end(), {float(u), float(v)});
  const int n = int(inputs.size() / 2);
  const GlBuffer buffers[2];
  glNamedBufferData(buffers[0], GLsizeiptr(inputs.size() * sizeof(float)), inputs.data(), GL_STATIC_DRAW);
  glNamedBufferData(buffers[1], GLsizeiptr(size_t(n) * kOut * sizeof(float)), nullptr, GL_STREAM_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
  probe.use();
  glDispatchCompute(GLuint(n), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> gpu(size_t(n) * kOut);
  glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(gpu.size() * sizeof(float)), gpu.data());
  check_gl_errors("the basis probe");
  for (int i = 0; i < n; ++i) {
    const std::vector<double> cpu = cpu_probe(i, double(inputs[size_t(2 * i)]), double(inputs[size_t(2 * i + 1)]));
    for (int k = 0; k < kOut; ++k)
      EXPECT_NEAR(gpu[size_t(i * kOut + k)], cpu[size_t(k)], 2e-5 * (1 + std::abs(cpu[size_t(k)])))
          << "output " << k << " at (" << inputs[size_t(2 * i)] << ", " << inputs[size_t(2 * i + 1)] << ")";
  }
}

// The descent of core/plans/plan_descent.h through real plans, and an extraordinary leaf's rows: per
// input (root, triangle, u, v): leaf node, kind, depth, leaf (u, v), scale, then the leaf's rows
// count, first row, d[4], scale, steps (0: the GPU takes no steps) and 16 weights each of w, ws, wt: 64 floats.
constexpr int kDescentOut = 64;
constexpr const char* kDescentBuffers = R"glsl(
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer Nodes { int nodes[]; };
)glsl";
constexpr const char* kDescentProbe = R"glsl(
layout(std430, binding = 1) readonly buffer In { vec4 inputs[]; };
layout(std430, binding = 2) writeonly buffer Out { float outputs[]; };
void main() {
  int i = int(gl_GlobalInvocationID.x), o = 64 * i;
  for (int k = 0; k < 64; ++k) outputs[o + k] = 0.0;
  bool triangle = inputs[i].y != 0.0;
  float u = inputs[i].z, v = inputs[i].w, scale;
  int kind, depth;
  int node = descend_plan(int(inputs[i].x), triangle, u, v, scale, kind, depth);
  outputs[o] = float(node); outputs[o + 1] = float(kind); outputs[o + 2] = float(depth);
  outputs[o + 3] = u; outputs[o + 4] = v; outputs[o + 5] = scale;
  if (kind != kNodeExtraordinary) return;
  float w[16], ws[16], wt[16], d[4], extraordinary_scale;
  int first_row, steps;
  int n = extraordinary_rows(!triangle, nodes[node + 1], u, v, false, first_row, steps, w, ws, wt, d, extraordinary_scale);
  outputs[o + 6] = float(n); outputs[o + 7] = float(first_row); outputs[o + 13] = float(steps);
  for (int k = 0; k < 4; ++k) outputs[o + 8 + k] = d[k];
  outputs[o + 12] = extraordinary_scale;
  for (int k = 0; k < n; ++k) { outputs[o + 16 + k] = w[k]; outputs[o + 32 + k] = ws[k]; outputs[o + 48 + k] = wt[k]; }
}
)glsl";

std::vector<double> cpu_descent(const std::vector<int32_t>& nodes, int root, bool triangle, double u, double v) {
  std::vector<double> out(kDescentOut, 0.0);
  double scale;
  int kind, depth;
  const int node = descend_plan(nodes.data(), root, triangle, u, v, scale, kind, depth);
  out[0] = node, out[1] = kind, out[2] = depth, out[3] = u, out[4] = v, out[5] = scale;
  if (kind != kNodeExtraordinary) return out;
  double w[16], ws[16], wt[16], d[4], extraordinary_scale;
  int first_row, steps;
  const int n = extraordinary_rows(!triangle, nodes[size_t(node + 1)], u, v, false, first_row, steps, w, ws, wt, d,
                                   extraordinary_scale);
  out[6] = n, out[7] = first_row, out[13] = steps;
  for (int k = 0; k < 4; ++k) out[size_t(8 + k)] = d[k];
  out[12] = extraordinary_scale;
  for (int k = 0; k < n; ++k) out[size_t(16 + k)] = w[k], out[size_t(32 + k)] = ws[k], out[size_t(48 + k)] = wt[k];
  return out;
}

void expect_same_descent(const char* name, const CovarianceMesh& mesh, const PlanOptions& options) {
  const SurfaceTables tables = build_surface_plans(mesh.topology(), options);
  const PatchPlans& plans = tables.plans;
  const bool triangle = plans.shape == PatchShape::triangle;
  const ShaderProgram probe(
      "descent_probe",
      {{GL_COMPUTE_SHADER, {shaders::patch_basis, kDescentBuffers, shaders::plan_descent, kDescentProbe}}});
  // Every patch at points inside, along the edges and near each corner (down to the limit masks).
  std::vector<float> inputs;
  const std::vector<std::pair<double, double>> uvs = {
      {0.3, 0.2},   {0.71, 0.13}, {0.05, 0.6},    {0.33, 0.33},  {0.0, 0.0},    {1.0, 0.0},  {0.0, 1.0},
      {0.02, 0.01}, {1e-6, 3e-7}, {1e-13, 1e-13}, {0.99, 0.004}, {0.004, 0.98}, {0.6, 0.37}, {0.9, 0.9}};
  for (int patch = 0; patch < plans.n_patches(); ++patch)
    for (const auto& [u, v] : uvs) {
      if (triangle && u + v > 1.0) continue;
      inputs.insert(inputs.end(),
                    {float(plans.patch_roots[size_t(patch)]), triangle ? 1.0f : 0.0f, float(u), float(v)});
    }
  const int n = int(inputs.size() / 4);
  const GlBuffer buffers[3];
  glNamedBufferData(buffers[0], GLsizeiptr(plans.nodes.size() * sizeof(int32_t)), plans.nodes.data(), GL_STATIC_DRAW);
  glNamedBufferData(buffers[1], GLsizeiptr(inputs.size() * sizeof(float)), inputs.data(), GL_STATIC_DRAW);
  glNamedBufferData(buffers[2], GLsizeiptr(size_t(n) * kDescentOut * sizeof(float)), nullptr, GL_STREAM_READ);
  for (unsigned b = 0; b < 3; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, buffers[b]);
  probe.use();
  glDispatchCompute(GLuint(n), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> gpu(size_t(n) * kDescentOut);
  glGetNamedBufferSubData(buffers[2], 0, GLsizeiptr(gpu.size() * sizeof(float)), gpu.data());
  check_gl_errors("the descent probe");
  int extraordinary = 0, deep = 0;
  for (int i = 0; i < n; ++i) {
    const float* in = &inputs[size_t(4 * i)];
    const std::vector<double> cpu = cpu_descent(plans.nodes, int(in[0]), triangle, double(in[2]), double(in[3]));
    extraordinary += cpu[1] == kNodeExtraordinary;
    deep += cpu[2] > 1;
    for (int k = 0; k < kDescentOut; ++k)
      EXPECT_NEAR(gpu[size_t(i * kDescentOut + k)], cpu[size_t(k)], 2e-5 * (1 + std::abs(cpu[size_t(k)])))
          << name << ": output " << k << " from root " << in[0] << " at (" << in[2] << ", " << in[3] << ")";
  }
  EXPECT_GT(extraordinary, 0) << name;  // the inputs reach extraordinary leaves,
  if (!triangle) {
    EXPECT_GT(deep, 0) << name;  // and quad plans more than one level down
  }
}

// Every constant of gpu_layout.h and the node kinds of patch_basis.h, read back from GLSL.
constexpr const char* kConstantsProbe = R"glsl(
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Out { int outputs[]; };
void main() {
  int values[34] = int[34](kBindingGaussians, kBindingPoints, kBindingOffsets, kBindingIndices, kBindingWeights,
                           kBindingNodes, kBindingRoots, kBindingCorners, kBindingChanged, kBindingRows, kBindingExtraordinaryTables,
                           kBindingPatchEdges, kBindingPatchNeighbours, kBindingCornerOwners, kBindingCornerLimits, kBindingCornerList, kBindingCurveMidpoints, kBindingCount,
                           kBindingStoredVertices, kBindingWeldTable, kBindingStoredIndices, kBindingBlockStarts,
                           kWorkGroupSize, kVec4PerPoint, kNodeInternal, kNodeRegular, kNodeTerminal, kNodeExtraordinary,
                           kPatchEdgeInts, kPatchEdgeStride, kEdgeWhole, kEdgeWholeBesideHalves, kEdgeFirstHalf, kEdgeSecondHalf);
  for (int k = 0; k < 34; ++k) outputs[k] = values[k];
}
)glsl";

using SharedLayout = test::GlTest;

TEST_F(SharedLayout, GlslAndCppAgreeOnEveryConstant) {
  using namespace gpu;
  const std::vector<int> cpu = {kBindingGaussians,
                                kBindingPoints,
                                kBindingOffsets,
                                kBindingIndices,
                                kBindingWeights,
                                kBindingNodes,
                                kBindingRoots,
                                kBindingCorners,
                                kBindingChanged,
                                kBindingRows,
                                kBindingExtraordinaryTables,
                                kBindingPatchEdges,
                                kBindingPatchNeighbours,
                                kBindingCornerOwners,
                                kBindingCornerLimits,
                                kBindingCornerList,
                                kBindingCurveMidpoints,
                                kBindingCount,
                                kBindingStoredVertices,
                                kBindingWeldTable,
                                kBindingStoredIndices,
                                kBindingBlockStarts,
                                kWorkGroupSize,
                                kVec4PerPoint,
                                kNodeInternal,
                                kNodeRegular,
                                kNodeTerminal,
                                kNodeExtraordinary,
                                kPatchEdgeInts,
                                kPatchEdgeStride,
                                kEdgeWhole,
                                kEdgeWholeBesideHalves,
                                kEdgeFirstHalf,
                                kEdgeSecondHalf};
  const ShaderProgram probe("constants_probe",
                            {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::patch_basis, kConstantsProbe}}});
  const GlBuffer buffer;
  glNamedBufferData(buffer, GLsizeiptr(cpu.size() * sizeof(int)), nullptr, GL_STREAM_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
  probe.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<int> gpu(cpu.size());
  glGetNamedBufferSubData(buffer, 0, GLsizeiptr(gpu.size() * sizeof(int)), gpu.data());
  check_gl_errors("the constants probe");
  EXPECT_EQ(gpu, cpu);
}

// The compute passes as the renderer builds them (render/pipeline/dual_stencil_pass.cpp): their work-group
// size and each storage block's binding, as the driver reports them, are gpu_layout.h's.
TEST_F(SharedLayout, ComputePassesUseTheSharedBindingsAndWorkGroupSize) {
  const auto expect_layout = [](const char* name, const char* source,
                                const std::vector<std::pair<const char*, int>>& blocks) {
    const ShaderProgram program(name, {{GL_COMPUTE_SHADER, {shaders::gpu_layout, source}}});
    GLint size[3] = {};
    glGetProgramiv(program.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
    EXPECT_EQ(size[0], gpu::kWorkGroupSize) << name;
    for (const auto& [block, binding] : blocks) {
      const GLuint index = glGetProgramResourceIndex(program.id(), GL_SHADER_STORAGE_BLOCK, block);
      ASSERT_NE(index, GL_INVALID_INDEX) << name << ": no block " << block;
      const GLenum property = GL_BUFFER_BINDING;
      GLint value = -1;
      glGetProgramResourceiv(program.id(), GL_SHADER_STORAGE_BLOCK, index, 1, &property, 1, nullptr, &value);
      EXPECT_EQ(value, binding) << name << ": block " << block;
    }
    check_gl_errors(name);
  };
  expect_layout(
      "dual_map", shaders::dual_map_comp,
      {{"Gaussians", gpu::kBindingGaussians}, {"Points", gpu::kBindingPoints}, {"Changed", gpu::kBindingChanged}});
  expect_layout("stencil", shaders::stencil_comp,
                {{"Points", gpu::kBindingPoints},
                 {"Offsets", gpu::kBindingOffsets},
                 {"Indices", gpu::kBindingIndices},
                 {"Weights", gpu::kBindingWeights},
                 {"Rows", gpu::kBindingRows}});
}

using SharedPlanDescent = test::GlTest;

TEST_F(SharedPlanDescent, GlslAndCppAgreeOnTheSameInputs) {
  expect_same_descent("cube", test::cube_mesh(), PlanOptions{Scheme::catmull_clark, 3});
  expect_same_descent("prism", test::prism_mesh(), PlanOptions{Scheme::catmull_clark, 2});
  expect_same_descent("icosahedron", test::icosahedron_mesh(), PlanOptions{Scheme::loop});
  expect_same_descent("cone", test::cone_mesh(), PlanOptions{Scheme::loop});
}

}  // namespace
}  // namespace gps
