#include "render/pipeline/patch_draw.h"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>

#include "core/support/error.h"
#include "render/gl/gl_context.h"
#include "shaders/embedded_shaders.h"

namespace gps {

namespace {

ShaderProgram patch_program(PatchShape shape, PatchOutput output, PointPrecision precision) {
  const bool triangles = shape == PatchShape::triangle, feedback = output == PatchOutput::feedback;
  std::vector<const char*> control = {shaders::gpu_layout, shaders::patch_basis, shaders::plan_eval};
  if (triangles) control.insert(control.begin(), "#define GPS_TRIANGLE_PATCHES\n");
  control.insert(control.end(), {shaders::canonical_edge, shaders::tess_levels});
  std::vector<const char*> evaluation = {shaders::gpu_layout, shaders::patch_basis, shaders::plan_eval};
  if (output == PatchOutput::wireframe) evaluation.insert(evaluation.begin(), shaders::geometry_next);
  control.push_back(triangles ? shaders::triangle_tesc : shaders::patch_tesc);
  if (triangles) evaluation.push_back(shaders::loop_eval);
  evaluation.push_back(shaders::canonical_edge);
  evaluation.push_back(triangles ? shaders::triangle_tese : shaders::patch_tese);
  std::vector<ShaderStage> stages = at_precision({{GL_VERTEX_SHADER, {shaders::patch_vert}},
                                                  {GL_TESS_CONTROL_SHADER, control},
                                                  {GL_TESS_EVALUATION_SHADER, evaluation}},
                                                 precision);
  const std::string name = triangles ? "triangle_patch" : "patch";
  if (feedback)
    return ShaderProgram(name + "_feedback", stages, {"v_patch_uv", "v_position", "v_normal", "v_evaluated"});
  // cache_vert.glsl's inputs, then what the surface cache evaluates again after an edit
  // (render/cache/stored_vertex_evaluation.h).
  const std::vector<const char*> stored = {"v_position", "v_stored_normal", "v_grid", "v_evaluated"};
  if (output == PatchOutput::capture) return ShaderProgram(name + "_capture", stages, stored);
  if (output == PatchOutput::wireframe) stages.push_back({GL_GEOMETRY_SHADER, {shaders::mesh_geom}});
  stages.push_back({GL_FRAGMENT_SHADER, {shaders::shade_frag}});
  if (output == PatchOutput::shaded_capture) return ShaderProgram(name + "_shaded_capture", stages, stored);
  return ShaderProgram(name + (output == PatchOutput::wireframe ? "_wire" : ""), stages);
}

// Rasterisation discarded, into a framebuffer without attachments, while it lives: a draw needs a
// complete framebuffer even so (NVIDIA's driver checks it, and a surfaceless EGL context has no
// default one), one of 1×1 (GL 4.3).
class DiscardedRaster {
public:
  DiscardedRaster() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_);
    glNamedFramebufferParameteri(framebuffer_, GL_FRAMEBUFFER_DEFAULT_WIDTH, 1);
    glNamedFramebufferParameteri(framebuffer_, GL_FRAMEBUFFER_DEFAULT_HEIGHT, 1);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
    glEnable(GL_RASTERIZER_DISCARD);
  }
  ~DiscardedRaster() {
    glDisable(GL_RASTERIZER_DISCARD);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(previous_));
  }
  DiscardedRaster(const DiscardedRaster&) = delete;
  DiscardedRaster& operator=(const DiscardedRaster&) = delete;

private:
  GLint previous_ = 0;
  GlFramebuffer framebuffer_;
};

ShapePrograms::Build patch_programs(PatchOutput output) {
  return [output](PatchShape shape, PointPrecision precision) {
    if (shape == PatchShape::quad && output == PatchOutput::wireframe)
      throw Error("quad patches have no wireframe program");
    return patch_program(shape, output, precision);
  };
}

}  // namespace

PatchDraw::PatchDraw()
    : programs_{
          ShapePrograms(patch_programs(PatchOutput::shaded)), ShapePrograms(patch_programs(PatchOutput::feedback)),
          ShapePrograms(patch_programs(PatchOutput::wireframe)), ShapePrograms(patch_programs(PatchOutput::capture)),
          ShapePrograms(patch_programs(PatchOutput::shaded_capture))} {}

void PatchDraw::set_precision(PointPrecision precision) {
  // The shaded program checks the precision for all of them.
  for (ShapePrograms& programs : programs_) programs.set_precision(precision, &programs == &programs_[0]);
  level_bound_.set_precision(precision);
}

const ShaderProgram& PatchDraw::program(PatchShape shape, PatchOutput output) const {
  return programs_[size_t(output)](shape);
}

void PatchDraw::draw(PatchShape shape, const ShaderProgram& program, const DrawOptions& o, int n_total, int first_patch,
                     int n_patches) const {
  if (statistics_) statistics_->begin();
  draw_batches(shape, program, o, n_total, first_patch, n_patches);
  if (statistics_) statistics_->end();
}

void PatchDraw::draw_batches(PatchShape shape, const ShaderProgram& program, const DrawOptions& o, int n_total,
                             int first_patch, int n_patches) const {
  const int end = n_patches < 0 ? n_total : std::min(n_total, first_patch + n_patches);
  // Mesa 22.3's llvmpipe drops whole patches from draws of more than 4096 patches or that generate
  // some 10^5 vertices, so draw in batches of at most 4096 patches and ~2^15 generated vertices at
  // the largest level these patches get. Adaptive levels: measured on the GPU first, with the draw's
  // own uniforms, where the patches are more than one batch; a smaller draw (a surface cache block)
  // takes the worst case, 64, rather than wait for the measure.
  const int level = o.pixels <= 0.0f           ? std::clamp(int(std::ceil(o.level)), 1, 64)
                    : end - first_patch > 4096 ? level_bound_.max_level(shape, program, first_patch, end - first_patch)
                                               : 64;
  const int batch = std::clamp(32768 / ((level + 1) * (level + 1)), 1, 4096);
  glBindVertexArray(empty_vao_);
  glPatchParameteri(GL_PATCH_VERTICES, 1);
  // The runs of patches not hidden, each in batches.
  const std::vector<int> none;
  const std::vector<int>& hidden = o.hidden_patches ? *o.hidden_patches : none;
  auto next_hidden = std::lower_bound(hidden.begin(), hidden.end(), first_patch);
  for (int run = first_patch; run < end;) {
    const int run_end = next_hidden == hidden.end() ? end : std::min(end, *next_hidden);
    for (int first = run; first < run_end; first += batch) {
      program.set("u_first_patch", first);
      glDrawArrays(GL_PATCHES, 0, std::min(batch, run_end - first));
    }
    if (next_hidden == hidden.end()) break;
    run = *next_hidden + 1;
    ++next_hidden;
  }
}

long long PatchDraw::count_triangles(PatchShape shape, const Camera& camera, const DrawOptions& o, int width,
                                     int height, int n_total, int first_patch, int n_patches) const {
  const ShaderProgram& feedback = program(shape, PatchOutput::feedback);
  set_frame_uniforms(feedback, camera, o, float(width) / float(height), width, height, frame_);
  feedback.use();
  const GlQuery query(GL_PRIMITIVES_GENERATED);
  {
    const DiscardedRaster discarded;
    glBeginQuery(GL_PRIMITIVES_GENERATED, query);
    draw_batches(shape, feedback, o, n_total, first_patch, n_patches);
    glEndQuery(GL_PRIMITIVES_GENERATED);
  }
  GLuint64 primitives = 0;
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &primitives);
  check_gl_errors("counting tessellated triangles");
  return (long long)primitives;
}

std::vector<TessellatedVertex> PatchDraw::capture_vertices(PatchShape shape, const Camera& camera, const DrawOptions& o,
                                                           int width, int height, int n_total, int first_patch,
                                                           int n_patches) const {
  std::vector<TessellatedVertex> out =
      capture_frame_vertices(shape, camera, o, width, height, n_total, first_patch, n_patches);
  for (TessellatedVertex& t : out) {
    const glm::dvec3 world = frame_.to_world(glm::dvec3(t.position[0], t.position[1], t.position[2]));
    const glm::dvec3 normal = frame_.direction_to_world(glm::dvec3(t.normal[0], t.normal[1], t.normal[2]));
    for (int k = 0; k < 3; ++k) t.position[k] = float(world[k]), t.normal[k] = float(normal[k]);
  }
  return out;
}

std::vector<TessellatedVertex> PatchDraw::capture_frame_vertices(PatchShape shape, const Camera& camera,
                                                                 const DrawOptions& o, int width, int height,
                                                                 int n_total, int first_patch, int n_patches) const {
  first_patch = std::clamp(first_patch, 0, n_total);
  n_patches = n_patches < 0 ? n_total - first_patch : std::min(n_patches, n_total - first_patch);
  // Counted first, then captured into a buffer of that size (a bound from the largest level alone
  // is 24,576 vertices a quad: gigabytes for a mesh of a few thousand faces).
  const long long triangles = count_triangles(shape, camera, o, width, height, n_total, first_patch, n_patches);
  std::vector<TessellatedVertex> out(size_t(triangles) * 3);
  const GlBuffer buffer;
  glNamedBufferData(buffer, GLsizeiptr(std::max<size_t>(1, out.size()) * sizeof(TessellatedVertex)), nullptr,
                    GL_STREAM_READ);
  {
    const DiscardedRaster discarded;
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    glBeginTransformFeedback(GL_TRIANGLES);
    // The feedback program as count_triangles() left it: bound, with this frame's uniforms.
    draw_batches(shape, program(shape, PatchOutput::feedback), o, n_total, first_patch, n_patches);
    glEndTransformFeedback();
  }
  glGetNamedBufferSubData(buffer, 0, GLsizeiptr(out.size() * sizeof(TessellatedVertex)), out.data());
  check_gl_errors("capturing tessellated vertices");
  return out;
}

void PatchDraw::set_collect_statistics(bool collect) {
  if (!collect) {
    statistics_.reset();
  } else if (!statistics_) {
    std::vector<unsigned> targets = {GL_PRIMITIVES_GENERATED};
    if (GLAD_GL_ARB_pipeline_statistics_query) targets.push_back(GL_TESS_EVALUATION_SHADER_INVOCATIONS_ARB);
    statistics_ = std::make_unique<QueryRing>(targets, 4);
  }
}

void PatchDraw::latest_statistics(DrawStatistics& s) const {
  if (statistics_)
    if (const auto& counts = statistics_->latest()) {
      s.triangles = (long long)(*counts)[0];
      s.vertices = counts->size() > 1 ? (long long)(*counts)[1] : 0;
    }
  if (!GLAD_GL_ARB_pipeline_statistics_query) s.vertices = -1;
}

}  // namespace gps
