// Normals on infinitely sharp creases (core/plans/patch_adjacency.h, shaders/limit_point.glsl): every
// drawn vertex on a crease edge or corner carries the normal of its own patch's side, as the CPU
// evaluator gives it, live and in the surface cache after edits, while the positions stay shared.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/evaluation/patch_eval.h"
#include "core/io/mesh_io.h"
#include "render/cache/surface_cache.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/plan_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using CreaseNormals = test::GlTest;

CovarianceMesh creased(const std::string& name) {
  return read_mesh(std::string(GPS_TEST_DATA_DIR) + "/" + name + ".ply");
}

double degrees_between(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

// Every tessellated vertex's normal against the CPU evaluator's at the vertex's own patch and
// (u, v): on a crease each side's own limit normal, elsewhere the one both sides share.
double worst_normal_degrees(SurfaceRenderer& renderer, const CovarianceMesh& mesh, float level, size_t& count) {
  DrawOptions o;
  o.level = level;
  const std::vector<TessellatedVertex> vertices = renderer.capture_vertices(Camera{}, o, 256, 256);
  const test::PlannedMesh cpu(mesh, PlanOptions{});
  double worst = 0.0;
  count = vertices.size();
  for (const TessellatedVertex& v : vertices) {
    const auto s = evaluate_patch(cpu.tables.plans, cpu.points, int(v.patch), v.u, v.v);
    if (!s) continue;
    const Vec3 gpu(v.normal[0], v.normal[1], v.normal[2]);
    worst = std::max(worst, gpu.allFinite() ? degrees_between(s->normal, gpu) : 180.0);
  }
  return worst;
}

TEST_F(CreaseNormals, VerticesOnACreaseTakeTheirOwnPatchsNormal) {
  for (const char* name : {"creased_cube", "creased_cylinder", "creased_cone"})
    for (const bool random : {false, true}) {
      const CovarianceMesh mesh = random ? test::with_random_covariances(creased(name), 11) : creased(name);
      SurfaceRenderer renderer;
      renderer.set_mesh(mesh);
      for (const float level : {1.0f, 4.0f, 7.0f}) {
        size_t count = 0;
        const double worst = worst_normal_degrees(renderer, mesh, level, count);
        std::printf("%-16s %-6s level %.0f: worst normal %.4f degrees from its own patch's, %zu vertices\n", name,
                    random ? "random" : "file", level, worst, count);
        EXPECT_GT(count, size_t(0)) << name;
        EXPECT_LT(worst, 0.05) << name << (random ? " random" : "") << " level " << level;
      }
    }
}

struct RimCheck {
  int top = 0, side = 0;                     // triangle corners on the top face's rim, by the face they draw
  double top_degrees = 0, side_degrees = 0;  // the worst angle between such a corner's normal and its triangle's
};

// The creased cube's top face is flat and bounded by infinitely sharp edges. A triangle with a
// corner on its plane draws the top (flat, normal +z) or a side face meeting it at the rim: each
// corner's normal must be its own triangle's side's, which at the rim differ by tens of degrees.
RimCheck check_rim(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                   const std::vector<std::array<int, 3>>& triangles) {
  double top = -1e30, size = 0;
  for (const Vec3& p : positions) {
    top = std::max(top, p.z());
    size = std::max(size, p.cwiseAbs().maxCoeff());
  }
  RimCheck r;
  for (const auto& t : triangles) {
    const Vec3 face =
        (positions[size_t(t[1])] - positions[size_t(t[0])]).cross(positions[size_t(t[2])] - positions[size_t(t[0])]);
    if (face.norm() == 0.0) continue;
    const bool flat = face.normalized().z() > 1.0 - 1e-6;
    for (const int c : t) {
      if (positions[size_t(c)].z() < top - 1e-6 * size) continue;
      const double d = degrees_between(normals[size_t(c)], face);
      if (flat) {
        ++r.top;
        r.top_degrees = std::max(r.top_degrees, degrees_between(normals[size_t(c)], Vec3(0, 0, 1)));
      } else {
        ++r.side;
        r.side_degrees = std::max(r.side_degrees, d);
      }
    }
  }
  return r;
}

RimCheck check_rim(const TriangleMesh& t) { return check_rim(t.positions, t.normals, t.triangles); }

void expect_sharp_rim(const RimCheck& r, const std::string& what) {
  std::printf("%s: %d top and %d side corners on the rim, worst %.3f and %.3f degrees\n", what.c_str(), r.top, r.side,
              r.top_degrees, r.side_degrees);
  EXPECT_GT(r.top, 0) << what;
  EXPECT_GT(r.side, 0) << what;
  EXPECT_LT(r.top_degrees, 1e-3) << what << ": a top corner with a side's normal";
  EXPECT_LT(r.side_degrees, 30.0) << what << ": a side corner with the top's normal";
}

TEST_F(CreaseNormals, TheCreasedCubesRimIsSharpOnBothSides) {
  const CovarianceMesh mesh = creased("creased_cube");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  for (const float level : {2.0f, 8.0f}) {
    DrawOptions o;
    o.level = level;
    const std::vector<TessellatedVertex> vertices = renderer.capture_vertices(Camera{}, o, 256, 256);
    std::vector<Vec3> positions, normals;
    std::vector<std::array<int, 3>> triangles;
    for (const TessellatedVertex& v : vertices) {
      positions.emplace_back(v.position[0], v.position[1], v.position[2]);
      normals.emplace_back(v.normal[0], v.normal[1], v.normal[2]);
    }
    for (int i = 0; i + 2 < int(vertices.size()); i += 3) triangles.push_back({i, i + 1, i + 2});
    expect_sharp_rim(check_rim(positions, normals, triangles), "live, level " + std::to_string(int(level)));
  }
}

// The surface cache evaluates its welded vertices again after an edit (render/cache/stored_vertex_evaluation.h):
// the rim keeps both sides' normals, bit for bit what a capture of the edited points stores.
TEST_F(CreaseNormals, TheSurfaceCacheKeepsEachSidesNormalThroughEdits) {
  CovarianceMesh mesh = creased("creased_cube");
  SurfaceRenderer renderer;
  SurfaceCache& cache = renderer.surface_cache();
  cache.set_weld(SurfaceCache::Weld::at_capture);
  renderer.set_mesh(mesh);
  RenderTarget target(160, 160);
  const Camera camera = frame_mesh(mesh, 35.0f, 25.0f);
  DrawOptions o;
  o.level = 8;
  renderer.draw(target, camera, o);
  renderer.draw(target, camera, o);
  ASSERT_TRUE(cache.stored_vertices_welded());
  expect_sharp_rim(check_rim(cache.stored_triangles()), "captured");
  // A bottom corner, then a top one within the top's plane (the top stays flat).
  for (const auto& [v, move] : {std::pair{0, Vec3(0.2, 0.1, -0.3)}, std::pair{6, Vec3(0.3, -0.2, 0.0)}}) {
    const std::string what = "edited vertex " + std::to_string(v);
    mesh.set_mean(size_t(v), mesh.mean(size_t(v)) + move);
    renderer.update_vertices(mesh, {v});
    renderer.draw(target, camera, o);
    EXPECT_GT(cache.evaluated_patches(), 0) << what;
    const TriangleMesh evaluated = cache.stored_triangles();
    expect_sharp_rim(check_rim(evaluated), what);
    DrawOptions other = o;
    other.level = 3;
    renderer.draw(target, camera, other);
    renderer.draw(target, camera, o);  // the same points captured
    const TriangleMesh captured = cache.stored_triangles();
    EXPECT_EQ(evaluated.positions, captured.positions) << what;
    EXPECT_EQ(evaluated.normals, captured.normals) << what;
    EXPECT_EQ(evaluated.triangles, captured.triangles) << what;
  }
}

}  // namespace
}  // namespace gps
