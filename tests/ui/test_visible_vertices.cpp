// Which control vertices the camera sees (view/visible_vertices.h): the software depth buffer of
// the control mesh against the exact answers on convex meshes and an occluder.
#include "view/visible_vertices.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/modelling/samples.h"
#include "core/modelling/delete_elements.h"

namespace gps {
namespace {

Viewport view_of(const Camera& camera, int width = 640, int height = 480) {
  Viewport v;
  v.camera = camera;
  v.width = width;
  v.height = height;
  return v;
}

// On a convex closed mesh a vertex is visible exactly when one of its faces faces the eye.
// Orthographic (`parallel`): one of its faces faces the direction towards the eye.
std::vector<char> convex_visible(const CovarianceMesh& mesh, const Vec3& eye, bool parallel = false) {
  std::vector<char> visible(mesh.n_vertices(), 0);
  for (size_t f = 0; f < mesh.n_faces(); ++f) {
    std::vector<Vec3> p;
    for (const int v : mesh.face(f)) p.push_back(mesh.mean(size_t(v)));
    const Vec3 normal = (p[1] - p[0]).cross(p[2] - p[0]);
    if (normal.dot(parallel ? eye : Vec3(eye - p[0])) > 1e-9)
      for (const int v : mesh.face(f)) visible[size_t(v)] = 1;
  }
  return visible;
}

TEST(VisibleVertices, TheCubeShowsSevenCornersAndHidesTheFarOne) {
  const CovarianceMesh mesh = make_sample("cube");
  for (const bool orthographic : {false, true}) {
    Camera camera = frame_mesh(mesh);
    camera.orthographic = orthographic;
    const std::vector<char> visible = visible_vertices(view_of(camera), mesh);
    EXPECT_EQ(visible, convex_visible(mesh, to_vec(camera.eye()))) << "orthographic " << orthographic;
    EXPECT_EQ(std::count(visible.begin(), visible.end(), 1), 7);
    // The default camera looks from +x, +y, +z: the hidden corner is (−1, −1, −1), vertex 0.
    EXPECT_FALSE(visible[0]);
  }
}

// Looking into a tube's open end, the far half of its rim is seen through the opening although all
// of its faces turn away from the camera; the closed bottom's rim is hidden behind the wall.
TEST(VisibleVertices, TheFarRimIsSeenThroughAnOpening) {
  const CovarianceMesh cylinder = make_sample("cylinder");  // y up; rings of 8 at y = -1, 0, 1; face 16 the top cap
  const CovarianceMesh tube = delete_faces(cylinder, {16}).mesh;
  ASSERT_EQ(tube.n_vertices(), 24u);
  const Camera camera = frame_mesh(tube, 0.0f, 30.0f);  // from above the open top
  const std::vector<char> visible = visible_vertices(view_of(camera), tube);
  const Vec3 eye = to_vec(camera.eye());
  int far_rim = 0;
  for (int v = 16; v < 24; ++v) {
    EXPECT_TRUE(visible[size_t(v)]) << "top rim vertex " << v;
    const Vec3 outward(tube.mean(size_t(v)).x(), 0, tube.mean(size_t(v)).z());
    far_rim += outward.dot(Vec3(eye.x(), 0, eye.z())) < -1e-9;
  }
  EXPECT_GE(far_rim, 3) << "the camera sees the far side of the rim";
  for (int v = 0; v < 8; ++v) {
    const Vec3 outward(tube.mean(size_t(v)).x(), 0, tube.mean(size_t(v)).z());
    if (outward.dot(Vec3(eye.x(), 0, eye.z())) < -1e-9) {
      EXPECT_FALSE(visible[size_t(v)]) << "bottom vertex " << v;
    }
  }
}

// On the sphere, convex with nearly planar quads: a vertex one of whose faces clearly faces the eye
// is visible, one all of whose faces clearly face away is not (at the silhouette either may be).
TEST(VisibleVertices, TheSphereShowsItsFrontHalf) {
  const CovarianceMesh mesh = make_sample("sphere", 384);
  for (const float yaw : {30.0f, 160.0f, -75.0f}) {
    const Camera camera = frame_mesh(mesh, yaw, 20.0f);
    const Vec3 eye = to_vec(camera.eye());
    const std::vector<char> visible = visible_vertices(view_of(camera, 800, 600), mesh);
    std::vector<double> facing(mesh.n_vertices(), -1.0);  // the best cosine of a face's normal towards the eye
    for (size_t f = 0; f < mesh.n_faces(); ++f) {
      std::vector<Vec3> p;
      for (const int v : mesh.face(f)) p.push_back(mesh.mean(size_t(v)));
      Vec3 normal = Vec3::Zero(), centre = Vec3::Zero();
      for (size_t k = 0; k < p.size(); ++k) normal += p[k].cross(p[(k + 1) % p.size()]), centre += p[k];
      centre /= double(p.size());
      const double cosine = normal.normalized().dot((eye - centre).normalized());
      for (const int v : mesh.face(f)) facing[size_t(v)] = std::max(facing[size_t(v)], cosine);
    }
    int shown = 0;
    for (size_t v = 0; v < mesh.n_vertices(); ++v) {
      if (facing[v] > 0.1) {
        EXPECT_TRUE(visible[v]) << "yaw " << yaw << " vertex " << v;
      }
      if (facing[v] < -0.1) {
        EXPECT_FALSE(visible[v]) << "yaw " << yaw << " vertex " << v;
      }
      shown += visible[v];
    }
    EXPECT_GT(shown, int(mesh.n_vertices()) / 4);
    EXPECT_LT(shown, int(mesh.n_vertices()) * 3 / 4);
  }
}

// A square in front of a small cube, looked at head on: the square's corners are seen, the cube
// behind it is not, though its front face faces the camera; beside the square the corners of its
// faces that face the camera are seen.
TEST(VisibleVertices, AFaceInFrontHidesWhatIsBehindIt) {
  const auto scene = [](double cube_x) {
    std::vector<Vec3> p = {{-2, -2, 1}, {2, -2, 1}, {2, 2, 1}, {-2, 2, 1}};
    std::vector<std::vector<int>> f = {{0, 1, 2, 3}};
    const CovarianceMesh cube = make_sample("cube");
    for (size_t i = 0; i < cube.n_vertices(); ++i) p.push_back(0.5 * cube.mean(i) + Vec3(cube_x, 0, -1));
    for (size_t face = 0; face < cube.n_faces(); ++face) {
      std::vector<int> corners;
      for (const int v : cube.face(face)) corners.push_back(4 + v);
      f.push_back(corners);
    }
    return make_covariance_mesh(p, std::vector<Mat3>(p.size(), 0.01 * Mat3::Identity()), f, "scene");
  };
  for (const bool orthographic : {false, true}) {
    Camera camera;
    camera.target = glm::vec3(0.0f);
    camera.yaw_degrees = 0.0f;  // looking down −z
    camera.pitch_degrees = 0.0f;
    camera.distance = 12.0f;
    camera.orthographic = orthographic;
    const CovarianceMesh hidden = scene(0.0);
    const std::vector<char> visible = visible_vertices(view_of(camera), hidden);
    for (int v = 0; v < 4; ++v) EXPECT_TRUE(visible[size_t(v)]) << "square corner " << v;
    for (int v = 4; v < 12; ++v) EXPECT_FALSE(visible[size_t(v)]) << "cube corner " << v - 4;

    const CovarianceMesh beside = scene(4.0);
    const std::vector<char> seen = visible_vertices(view_of(camera), beside);
    // Orthographic: the cube's inner side is edge-on.
    const Vec3 eye = to_vec(camera.eye());
    const std::vector<char> facing =
        convex_visible(beside, orthographic ? Vec3(eye - to_vec(camera.target)) : eye, orthographic);
    for (int v = 4; v < 12; ++v) EXPECT_EQ(seen[size_t(v)], facing[size_t(v)]) << "cube corner " << v - 4;
  }
}

}  // namespace
}  // namespace gps
