#include "render/surface_renderer.h"

#include <glad/gl.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/stencil_table.h"
#include "render/compute_limits.h"
#include "render/gl_context.h"
#include "render/gpu_layout.h"
#include "render/matcap.h"
#include "shaders/embedded_shaders.h"

namespace gps {

namespace {

using namespace gpu;
constexpr int kGaussians = kBindingGaussians, kPoints = kBindingPoints, kOffsets = kBindingOffsets, kIndices = kBindingIndices,
              kWeights = kBindingWeights, kNodes = kBindingNodes, kRoots = kBindingRoots, kCorners = kBindingCorners,
              kChanged = kBindingChanged, kRows = kBindingRows, kEvTables = kBindingEvTables, kEdges = kBindingPatchEdges,
              kNeighbours = kBindingPatchNeighbours, kOwners = kBindingCornerOwners, kBindings = kBindingCount;

// The patch program of a shape: quads (Catmull-Clark plans) or triangles (Loop plans). Triangle
// patches draw their wireframe through mesh_geom.glsl (the tessellator's triangles do not follow
// lines of constant barycentrics).
// `capture`: what the fragment shader reads, for the surface cache (cache_vert.glsl redraws it).
enum class PatchOutput { shaded, feedback, wireframe, capture };
ShaderProgram patch_program(PatchShape shape, PatchOutput output) {
  const bool triangles = shape == PatchShape::triangle, feedback = output == PatchOutput::feedback;
  std::vector<const char*> control = {shaders::gpu_layout, shaders::patch_basis, shaders::plan_eval, shaders::tess_levels};
  std::vector<const char*> evaluation = {shaders::gpu_layout, shaders::patch_basis, shaders::plan_eval};
  if (output == PatchOutput::wireframe) evaluation.insert(evaluation.begin(), shaders::geometry_next);
  control.push_back(triangles ? shaders::triangle_tesc : shaders::patch_tesc);
  if (triangles) evaluation.push_back(shaders::loop_eval);
  evaluation.push_back(shaders::canonical_edge);
  evaluation.push_back(triangles ? shaders::triangle_tese : shaders::patch_tese);
  std::vector<ShaderStage> stages = {{GL_VERTEX_SHADER, {shaders::patch_vert}},
                                     {GL_TESS_CONTROL_SHADER, control},
                                     {GL_TESS_EVALUATION_SHADER, evaluation}};
  const std::string name = triangles ? "triangle_patch" : "patch";
  if (feedback) return ShaderProgram(name + "_feedback", stages, {"v_patch_uv", "v_position", "v_normal", "v_evaluated"});
  if (output == PatchOutput::capture) return ShaderProgram(name + "_capture", stages, {"v_position", "v_normal", "v_grid", "v_kind"});
  if (output == PatchOutput::wireframe) stages.push_back({GL_GEOMETRY_SHADER, {shaders::mesh_geom}});
  stages.push_back({GL_FRAGMENT_SHADER, {shaders::shade_frag}});
  return ShaderProgram(name + (output == PatchOutput::wireframe ? "_wire" : ""), stages);
}

}  // namespace

SurfaceRenderer::SurfaceRenderer()
    : dual_map_("dual_map", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::dual_map_comp}}}),
      stencil_("stencil", {{GL_COMPUTE_SHADER, {shaders::gpu_layout, shaders::stencil_comp}}}),
      patches_(patch_program(PatchShape::quad, PatchOutput::shaded)),
      feedback_(patch_program(PatchShape::quad, PatchOutput::feedback)),
      triangle_patches_(patch_program(PatchShape::triangle, PatchOutput::shaded)),
      triangle_feedback_(patch_program(PatchShape::triangle, PatchOutput::feedback)),
      triangle_wire_(patch_program(PatchShape::triangle, PatchOutput::wireframe)),
      triangles_("mesh", {{GL_VERTEX_SHADER, {shaders::mesh_vert}}, {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}),
      triangles_wire_("mesh_wire", {{GL_VERTEX_SHADER, {shaders::geometry_next, shaders::mesh_vert}},
                                    {GL_GEOMETRY_SHADER, {shaders::mesh_geom}},
                                    {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}),
      lines_("lines", {{GL_VERTEX_SHADER, {shaders::lines_vert}}, {GL_FRAGMENT_SHADER, {shaders::lines_frag}}}),
      capture_(patch_program(PatchShape::quad, PatchOutput::capture)),
      triangle_capture_(patch_program(PatchShape::triangle, PatchOutput::capture)),
      cached_("cached", {{GL_VERTEX_SHADER, {shaders::geometry_next, shaders::cache_vert}},
                         {GL_GEOMETRY_SHADER, {shaders::cache_geom}},
                         {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}),
      cached_wire_("cached_wire", {{GL_VERTEX_SHADER, {shaders::geometry_next, shaders::cache_vert}},
                                   {GL_GEOMETRY_SHADER, {shaders::mesh_geom}},
                                   {GL_FRAGMENT_SHADER, {shaders::shade_frag}}}) {
  glCreateBuffers(kBindings, buffers_);
  glCreateVertexArrays(1, &empty_vao_);
  glCreateVertexArrays(1, &triangle_vao_);
  glCreateVertexArrays(1, &lines_vao_);
  glCreateBuffers(1, &triangle_vbo_);
  glCreateBuffers(1, &triangle_ibo_);
  glCreateBuffers(1, &lines_vbo_);
  glCreateBuffers(1, &lines_ibo_);
  glVertexArrayVertexBuffer(lines_vao_, 0, lines_vbo_, 0, 3 * sizeof(float));
  glVertexArrayElementBuffer(lines_vao_, lines_ibo_);
  glEnableVertexArrayAttrib(lines_vao_, 0);
  glVertexArrayAttribFormat(lines_vao_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(lines_vao_, 0, 0);
  set_matcap(make_builtin_matcap("clay"));
  check_gl_errors("creating the renderer");
}

SurfaceRenderer::~SurfaceRenderer() {
  glDeleteBuffers(kBindings, buffers_);
  glDeleteVertexArrays(1, &empty_vao_);
  glDeleteVertexArrays(1, &triangle_vao_);
  glDeleteVertexArrays(1, &lines_vao_);
  glDeleteBuffers(1, &triangle_vbo_);
  glDeleteBuffers(1, &triangle_ibo_);
  glDeleteBuffers(1, &lines_vbo_);
  glDeleteBuffers(1, &lines_ibo_);
  if (matcap_) glDeleteTextures(1, &matcap_);
}

template <class T>
static void upload(unsigned buffer, size_t& size, const std::vector<T>& data) {
  // Empty buffers still need storage to be bound.
  size = std::max<size_t>(sizeof(T), data.size() * sizeof(T));
  glNamedBufferData(buffer, GLsizeiptr(size), data.empty() ? nullptr : data.data(), GL_DYNAMIC_DRAW);
}

void SurfaceRenderer::set_mesh(const CovarianceMesh& mesh, const PlanOptions& options) {
  PlanTables tables = build_surface_plans(topology_of(mesh.mesh), options);
  // Refused before anything changes: the renderer keeps drawing the previous mesh.
  const int n_vertices = int(mesh.n_vertices()), n_faces = int(mesh.n_faces());
  check_storage_fits("plan points", size_t(tables.stencils.n_points()) * kVec4PerPoint * 4 * sizeof(float), n_vertices, n_faces, storage_limit_);
  check_storage_fits("stencil weights", tables.stencils.weights.size() * sizeof(float), n_vertices, n_faces, storage_limit_);
  check_storage_fits("plan nodes", tables.plans.nodes.size() * sizeof(tables.plans.nodes[0]), n_vertices, n_faces, storage_limit_);
  tables_ = std::move(tables);
  n_base_ = n_vertices;
  const StencilTable& s = tables_.stencils;
  dependents_ = stencil_dependents(s);
  upload(buffers_[kOffsets], buffer_sizes_[kOffsets], s.offsets);
  upload(buffers_[kIndices], buffer_sizes_[kIndices], s.indices);
  upload(buffers_[kWeights], buffer_sizes_[kWeights], std::vector<float>(s.weights.begin(), s.weights.end()));
  upload(buffers_[kNodes], buffer_sizes_[kNodes], tables_.plans.nodes);
  upload(buffers_[kRoots], buffer_sizes_[kRoots], tables_.plans.patch_roots);
  upload(buffers_[kCorners], buffer_sizes_[kCorners], tables_.plans.patch_corner_points);
  upload(buffers_[kEvTables], buffer_sizes_[kEvTables], std::vector<float>(tables_.plans.ev_tables.begin(), tables_.plans.ev_tables.end()));
  upload(buffers_[kEdges], buffer_sizes_[kEdges], tables_.plans.patch_edges);
  upload(buffers_[kNeighbours], buffer_sizes_[kNeighbours], tables_.plans.patch_neighbours);
  upload(buffers_[kOwners], buffer_sizes_[kOwners], tables_.plans.corner_owners);
  upload(buffers_[kPoints], buffer_sizes_[kPoints], std::vector<float>(size_t(s.n_points()) * kVec4PerPoint * 4, 0.0f));
  upload_gaussians(mesh);
  // Base mesh lines: the vertex positions (updated by edits) and each edge as a pair of indices.
  std::vector<unsigned> edges;
  edges.reserve(2 * mesh.mesh.n_edges());
  for (const auto e : mesh.mesh.edges()) edges.insert(edges.end(), {unsigned(e.v0().idx()), unsigned(e.v1().idx())});
  line_index_count_ = int(edges.size());
  upload_line_positions(mesh);
  cache_.set_cage(mesh);
  glNamedBufferData(lines_ibo_, GLsizeiptr(std::max<size_t>(2, edges.size()) * sizeof(unsigned)), edges.data(), GL_STATIC_DRAW);
  run_compute(nullptr);
}

void SurfaceRenderer::upload_gaussians(const CovarianceMesh& mesh) {
  std::vector<float> g(mesh.n_vertices() * 9);
  for (size_t i = 0; i < mesh.n_vertices(); ++i) {
    const Vec3 m = mesh.mean(i);
    const Mat3& c = mesh.covariance(i);
    const double values[9] = {m.x(), m.y(), m.z(), c(0, 0), c(0, 1), c(0, 2), c(1, 1), c(1, 2), c(2, 2)};
    std::copy(values, values + 9, g.begin() + long(9 * i));
  }
  ellipsoids_.upload(mesh, nullptr);
  if (buffer_sizes_[kGaussians] == std::max<size_t>(sizeof(float), g.size() * sizeof(float)))
    glNamedBufferSubData(buffers_[kGaussians], 0, GLsizeiptr(g.size() * sizeof(float)), g.data());
  else
    upload(buffers_[kGaussians], buffer_sizes_[kGaussians], g);
}

void SurfaceRenderer::upload_line_positions(const CovarianceMesh& mesh) {
  std::vector<float> positions(3 * mesh.n_vertices());
  for (size_t i = 0; i < mesh.n_vertices(); ++i)
    for (int k = 0; k < 3; ++k) positions[3 * i + size_t(k)] = float(mesh.mean(i)[k]);
  glNamedBufferData(lines_vbo_, GLsizeiptr(std::max<size_t>(3, positions.size()) * sizeof(float)), positions.data(), GL_DYNAMIC_DRAW);
}

void SurfaceRenderer::update_vertices(const CovarianceMesh& mesh, const std::vector<int>& changed) {
  cache_.update_cage(mesh, changed);
  if (changed.size() * 8 > size_t(n_base_)) {  // most of the mesh (select all, drag): whole buffers, one call each
    upload_gaussians(mesh);
    upload_line_positions(mesh);
    run_compute(nullptr);
    return;
  }
  for (const int v : changed) {
    const Vec3 m = mesh.mean(size_t(v));
    const Mat3& c = mesh.covariance(size_t(v));
    const float values[9] = {float(m.x()), float(m.y()), float(m.z()), float(c(0, 0)), float(c(0, 1)),
                             float(c(0, 2)), float(c(1, 1)), float(c(1, 2)), float(c(2, 2))};
    glNamedBufferSubData(buffers_[kGaussians], GLintptr(9 * sizeof(float) * size_t(v)), sizeof values, values);
    glNamedBufferSubData(lines_vbo_, GLintptr(3 * sizeof(float) * size_t(v)), 3 * sizeof(float), values);
  }
  ellipsoids_.upload(mesh, &changed);
  run_compute(&changed);
}

void SurfaceRenderer::run_compute(const std::vector<int>* changed) {
  const GpuPassScope pass(timer_, "9D + stencils");
  ++points_generation_;
  const int n_rows = tables_.stencils.n_rows();
  for (int b = 0; b < kBindings; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), buffers_[b]);
  int vertex_count = n_base_, row_count = n_rows;
  if (changed) {
    const std::vector<int> rows = rows_reading(dependents_, *changed);
    upload(buffers_[kChanged], buffer_sizes_[kChanged], *changed);
    upload(buffers_[kRows], buffer_sizes_[kRows], rows);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kChanged, buffers_[kChanged]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRows, buffers_[kRows]);
    vertex_count = int(changed->size());
    row_count = int(rows.size());
  }
  dual_map_.use();
  dual_map_.set("u_count", vertex_count);
  dual_map_.set("u_use_list", changed ? 1 : 0);
  dispatch_split(dual_map_, vertex_count, group_limit_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  stencil_.use();
  stencil_.set("u_count", row_count);
  stencil_.set("u_n_base", n_base_);
  stencil_.set("u_use_list", changed ? 1 : 0);
  dispatch_split(stencil_, row_count, group_limit_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl_errors("the compute passes");
}

void SurfaceRenderer::set_triangles(const TriangleMesh& t) {
  std::vector<float> vertices;
  vertices.reserve(t.positions.size() * 6);
  for (size_t i = 0; i < t.positions.size(); ++i)
    for (const Vec3* v : {&t.positions[i], &t.normals[i]})
      for (int k = 0; k < 3; ++k) vertices.push_back(float((*v)[k]));
  std::vector<unsigned> indices;
  for (const auto& tri : t.triangles) indices.insert(indices.end(), {unsigned(tri[0]), unsigned(tri[1]), unsigned(tri[2])});
  triangle_count_ = int(t.triangles.size());
  glNamedBufferData(triangle_vbo_, GLsizeiptr(std::max<size_t>(1, vertices.size()) * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
  glNamedBufferData(triangle_ibo_, GLsizeiptr(std::max<size_t>(1, indices.size()) * sizeof(unsigned)), indices.data(), GL_STATIC_DRAW);
  glVertexArrayVertexBuffer(triangle_vao_, 0, triangle_vbo_, 0, 6 * sizeof(float));
  glVertexArrayElementBuffer(triangle_vao_, triangle_ibo_);
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(triangle_vao_, a);
    glVertexArrayAttribFormat(triangle_vao_, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
    glVertexArrayAttribBinding(triangle_vao_, a, 0);
  }
  check_gl_errors("uploading triangles");
}

void SurfaceRenderer::set_matcap(const Image& m) {
  if (matcap_) glDeleteTextures(1, &matcap_);
  glCreateTextures(GL_TEXTURE_2D, 1, &matcap_);
  glTextureStorage2D(matcap_, 1, GL_RGBA32F, m.width, m.height);
  // Image rows run top-down; texture rows bottom-up, so that v = 0.5·n.y + 0.5 points up.
  std::vector<float> rgba(size_t(m.width) * size_t(m.height) * 4, 1.0f);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      for (int c = 0; c < 3; ++c)
        rgba[(size_t(m.height - 1 - y) * size_t(m.width) + size_t(x)) * 4 + size_t(c)] = m.at(x, y, std::min(c, m.channels - 1));
  glTextureSubImage2D(matcap_, 0, 0, 0, m.width, m.height, GL_RGBA, GL_FLOAT, rgba.data());
  glTextureParameteri(matcap_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(matcap_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(matcap_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(matcap_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  check_gl_errors("uploading the MatCap");
}

void SurfaceRenderer::set_frame_uniforms(const ShaderProgram& p, const Camera& camera, const DrawOptions& o, float aspect,
                                         int width, int height) const {
  p.set("u_view_projection", camera.view_projection(aspect));
  p.set("u_view", camera.view());
  p.set("u_viewport", glm::vec2(float(width), float(height)));
  p.set("u_level", std::clamp(o.level, 1.0f, 64.0f));
  p.set("u_pixels", o.pixels);
  p.set("u_debug_mismatch", o.debug_mismatch ? 1 : 0);
  p.set("u_flag_back_faces", o.flag_back_faces ? 1 : 0);
  p.set("u_mode", int(o.mode));
  p.set("u_matcap", 0);
  p.set("u_wire_color", glm::vec4(0.1f, 0.1f, 0.15f, o.wireframe ? 0.85f : 0.0f));
}

void SurfaceRenderer::set_collect_statistics(bool collect) {
  if (!collect) {
    statistics_.reset();
  } else if (!statistics_) {
    std::vector<unsigned> targets = {GL_PRIMITIVES_GENERATED};
    if (GLAD_GL_ARB_pipeline_statistics_query) targets.push_back(GL_TESS_EVALUATION_SHADER_INVOCATIONS_ARB);
    statistics_ = std::make_unique<QueryRing>(targets, 4);
  }
}

DrawStatistics SurfaceRenderer::last_statistics() {
  last_statistics_.cached = last_frame_cached_;
  if (last_frame_cached_) {
    last_statistics_.triangles = cache_.triangles();
    last_statistics_.vertices = 0;
  } else if (statistics_)
    if (const auto& counts = statistics_->latest()) {
      last_statistics_.triangles = (long long)(*counts)[0];
      last_statistics_.vertices = counts->size() > 1 ? (long long)(*counts)[1] : 0;
    }
  if (!GLAD_GL_ARB_pipeline_statistics_query) last_statistics_.vertices = -1;
  last_statistics_.patches = tables_.plans.n_patches();
  return last_statistics_;
}

void SurfaceRenderer::draw(const RenderTarget& target, const Camera& camera, const DrawOptions& o) {
  const float aspect = float(target.width()) / float(target.height());
  {
    const GpuPassScope pass(timer_, "surface");
    target.bind();
    const float clear_color[4] = {o.background.r, o.background.g, o.background.b, 1.0f};
    const float clear_zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, clear_color);
    glClearBufferfv(GL_COLOR, 1, clear_zero);
    glClearBufferfv(GL_COLOR, 2, clear_zero);
    const float far_depth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glBindTextureUnit(0, matcap_);
    for (int b = 0; b < kBindings; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), buffers_[b]);
    const bool cached = !o.static_triangles && o.surface_cache && draw_from_cache(camera, o, aspect, target.width(), target.height());
    last_frame_cached_ = cached;
    // The geometry shader only where a triangle wireframe is wanted: the static floor of the benchmark stays plain.
    const bool triangle_wire = o.wireframe && tables_.plans.shape == PatchShape::triangle;
    const ShaderProgram& program = cached                ? (triangle_wire ? cached_wire_ : cached_)
                                   : !o.static_triangles ? patch_program_for(false, o.wireframe)
                                   : o.wireframe         ? triangles_wire_
                                                         : triangles_;
    set_frame_uniforms(program, camera, o, aspect, target.width(), target.height());
    program.use();
    if (o.static_triangles) {
      glBindVertexArray(triangle_vao_);
      glDrawElements(GL_TRIANGLES, 3 * triangle_count_, GL_UNSIGNED_INT, nullptr);
    } else if (cached) {
      cache_.draw();
    } else {
      if (statistics_) statistics_->begin();
      draw_patches(program, o);
      if (statistics_) statistics_->end();
    }
  }
  if (o.ellipsoids && ellipsoids_.count() > 0) {
    const GpuPassScope pass(timer_, "ellipsoids");
    ellipsoids_.draw(camera.view_projection(aspect), o.sigma_scale, o.ellipsoid_vertices);
  }
  if (o.mesh_lines && line_index_count_ > 0) {
    const GpuPassScope pass(timer_, "mesh lines");
    lines_.set("u_view_projection", camera.view_projection(aspect));
    lines_.use();
    const GLenum only_colour[3] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_NONE};
    glNamedFramebufferDrawBuffers(target.framebuffer(), 3, only_colour);
    glBindVertexArray(lines_vao_);
    glDepthMask(GL_FALSE);  // the cage with depth: its parts behind the surface faint, the others full
    glEnablei(GL_BLEND, 0);
    glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // the image's alpha kept
    for (const bool hidden : {true, false}) {
      glDepthFunc(hidden ? GL_GREATER : GL_LEQUAL);
      lines_.set("u_color", glm::vec4(0.45f, 0.45f, 0.45f, hidden ? kHiddenCageAlpha : 1.0f));
      glDrawElements(GL_LINES, line_index_count_, GL_UNSIGNED_INT, nullptr);
    }
    glDisablei(GL_BLEND, 0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LEQUAL);
    const GLenum all[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(target.framebuffer(), 3, all);
  }
  glBindVertexArray(0);
  check_gl_errors("drawing");
}

// Captures the patches' triangles when the cache does not hold them for these inputs (the storage
// buffers bound); true when stored triangles are there to draw.
bool SurfaceRenderer::draw_from_cache(const Camera& camera, const DrawOptions& o, float aspect, int width, int height) {
  SurfaceCache::Key key;
  key.points = points_generation_;
  key.pixels = std::max(o.pixels, 0.0f);
  key.level = key.pixels > 0.0f ? 0.0f : std::clamp(o.level, 1.0f, 64.0f);
  key.debug_mismatch = o.debug_mismatch;
  const glm::mat4 view_projection = camera.view_projection(aspect);
  const glm::vec2 viewport{float(width), float(height)};
  if (!cache_.current(key, view_projection, viewport)) {
    // Buffer size: uniform levels generate about 2·L² triangles per quad (L² per triangle), the
    // larger edge levels beside half-size patches a little more; adaptive ones as last time.
    const bool quads = tables_.plans.shape == PatchShape::quad;
    const long long level = (long long)std::ceil(key.level), patches = tables_.plans.n_patches();
    const long long estimate = key.pixels > 0.0f ? (cache_.triangles() > 0 ? cache_.triangles() * 5 / 4 : patches * 128)
                                                 : patches * (quads ? 2 : 1) * level * level * 5 / 4 + 64;
    const ShaderProgram& capture = quads ? capture_ : triangle_capture_;
    set_frame_uniforms(capture, camera, o, aspect, width, height);
    capture.use();
    cache_.capture(key, view_projection, viewport, estimate, [&] {
      if (statistics_) statistics_->begin();
      draw_patches(capture, o);
      if (statistics_) statistics_->end();
    });
  }
  return cache_.holds_triangles();
}

std::vector<TessellatedVertex> SurfaceRenderer::capture_vertices(const Camera& camera, const DrawOptions& o, float aspect,
                                                                 int first_patch, int n_patches) {
  first_patch = std::clamp(first_patch, 0, tables_.plans.n_patches());
  n_patches = n_patches < 0 ? tables_.plans.n_patches() - first_patch : std::min(n_patches, tables_.plans.n_patches() - first_patch);
  const size_t max_vertices = size_t(n_patches) * 64 * 64 * 6 + 64;
  unsigned buffer = 0, query = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferData(buffer, GLsizeiptr(max_vertices * sizeof(TessellatedVertex)), nullptr, GL_STREAM_READ);
  glCreateQueries(GL_PRIMITIVES_GENERATED, 1, &query);
  for (int b = 0; b < kBindings; ++b) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(b), buffers_[b]);
  const ShaderProgram& feedback = patch_program_for(true, false);
  set_frame_uniforms(feedback, camera, o, aspect, 512, 512);
  feedback.use();
  glEnable(GL_RASTERIZER_DISCARD);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
  glBeginQuery(GL_PRIMITIVES_GENERATED, query);
  glBeginTransformFeedback(GL_TRIANGLES);
  draw_patches(feedback, o, first_patch, n_patches);
  glEndTransformFeedback();
  glEndQuery(GL_PRIMITIVES_GENERATED);
  glDisable(GL_RASTERIZER_DISCARD);
  GLuint primitives = 0;
  glGetQueryObjectuiv(query, GL_QUERY_RESULT, &primitives);
  std::vector<TessellatedVertex> out(std::min<size_t>(max_vertices, size_t(primitives) * 3));
  glGetNamedBufferSubData(buffer, 0, GLsizeiptr(out.size() * sizeof(TessellatedVertex)), out.data());
  glDeleteBuffers(1, &buffer);
  glDeleteQueries(1, &query);
  check_gl_errors("capturing tessellated vertices");
  return out;
}

std::vector<float> SurfaceRenderer::read_points() const {
  std::vector<float> points(size_t(tables_.stencils.n_points()) * kVec4PerPoint * 4);
  glGetNamedBufferSubData(buffers_[kPoints], 0, GLsizeiptr(points.size() * sizeof(float)), points.data());
  check_gl_errors("reading the plan points");
  return points;
}

void SurfaceRenderer::draw_patches(const ShaderProgram& program, const DrawOptions& o, int first_patch, int n_patches) const {
  // Mesa 22.3's llvmpipe was seen to drop whole patches from draws that generate some 10^5
  // vertices (the crack test caught it), so draw in batches of at most ~2^15 generated vertices at
  // the chosen level (adaptive levels: the worst case, 64).
  const int level = o.pixels > 0.0f ? 64 : std::clamp(int(std::ceil(o.level)), 1, 64);
  const int batch = std::max(1, 32768 / ((level + 1) * (level + 1)));
  glBindVertexArray(empty_vao_);
  glPatchParameteri(GL_PATCH_VERTICES, 1);
  const int end = n_patches < 0 ? tables_.plans.n_patches() : std::min(tables_.plans.n_patches(), first_patch + n_patches);
  for (int first = first_patch; first < end; first += batch) {
    program.set("u_first_patch", first);
    glDrawArrays(GL_PATCHES, 0, std::min(batch, end - first));
  }
}

const ShaderProgram& SurfaceRenderer::patch_program_for(bool feedback, bool wireframe) const {
  if (tables_.plans.shape == PatchShape::triangle) return feedback ? triangle_feedback_ : wireframe ? triangle_wire_ : triangle_patches_;
  return feedback ? feedback_ : patches_;
}

size_t SurfaceRenderer::buffer_bytes() const {
  size_t total = 0;
  for (const size_t s : buffer_sizes_) total += s;
  return total;
}

}  // namespace gps
