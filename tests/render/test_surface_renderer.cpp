// The GPU pipeline on OSMesa against the CPU evaluator; its watertightness is test_watertight.cpp.
#include "render/pipeline/surface_renderer.h"

#include <gtest/gtest.h>

#include <glad/gl.h>

#include <array>
#include <cmath>
#include <map>
#include <tuple>

#include "core/support/error.h"
#include "core/evaluation/patch_eval.h"
#include "core/reference/reference_subdivision.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/plans/stencil_table.h"
#include "core/evaluation/tessellator.h"
#include "render/image/non_finite_pixels.h"
#include "render/pipeline/plan_buffers.h"
#include "render/pipeline/surface_point.h"
#include "render/comparison/reference_triangles.h"
#include "tests/support/device_limits.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"
#include "view/picking.h"

namespace gps {
namespace {

using GpuTest = test::GlTest;

// A plan point as the GPU keeps it, (q̂, y, anchor a) (shaders/plan_point.glsl), as a 9D point: q̄ = y + q̂ a.
Dual dual_of_gpu_point(const float* g) {
  Dual q;
  for (int k = 0; k < 9; ++k) q[k] = g[k];
  q.tail<3>() += unvech(q) * Vec3(g[9], g[10], g[11]);
  return q;
}

// The GPU's plan points (read_points) against the CPU's 9D points, 1e-4 relative.
void expect_points_match(const std::vector<float>& gpu, const std::vector<Dual>& cpu, const std::string& what) {
  ASSERT_EQ(gpu.size(), cpu.size() * 12) << what;
  for (size_t p = 0; p < cpu.size(); ++p) {
    const Dual q = dual_of_gpu_point(&gpu[12 * p]);
    for (int k = 0; k < 9; ++k)
      ASSERT_NEAR(q[k], cpu[p][k], 1e-4 * (1 + std::abs(cpu[p][k]))) << what << " point " << p << " k " << k;
  }
}

struct VertexErrors {
  double position = 0, normal_degrees = 0;
  size_t count = 0;
};

// Every vertex the GPU tessellator produced, against the CPU evaluator at the same (patch, u, v).
VertexErrors compare_vertices(const CovarianceMesh& mesh, const PlanOptions& options, float level) {
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh, options);
  DrawOptions o;
  o.level = level;
  const auto vertices = renderer.capture_vertices(Camera{}, o, 512, 512);
  const test::PlannedMesh cpu(mesh, options);
  const double diag = bounding_box_diagonal(mesh);
  VertexErrors e;
  for (const auto& v : vertices) {
    // On a crease the vertex's normal is its own patch's (TessellatedVertex::on_crease).
    const auto s = v.on_crease() ? evaluate_patch(cpu.tables.plans, cpu.points, int(v.patch), v.u, v.v)
                                 : evaluate_patch(cpu.tables.plans, cpu.points, int(v.evaluated[0]), v.evaluated[1],
                                                  v.evaluated[2]);
    if (!s) continue;
    const double err = (s->position - Vec3(v.position[0], v.position[1], v.position[2])).norm() / diag;
    e.position = std::max(e.position, err);
    const Vec3 gpu_normal(v.normal[0], v.normal[1], v.normal[2]);
    const double c = std::clamp(s->normal.dot(gpu_normal.normalized()), -1.0, 1.0);
    // A non-finite GPU vertex counts as the worst error (max() would skip a NaN).
    const bool finite = gpu_normal.allFinite() && Vec3(v.position[0], v.position[1], v.position[2]).allFinite();
    e.normal_degrees = std::max(e.normal_degrees, finite ? std::acos(c) * 180.0 / M_PI : 180.0);
    if (!finite) e.position = 1.0;
    ++e.count;
  }
  return e;
}

// The compute passes (dual map, stencils) against core's apply_stencils().
TEST_F(GpuTest, ComputePassesMatchTheCpuStencils) {
  for (const char* name : {"cube", "cone-pointy", "cylinder"}) {
    const CovarianceMesh mesh = make_sample(name);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh);
    // The GPU's points are those of the mesh in the renderer's frame.
    const test::PlannedMesh cpu(renderer.frame().to_frame(mesh), PlanOptions{});
    expect_points_match(renderer.read_points(), cpu.points, name);
  }
}

// Every sample's patches (exact extraordinary nodes included) under its own scheme and under
// Catmull-Clark, float on the GPU against double on the CPU (required: ≤ 2e-6 of the diagonal, 0.05°).
// The pawn's inferred covariances are thin at its poles (eigenvalues down to 9.3e-7, q̂ ~ 1e6): its
// normals keep within the bound because the GPU keeps points about nearby anchors
// (shaders/plan_point.glsl) and takes each leaf's sums about its heaviest point's anchor
// (shaders/plan_eval.glsl) instead of summing q̄ = q̂μ itself. cone-pointy as Catmull-Clark, whose
// boundary rows weigh its apex (q̂ = 1e5 I) by −0.375, keeps within it because boundary phantoms are
// folded into the basis (core/patches/patch_basis.h).
TEST_F(GpuTest, TessellatedVerticesMatchTheCpuEvaluator) {
  for (const std::string& name : sample_names()) {
    const CovarianceMesh mesh = make_sample(name, 300);
    const bool large = mesh.n_faces() > 200;
    for (const auto& scheme : {std::optional<Scheme>{}, std::optional<Scheme>{Scheme::catmull_clark}}) {
      if (scheme && scheme_for(mesh.topology(), {}) == Scheme::catmull_clark) continue;  // the same plans
      // Level 64 on valence10 with plans of depth 0 (extraordinary nodes as large as base faces):
      // the vertices closest to those corners (1/64 of a patch) are within the tables' levels
      // (core/patches/patch_basis.h, kExtraordinaryLevels), where the GPU is exact too.
      std::vector<float> levels = {1.0f, large ? 3.0f : 7.0f};
      if (name == "valence10") levels.push_back(64.0f);
      for (const float level : levels) {
        const VertexErrors e = compare_vertices(mesh, PlanOptions{scheme, level == 64.0f ? 0 : kExactPlanDepth}, level);
        std::printf(
            "%-13s %-6s level %2.0f: GPU against CPU: position %.1e of the diagonal, normal %.4f degrees, %zu "
            "vertices\n",
            name.c_str(), scheme ? "cc" : "auto", level, e.position, e.normal_degrees, e.count);
        EXPECT_GT(e.count, size_t(mesh.n_faces())) << name;
        // 2e-6 is required; 5e-7 holds since boundary phantoms are folded into the basis
        // (core/patches/patch_basis.h).
        EXPECT_LT(e.position, 5e-7) << name << " level " << level;
        EXPECT_LT(e.normal_degrees, 0.05) << name << " level " << level;
      }
    }
  }
}

// Creased meshes (semi-sharp and infinitely sharp edges and corners, random anisotropic covariances):
// the same plans on the GPU, with one-sided normals along the creases, within the bounds above.
TEST_F(GpuTest, CreasedPatchesMatchTheCpuEvaluator) {
  for (const char* name : {"creased_cube", "creased_cylinder", "creased_cone"}) {
    const CovarianceMesh mesh =
        test::with_random_covariances(read_mesh(std::string(GPS_TEST_DATA_DIR) + "/" + name + ".ply"), 11);
    ASSERT_FALSE(mesh.sharpness.empty()) << name;
    for (const float level : {1.0f, 7.0f, 64.0f}) {
      const VertexErrors e = compare_vertices(mesh, PlanOptions{}, level);
      std::printf(
          "%-16s level %2.0f: GPU against CPU: position %.1e of the diagonal, normal %.4f degrees, %zu vertices\n",
          name, level, e.position, e.normal_degrees, e.count);
      EXPECT_GT(e.count, size_t(mesh.n_faces())) << name;
      EXPECT_LT(e.position, 5e-7) << name << " level " << level;
      EXPECT_LT(e.normal_degrees, 0.05) << name << " level " << level;
    }
  }
}

// Loop patches (box splines and exact extraordinary nodes) on the GPU against the CPU evaluator.
TEST_F(GpuTest, LoopPatchesMatchTheCpuEvaluator) {
  std::vector<std::pair<std::string, CovarianceMesh>> meshes;
  for (const char* name : {"cone", "cone-pointy", "cone-concave", "cone-plateau", "cone-cylinder"})
    meshes.emplace_back(name, make_sample(name));
  meshes.emplace_back("icosahedron", test::with_random_covariances(test::icosahedron_mesh(), 4));
  meshes.emplace_back("triangle grid", test::with_random_covariances(test::triangle_grid_mesh(5, 4), 5));
  for (const auto& [name, mesh] : meshes)
    for (const float level :
         {1.0f, 7.0f, 64.0f}) {  // 64: the points closest to the corners (as in TessellatedVertices…)
      if (level == 64.0f && name != "icosahedron") continue;
      const VertexErrors e = compare_vertices(mesh, PlanOptions{Scheme::loop, 3}, level);
      std::printf(
          "%-14s level %2.0f: GPU against CPU: position %.1e of the diagonal, normal %.3f degrees, %zu vertices\n",
          name.c_str(), level, e.position, e.normal_degrees, e.count);
      EXPECT_GT(e.count, size_t(mesh.n_faces())) << name;
      // Float against double, the bounds of TessellatedVerticesMatchTheCpuEvaluator: the needle cones'
      // normals keep within them because each leaf's sums are taken about its heaviest point's anchor
      // (shaders/plan_eval.glsl).
      EXPECT_LT(e.position, 5e-7) << name << " level " << level;
      EXPECT_LT(e.normal_degrees, 0.05) << name << " level " << level;
    }
}

// Position and normal AOVs of the patches against the CPU evaluator's tessellation (same level)
// drawn as a static mesh through the same shading, over pixels covered by both and their neighbours.
TEST_F(GpuTest, AovsMatchTheCpuEvaluatorPixelForPixel) {
  for (const char* name : {"valence5", "wirecube", "cone"}) {
    const CovarianceMesh mesh = make_sample(name);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh);
    const test::PlannedMesh cpu(mesh, PlanOptions{});
    DrawOptions o;
    o.level = 64;  // the two triangulations differ by the chord error, ~1e-4 of the diagonal at 64 here
    const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
    RenderTarget target(200, 200);
    renderer.draw(target, camera, o);
    const Image gpu_position = target.read(1), gpu_normal = target.read(2);
    renderer.set_triangles(tessellate(cpu.tables.plans, cpu.points, 64));
    o.static_triangles = true;
    renderer.draw(target, camera, o);
    const Image cpu_position = target.read(1), cpu_normal = target.read(2);
    const double diag = bounding_box_diagonal(mesh);
    // Covered, and no silhouette or occlusion edge in the 3×3 neighbourhood (positions continuous).
    const auto inside = [&](const Image& im, int x, int y) {
      const Vec3 p(im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2));
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = std::clamp(x + dx, 0, im.width - 1), yy = std::clamp(y + dy, 0, im.height - 1);
          if (im.at(xx, yy, 3) < 0.5f) return false;
          if ((Vec3(im.at(xx, yy, 0), im.at(xx, yy, 1), im.at(xx, yy, 2)) - p).norm() >
              0.02 * bounding_box_diagonal(mesh))
            return false;
        }
      return true;
    };
    double position = 0, normal = 0;
    int covered = 0;
    for (int y = 0; y < 200; ++y)
      for (int x = 0; x < 200; ++x) {
        if (!inside(gpu_position, x, y) || !inside(cpu_position, x, y)) continue;
        const Vec3 a(gpu_position.at(x, y, 0), gpu_position.at(x, y, 1), gpu_position.at(x, y, 2));
        const Vec3 b(cpu_position.at(x, y, 0), cpu_position.at(x, y, 1), cpu_position.at(x, y, 2));
        // At grazing angles a sub-pixel difference in the triangulation moves the hit far along the ray.
        const glm::vec3 eye = camera.eye();
        const Vec3 ray = (a - Vec3(eye.x, eye.y, eye.z)).normalized();
        const Vec3 n(cpu_normal.at(x, y, 0), cpu_normal.at(x, y, 1), cpu_normal.at(x, y, 2));
        if (std::abs(ray.dot(n.normalized())) < 0.3) continue;
        position = std::max(position, (a - b).norm() / diag);
        if (gpu_normal.at(x, y, 3) != 2.0f) continue;  // normals: where the node is regular
        const Vec3 na(gpu_normal.at(x, y, 0), gpu_normal.at(x, y, 1), gpu_normal.at(x, y, 2));
        const Vec3 nb(cpu_normal.at(x, y, 0), cpu_normal.at(x, y, 1), cpu_normal.at(x, y, 2));
        normal =
            std::max(normal, std::acos(std::clamp(na.normalized().dot(nb.normalized()), -1.0, 1.0)) * 180.0 / M_PI);
        ++covered;
      }
    EXPECT_GT(covered, 1000) << name;
    std::printf("%s: max position %.2e of the diagonal, max normal %.3f degrees over %d pixels\n", name, position,
                normal, covered);
    EXPECT_LT(position, 1e-4) << name;
    EXPECT_LT(normal, 1.0) << name;
  }
}

// The colour of one frame of the mesh, framed from (35°, 25°).
Image render_color(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const DrawOptions& o, int size = 160) {
  RenderTarget target(size, size);
  renderer.draw(target, frame_mesh(mesh, 35.0f, 25.0f), o);
  return target.read(0);
}

// An edit runs the compute passes on the changed vertex only, and gives the same image as
// rebuilding everything for the edited mesh.
TEST_F(GpuTest, EditingOneCovarianceUpdatesTheSurface) {
  CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  DrawOptions o;
  o.mode = ShadingMode::normals;
  const Image before = render_color(renderer, mesh, o);
  const auto nodes = renderer.tables().plans.nodes;
  mesh.covariances[6] *= 0.001;  // vertex (1, 1, 1) faces the camera: a sharp corner
  renderer.update_vertices(mesh, {6});
  const Image edited = render_color(renderer, mesh, o);
  EXPECT_EQ(renderer.tables().plans.nodes, nodes);
  SurfaceRenderer rebuilt;
  rebuilt.set_mesh(mesh);
  const Image fresh = render_color(rebuilt, mesh, o);
  int changed = 0, mismatched = 0;
  for (size_t i = 0; i < before.pixels.size(); ++i) {
    changed += std::abs(before.pixels[i] - edited.pixels[i]) > 0.02f;
    mismatched += std::abs(fresh.pixels[i] - edited.pixels[i]) > 0.02f;
  }
  EXPECT_GT(changed, 200);
  EXPECT_EQ(mismatched, 0);
}

// --wireframe over static triangles (render --reference) draws every triangle's edges, shading
// untouched elsewhere; without it the triangle program has no geometry shader.
TEST_F(GpuTest, WireframeOverStaticTriangles) {
  const CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  renderer.set_triangles(reference_triangles(mesh, 2));
  DrawOptions o;
  o.static_triangles = true;
  const Image plain = render_color(renderer, mesh, o);
  o.wireframe = true;
  const Image wire = render_color(renderer, mesh, o);
  int darker = 0, brighter = 0;
  for (size_t i = 0; i < plain.pixels.size(); i += 4) {
    darker += wire.pixels[i] < plain.pixels[i] - 0.2f;
    brighter += wire.pixels[i] > plain.pixels[i] + 0.02f;
  }
  EXPECT_GT(darker, 300);  // 96 quads' worth of triangle edges in view
  EXPECT_EQ(brighter, 0);
}

// Ellipsoid instances follow an edit (only the changed vertex is re-uploaded) and the k-σ scale.
TEST_F(GpuTest, EllipsoidsFollowEditsAndSigma) {
  CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  DrawOptions o;
  o.ellipsoids = true;
  o.sigma_scale = 1.5f;
  const Image before = render_color(renderer, mesh, o);
  mesh.covariances[6] *= 9.0;  // three times the radii
  renderer.update_vertices(mesh, {6});
  const Image edited = render_color(renderer, mesh, o);
  SurfaceRenderer rebuilt;
  rebuilt.set_mesh(mesh);
  const Image fresh = render_color(rebuilt, mesh, o);
  o.sigma_scale = 3.0f;
  const Image wider = render_color(rebuilt, mesh, o);
  int changed = 0, mismatched = 0, widened = 0;
  for (size_t i = 0; i < before.pixels.size(); ++i) {
    changed += std::abs(before.pixels[i] - edited.pixels[i]) > 0.02f;
    mismatched += std::abs(fresh.pixels[i] - edited.pixels[i]) > 0.02f;
    widened += std::abs(fresh.pixels[i] - wider.pixels[i]) > 0.02f;
  }
  EXPECT_GT(changed, 50);
  EXPECT_EQ(mismatched, 0);
  EXPECT_GT(widened, 50);
}

// Quads at a uniform integer level L with equal spacing: L×L cells, 2·L² triangles per patch.
TEST_F(GpuTest, StatisticsCountTheTessellatedTriangles) {
  for (const auto& [name, size, level] : {std::tuple{"cube", 0, 4}, std::tuple{"sphere", 500, 16}}) {
    const CovarianceMesh mesh = make_sample(name, size);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh);
    DrawOptions o;
    o.level = float(level);
    o.surface_cache = false;  // the live pipeline's counts; the cached frame's below
    render_color(renderer, mesh, o, 64);
    glFinish();
    EXPECT_EQ(renderer.last_statistics().triangles, 0) << name << ": statistics are off by default";
    renderer.set_collect_statistics(true);
    for (int frame = 0; frame < 2; ++frame) render_color(renderer, mesh, o, 64);
    glFinish();
    const DrawStatistics s = renderer.last_statistics();
    const long long patches = renderer.tables().plans.n_patches();
    EXPECT_EQ(s.patches, patches) << name;
    EXPECT_EQ(s.triangles, patches * 2 * level * level) << name;
    if (GLAD_GL_ARB_pipeline_statistics_query)
      EXPECT_GT(s.vertices, 0) << name;
    else
      EXPECT_EQ(s.vertices, -1) << name;
    std::printf("%s: %d patches at level %d: %lld triangles, %lld evaluation shader invocations\n", name, s.patches,
                level, s.triangles, s.vertices);
    // A frame from the surface cache counts the stored triangles and the stored vertices it drew:
    // each distinct one at least once, at most three per triangle.
    o.surface_cache = true;
    for (int frame = 0; frame < 3; ++frame) render_color(renderer, mesh, o, 64);
    glFinish();
    const DrawStatistics c = renderer.last_statistics();
    EXPECT_TRUE(c.cached) << name;
    EXPECT_EQ(c.triangles, patches * 2 * level * level) << name;
    if (GLAD_GL_ARB_pipeline_statistics_query) {
      EXPECT_GE(c.vertices, renderer.surface_cache().distinct_vertices()) << name;
      EXPECT_LE(c.vertices, 3 * c.triangles) << name;
    } else {
      EXPECT_EQ(c.vertices, -1) << name;
    }
    std::printf("%s from the surface cache: %lld triangles, %lld vertex shader invocations (%lld distinct vertices)\n",
                name, c.triangles, c.vertices, renderer.surface_cache().distinct_vertices());
  }
}

// Every patch of a mesh larger than one draw batch is drawn, at uniform level 1 and at adaptive
// levels that are 1 everywhere: the sphere covers the pixels the CPU reference's triangles cover.
// llvmpipe leaves whole patches out of a draw of more than 4096 of them.
TEST_F(GpuTest, EveryPatchOfALargeMeshIsDrawnAtLevelOne) {
  const CovarianceMesh mesh = make_sample("sphere", 10000);
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  ASSERT_GT(renderer.tables().plans.n_patches(), 8192);
  const auto covered = [&](float level, float pixels, bool reference = false) {
    DrawOptions o;
    o.surface_cache = false;
    o.level = level;
    o.pixels = pixels;
    o.static_triangles = reference;
    RenderTarget target(160, 160);
    renderer.draw(target, frame_mesh(mesh, 35.0f, 25.0f), o);
    return count_covered_pixels(target.read(2));
  };
  renderer.set_triangles(reference_triangles(mesh, 2, PlanOptions{}));
  const long long reference = covered(1.0f, 0.0f, true);
  EXPECT_GT(reference, 160 * 160 / 8);
  EXPECT_NEAR(double(covered(1.0f, 0.0f)), double(reference), 0.01 * double(reference)) << "level 1";
  EXPECT_NEAR(double(covered(1.0f, 1000.0f)), double(reference), 0.01 * double(reference)) << "adaptive";
}

// The base-mesh lines follow an edit that moves a vertex: the lines meet where the vertex now
// projects, exactly as for a renderer built for the edited mesh.
TEST_F(GpuTest, MeshLinesFollowAMovedVertex) {
  CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  const Camera camera = frame_box(Vec3(-3, -3, -3), Vec3(3, 3, 3), 35.0f, 25.0f);
  DrawOptions o;
  o.mesh_lines = true;
  o.level = 2;
  RenderTarget target(200, 200);
  renderer.draw(target, camera, o);
  const Image before = target.read(0);
  mesh.set_mean(6, Vec3(1.0, 3.2, 1.0));  // (1, 1, 1) moved far up, clear of the surface
  renderer.update_vertices(mesh, {6});
  renderer.draw(target, camera, o);
  const Image edited = target.read(0);
  const auto p = project_to_pixel(camera, 200, 200, glm::vec3(1.0f, 3.2f, 1.0f));
  ASSERT_TRUE(p.has_value());
  const int px = int(p->x), py = int(p->y);
  ASSERT_TRUE(px > 1 && py > 1 && px < 198 && py < 198);
  const auto line_near = [&](const Image& im) {
    int n = 0;
    for (int y = py - 1; y <= py + 1; ++y)
      for (int x = px - 1; x <= px + 1; ++x)
        n += std::abs(im.at(x, y, 0) - 0.45f) < 0.03f && std::abs(im.at(x, y, 2) - 0.45f) < 0.03f;
    return n;
  };
  EXPECT_EQ(line_near(before), 0);
  EXPECT_GE(line_near(edited), 2);
  SurfaceRenderer rebuilt;
  rebuilt.set_mesh(mesh);
  rebuilt.draw(target, camera, o);
  const Image fresh = target.read(0);
  int mismatched = 0;
  for (size_t i = 0; i < fresh.pixels.size(); ++i) mismatched += std::abs(fresh.pixels[i] - edited.pixels[i]) > 0.02f;
  EXPECT_EQ(mismatched, 0);
}

// With a pass timer the compute passes and each drawn layer are timed, in the order first run;
// layers not drawn are not reported.
TEST_F(GpuTest, PassTimerSeesComputeAndEachDrawnLayer) {
  const CovarianceMesh mesh = make_sample("cube");
  SurfaceRenderer renderer;
  GpuPassTimer timer;
  renderer.set_pass_timer(&timer);
  renderer.set_mesh(mesh);
  DrawOptions o;
  o.mesh_lines = true;
  render_color(renderer, mesh, o, 64);
  glFinish();
  const auto names = [&timer] {
    std::vector<std::string> out;
    for (const auto& [name, ms] : timer.latest()) {
      EXPECT_TRUE(std::isfinite(ms) && ms >= 0.0) << name;
      out.push_back(name);
    }
    return out;
  };
  EXPECT_EQ(names(), (std::vector<std::string>{"9D + stencils", "surface", "mesh lines"}));
  o.ellipsoids = true;
  render_color(renderer, mesh, o, 64);
  glFinish();
  EXPECT_EQ(names(), (std::vector<std::string>{"9D + stencils", "surface", "mesh lines", "ellipsoids"}));
  renderer.set_pass_timer(nullptr);
}

// Passes larger than one dispatch can reach are split into several. llvmpipe's limits (65,535 groups
// of 64, storage blocks of 128 MiB) let no buffer hold 65,535 × 64 points, so the test lowers the
// group limit to 64 (4,096 rows a dispatch): the passes over 186,054 rows take 46 dispatches, and
// every point matches the CPU, the last dispatch's included.
TEST_F(GpuTest, ComputePassesSplitIntoSeveralDispatches) {
  SubdivisionOptions loop;
  loop.scheme = Scheme::loop;
  loop.levels = 3;
  const CovarianceMesh mesh = subdivide(make_sample("cone"), loop).mesh;
  SurfaceRenderer renderer;
  DeviceLimitsForTests::lower(renderer, 64, 0);
  renderer.set_mesh(
      mesh, PlanOptions{Scheme::catmull_clark, 5, LoopBeta::loop, false});  // the thesis plans of depth 5: many rows
  const int n_rows = renderer.tables().stencils.n_rows();
  ASSERT_GT(n_rows, 20 * 64 * 64);
  expect_points_match(renderer.read_points(),
                      apply_stencils(renderer.tables().stencils, base_points(renderer.frame().to_frame(mesh))),
                      "rebuild");
  // An edit (the listed-rows path) splits the same way: 64 rows a dispatch.
  DeviceLimitsForTests::lower(renderer, 1, 0);
  CovarianceMesh edited = mesh;
  edited.set_mean(0, mesh.mean(0) + Vec3(0.05, 0.0, 0.0));
  renderer.update_vertices(edited, {0});
  expect_points_match(renderer.read_points(),
                      apply_stencils(renderer.tables().stencils, base_points(renderer.frame().to_frame(edited))),
                      "edit");
}

// A mesh whose plan points exceed the device's largest storage block is refused before any upload,
// with one line naming the mesh and the figures (the limit lowered to 64 KiB: llvmpipe's 128 MiB
// takes some 3 million plan points, too many to build in a test); the previous mesh stays.
TEST_F(GpuTest, AMeshBeyondTheStorageLimitIsRefusedWithItsFigures) {
  SurfaceRenderer renderer;
  renderer.set_mesh(make_sample("cube"));
  DeviceLimitsForTests::lower(renderer, 0, 64 << 10);
  const CovarianceMesh sphere = make_sample("sphere");  // 1536 quads: more than 64 KiB of points
  try {
    renderer.set_mesh(sphere);
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the mesh (" + std::to_string(sphere.n_vertices()) + " vertices, " +
                        std::to_string(sphere.n_faces()) + " faces) needs "),
              std::string::npos)
        << what;
    EXPECT_NE(what.find(" KiB of plan points, more than the GPU's largest storage buffer (64.0 KiB)"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  RenderTarget target(32, 32);  // the previous mesh is still drawn
  renderer.draw(target, frame_mesh(make_sample("cube"), 30.0f, 20.0f), DrawOptions{});
  const Image image = target.read(0);
  EXPECT_LT(image.at(16, 16, 0), 0.99f);
}

// The buffers kept per patch corner for a mesh of a million quads (four million corners) each fit a
// storage block of 128 MiB, llvmpipe's largest: the corner limits (two vec4 each) and the edge
// midpoints (one) are buffers of their own.
TEST_F(GpuTest, TheCornerBuffersOfAMillionQuadsFitTheSmallestStorageBlock) {
  SurfaceTables tables;
  tables.plans.patch_roots.assign(1'000'000, 0);
  tables.stencils.offsets = {0};
  EXPECT_NO_THROW(PlanBuffers::check_fits(tables, 1'000'000, 1'000'000, 128ll << 20, PointPrecision::single_float));
}

}  // namespace
}  // namespace gps
