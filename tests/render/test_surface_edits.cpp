// Edits against rebuilds: the plan points and the tessellated vertices an edit leaves equal those of
// a renderer set up anew for the edited mesh.
#include <gtest/gtest.h>

#include <cstring>

#include "core/modelling/samples.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"
#include "tests/support/gl_fixture.h"

namespace gps {
namespace {

using GpuTest = test::GlTest;

// The plan points, the corner pass's output and the tessellated vertices (the corners from the corner
// pass's listed slots included) after an edit equal those of the edited mesh set anew, bit for bit,
// for quad and triangle patches: edits of one vertex, of a few, of half (whole buffers), and of every
// vertex made a needle (whole buffers in a new point precision).
TEST_F(GpuTest, EditsOfAnySizeEqualARebuild) {
  for (const char* name : {"torus", "icosphere"}) {
    CovarianceMesh mesh = make_sample(name);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh);
    const std::vector<std::vector<int>> edits = {{5},
                                                 {1, 40, 41, 200},
                                                 [&mesh] {
                                                   std::vector<int> most;
                                                   for (int v = 0; v < int(mesh.n_vertices()); v += 2)
                                                     most.push_back(v);
                                                   return most;
                                                 }(),
                                                 [&mesh] {
                                                   std::vector<int> all(mesh.n_vertices());
                                                   for (int v = 0; v < int(all.size()); ++v) all[size_t(v)] = v;
                                                   return all;
                                                 }()};
    DrawOptions o;
    o.level = 3;
    for (const auto& changed : edits) {
      const bool needles = changed.size() == mesh.n_vertices();
      const Mat3 thin = Vec3(1.0, 1.0, 1e-3).asDiagonal();  // Σ's condition times 1e6
      for (const int v : changed) {
        const Mat3 sigma = mesh.covariance(size_t(v));
        mesh.set_covariance(size_t(v), needles ? Mat3(thin * sigma * thin) : Mat3(sigma * 0.5));
        mesh.set_mean(size_t(v), mesh.mean(size_t(v)) * 1.1);
      }
      renderer.update_vertices(mesh, changed);
      EXPECT_EQ(renderer.point_precision() == PointPrecision::double_float, needles) << name;
      SurfaceRenderer rebuilt;
      rebuilt.set_mesh(mesh, PlannedSurface(mesh, PlanOptions{}), renderer.frame());  // the edits' frame
      EXPECT_EQ(renderer.read_points(), rebuilt.read_points()) << name << ", " << changed.size() << " vertices";
      EXPECT_TRUE(renderer.read_corner_pass() == rebuilt.read_corner_pass())
          << name << ", " << changed.size() << " vertices: corner pass";
      const auto edited = renderer.capture_vertices(Camera{}, o, 512, 512),
                 fresh = rebuilt.capture_vertices(Camera{}, o, 512, 512);
      ASSERT_EQ(edited.size(), fresh.size()) << name;
      size_t differing = 0;
      for (size_t i = 0; i < edited.size(); ++i)
        differing += std::memcmp(edited[i].position, fresh[i].position, sizeof edited[i].position) != 0 ||
                     std::memcmp(edited[i].normal, fresh[i].normal, sizeof edited[i].normal) != 0;
      EXPECT_EQ(differing, 0u) << name << ", " << changed.size()
                               << " vertices: tessellated vertices differ from a rebuild";
    }
  }
}

// A tool lists the vertices it may move (G's first frame lists every selected vertex and moves none):
// the listed vertices it left as they were are not edited, so that a list of only those changes
// nothing drawn, and a list with one moved vertex edits that one, as a rebuild draws it.
TEST_F(GpuTest, ListedVerticesThatDidNotChangeAreNotEdited) {
  CovarianceMesh mesh = make_sample("torus");
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  RenderTarget target(96, 96);
  const Camera camera = frame_mesh(mesh);
  const DrawOptions o;
  for (int frame = 0; frame < 6 && !renderer.draws_as_last(target, camera, o); ++frame)
    renderer.draw(target, camera, o);
  ASSERT_TRUE(renderer.draws_as_last(target, camera, o));
  std::vector<int> all(mesh.n_vertices());
  for (int v = 0; v < int(all.size()); ++v) all[size_t(v)] = v;
  renderer.update_vertices(mesh, all);
  EXPECT_TRUE(renderer.draws_as_last(target, camera, o)) << "an edit that changed nothing was drawn again";
  mesh.set_mean(5, mesh.mean(5) * 1.1);
  renderer.update_vertices(mesh, all);
  EXPECT_FALSE(renderer.draws_as_last(target, camera, o));
  SurfaceRenderer rebuilt;
  rebuilt.set_mesh(mesh, PlannedSurface(mesh, PlanOptions{}), renderer.frame());
  EXPECT_EQ(renderer.read_points(), rebuilt.read_points());
  EXPECT_TRUE(renderer.read_corner_pass() == rebuilt.read_corner_pass());
}

}  // namespace
}  // namespace gps
