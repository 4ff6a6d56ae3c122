// core/patch_basis.h is one source for C++ and GLSL: compiled both ways, it must give the same
// results on the same inputs (a compute shader against the C++ functions).
#include <gtest/gtest.h>

#include <glad/gl.h>

#include <vector>

#include "core/patch_basis.h"
#include "render/gl_context.h"
#include "render/shader_program.h"
#include "shaders/embedded_shaders.h"

namespace gps {
namespace {

// Per input (u, v): 36 Loop weights and derivatives, 16 cubic values, the child, sign, the turned
// (s, t) of corner 1 and 2, and the extraordinary block and scale: 64 floats.
constexpr int kOut = 64;
constexpr const char* kProbe = R"glsl(
layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer In { vec2 inputs[]; };
layout(std430, binding = 1) writeonly buffer Out { float outputs[]; };
void main() {
  int i = int(gl_GlobalInvocationID.x), o = 64 * i;
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
  outputs[o + 60] = float(loop_ev_locate(s, t, scale));
  outputs[o + 61] = s; outputs[o + 62] = t; outputs[o + 63] = scale;
}
)glsl";

std::vector<double> cpu_probe(double u, double v) {
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
  out[60] = loop_ev_locate(s, t, scale);
  out[61] = s, out[62] = t, out[63] = scale;
  return out;
}

TEST(SharedPatchBasis, GlslAndCppAgreeOnTheSameInputs) {
  const auto context = create_offscreen_context();
  const ShaderProgram probe("basis_probe", {{GL_COMPUTE_SHADER, {shaders::patch_basis, kProbe}}});
  std::vector<float> inputs;
  for (const auto& [u, v] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.5, 0.5}, {0.25, 0.125}, {0.6, 0.1},
                             {0.1, 0.7}, {0.3, 0.3}, {0.2, 0.2}, {0.75, 0.25}, {0.01, 0.02}, {1.0 / 3, 1.0 / 3}})
    inputs.insert(inputs.end(), {float(u), float(v)});
  const int n = int(inputs.size() / 2);
  unsigned buffers[2];
  glCreateBuffers(2, buffers);
  glNamedBufferData(buffers[0], GLsizeiptr(inputs.size() * sizeof(float)), inputs.data(), GL_STATIC_DRAW);
  glNamedBufferData(buffers[1], GLsizeiptr(size_t(n) * kOut * sizeof(float)), nullptr, GL_STREAM_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
  probe.use();
  glDispatchCompute(GLuint(n), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> gpu(size_t(n) * kOut);
  glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(gpu.size() * sizeof(float)), gpu.data());
  glDeleteBuffers(2, buffers);
  check_gl_errors("the basis probe");
  for (int i = 0; i < n; ++i) {
    const std::vector<double> cpu = cpu_probe(double(inputs[size_t(2 * i)]), double(inputs[size_t(2 * i + 1)]));
    for (int k = 0; k < kOut; ++k)
      EXPECT_NEAR(gpu[size_t(i * kOut + k)], cpu[size_t(k)], 2e-5 * (1 + std::abs(cpu[size_t(k)])))
          << "output " << k << " at (" << inputs[size_t(2 * i)] << ", " << inputs[size_t(2 * i + 1)] << ")";
  }
}

}  // namespace
}  // namespace gps
