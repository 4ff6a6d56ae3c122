// Adaptive tessellation levels (shaders/tess_levels.glsl) on OSMesa: an edge seen end-on, and an edge
// whose limit curve bends far from its chord, still get the level their size on screen asks for, so
// that the silhouette of an orthographic axis view, which runs beside such edges, is as smooth as at
// a high uniform level.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "core/modelling/affine_transform.h"
#include "core/modelling/extrude.h"
#include "core/modelling/inset.h"
#include "core/modelling/samples.h"
#include "render/gl/render_target.h"
#include "render/image/image_io.h"
#include "render/pipeline/render_framing.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "view/camera.h"

namespace gps {
namespace {

using GpuTest = test::GlTest;

// Where the surface was drawn: the position AOV's coverage (w ≥ 1).
std::vector<char> coverage_of(const Image& position) {
  std::vector<char> covered(size_t(position.width) * size_t(position.height));
  for (int y = 0; y < position.height; ++y)
    for (int x = 0; x < position.width; ++x)
      covered[size_t(y) * size_t(position.width) + size_t(x)] = position.at(x, y, 3) >= 1.0f;
  return covered;
}

// Pixels covered by exactly one of the two masks, and those covered by `a`, as a grey image (white:
// covered by `a`; black and white swapped where the masks differ) for looking at.
struct MaskDifference {
  long long differing = 0, covered = 0;
  Image image;
};

MaskDifference difference(const std::vector<char>& a, const std::vector<char>& b, int width, int height) {
  MaskDifference d;
  d.image.width = width;
  d.image.height = height;
  d.image.channels = 3;
  d.image.pixels.assign(size_t(width) * size_t(height) * 3, 0.0f);
  for (size_t i = 0; i < a.size(); ++i) {
    d.covered += a[i];
    d.differing += a[i] != b[i];
    const float grey = a[i] != b[i] ? 0.5f : a[i] ? 1.0f : 0.0f;
    for (size_t c = 0; c < 3; ++c) d.image.pixels[3 * i + c] = grey;
  }
  return d;
}

// The mesh from the front in the editor's orthographic axis view (numpad 1, then 5) in its default
// window, at the editor's default adaptive target of 6 pixels and at uniform level 32: where each
// covers the view, and where they differ. GPS_KEEP_IMAGES writes <name>_adaptive.png,
// <name>_uniform.png and <name>_difference.png.
MaskDifference front_silhouettes(const CovarianceMesh& mesh, const std::string& name) {
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  Camera camera = frame_mesh(mesh, 0.0f, 0.0f);
  camera.orthographic = true;
  const int width = 1280, height = 800;
  RenderTarget target(width, height);
  const auto coverage = [&](const DrawOptions& o) {
    renderer.draw(target, camera, o);
    return std::pair{coverage_of(target.read(1)), target.read(0)};
  };
  DrawOptions adaptive;
  adaptive.pixels = 6.0f;
  DrawOptions fine;
  fine.level = 32.0f;
  const auto [adaptive_mask, adaptive_color] = coverage(adaptive);
  const auto [fine_mask, fine_color] = coverage(fine);
  MaskDifference d = difference(fine_mask, adaptive_mask, width, height);
  if (std::getenv("GPS_KEEP_IMAGES")) {
    write_image(name + "_adaptive.png", adaptive_color);
    write_image(name + "_uniform.png", fine_color);
    write_image(name + "_difference.png", d.image);
  }
  std::printf("coverage: %lld pixels, %lld differ between adaptive and uniform level 32\n", d.covered, d.differing);
  return d;
}

// The cube stretched y×2, its top face's four vertices then scaled z×0.05 about their centre: their
// Gaussians flatten into discs, and the limit curves along the top's short edges bend far from
// their chords, up over the top and back.
CovarianceMesh stretched_with_flat_top(const CovarianceMesh& cube) {
  CovarianceMesh mesh = transform_vertices(cube, {}, AffineMap{Vec3(1.0, 2.0, 1.0).asDiagonal(), Vec3::Zero()}).mesh;
  std::vector<int> top;
  Vec3 centre = Vec3::Zero();
  for (int i = 0; i < int(mesh.n_vertices()); ++i)
    if (mesh.mean(size_t(i)).y() > 1.5) {
      top.push_back(i);
      centre += mesh.mean(size_t(i)) / 4.0;
    }
  EXPECT_EQ(top.size(), 4u);
  return transform_vertices(mesh, top, AffineMap::about(centre, Vec3(1.0, 1.0, 0.05).asDiagonal())).mesh;
}

// The cube sample from the front in the orthographic axis view: the patch edges along the view
// direction project to a point. Their level must still follow their size, or the side patches, whose
// silhouette runs across them, are cut into a polygon of a few segments, with notches where the
// uniform render is round.
TEST_F(GpuTest, EdgesSeenEndOnKeepTheSilhouetteOfAnOrthographicAxisView) {
  const MaskDifference d = front_silhouettes(make_sample("cube"), "front_ortho");
  ASSERT_GT(d.covered, 1280 * 800 / 20) << "the cube fills much of the view";
  // Both silhouettes are round: they differ by rasterisation alone, a few pixels along the outline.
  EXPECT_LE(d.differing, 40);
}

// The cube with a flattened top (stretched_with_flat_top). From the front, orthographic, the chords of
// the top patch's short edges alone would give it a few segments across its outline, a band lower
// than the uniform render's with notches at its ends.
TEST_F(GpuTest, FlattenedGaussiansKeepTheSilhouetteOfTheirCurvedEdges) {
  const MaskDifference d = front_silhouettes(stretched_with_flat_top(make_sample("cube")), "flattened_top");
  ASSERT_GT(d.covered, 1280 * 800 / 20) << "the stretched cube fills much of the view";
  // Both outlines are round; where the top's is nearly level, a sub-pixel difference flips a run of
  // pixels (as between uniform levels 16 and 64), but no band is missing along the top patch.
  EXPECT_LE(d.differing, 200);
}

// The same flattened top on a cube whose faces but the bottom are each cut into two triangles: the
// mesh is planned by Catmull-Clark (a quad remains), each triangle split into three quads, so every
// edge but the bottom's is two halves beside two halves, and no patch edge covers a whole mesh edge.
// Each half's own limit curve must then stand for it, or its chord alone notches the outline.
TEST_F(GpuTest, FlattenedGaussiansKeepTheSilhouetteAlongSplitFacesHalfEdges) {
  const CovarianceMesh cube = make_sample("cube");
  std::vector<Vec3> means;
  for (size_t v = 0; v < cube.n_vertices(); ++v) means.push_back(cube.mean(v));
  std::vector<std::vector<int>> faces;
  for (size_t f = 0; f < cube.n_faces(); ++f) {
    const std::vector<int> c(cube.face(f).begin(), cube.face(f).end());
    if (std::all_of(c.begin(), c.end(), [&](int v) { return means[size_t(v)].y() < -0.5; })) {
      faces.push_back(c);  // the bottom
    } else {
      faces.push_back({c[0], c[1], c[2]});
      faces.push_back({c[0], c[2], c[3]});
    }
  }
  ASSERT_EQ(faces.size(), 11u);
  const CovarianceMesh mesh =
      stretched_with_flat_top(make_covariance_mesh(means, cube.covariances, faces, "triangulated cube"));
  const MaskDifference d = front_silhouettes(mesh, "flattened_top_split_faces");
  ASSERT_GT(d.covered, 1280 * 800 / 20) << "the stretched cube fills much of the view";
  EXPECT_LE(d.differing, 200);
}

// A mug as a designer makes one: the cylinder sample's top inset, its inner face extruded down. The
// rim's patch edges that run across it are short, while their limit curves round over the rim; from
// their chords alone, adaptive levels gave them a few segments, and the normals interpolated across
// those long triangles streaked the rim's highlight. Looked into from above, the adaptive render's
// normals must be those of uniform level 32 wherever both cover the view.
TEST_F(GpuTest, AdaptiveLevelsShadeTheRoundedRimOfAMugAsAUniformLevelDoes) {
  CovarianceMesh mesh = make_sample("cylinder");
  const int top = 16;  // the cap at y = 1
  mesh = inset_faces(mesh, {top}, 0.2).mesh;
  mesh = extrude_faces(mesh, {top}, -1.5).mesh;
  SurfaceRenderer renderer;
  renderer.set_mesh(mesh);
  const int width = 800, height = 600;
  DrawOptions adaptive;
  adaptive.pixels = 6.0f;  // `gpsurf render`'s default at this size
  DrawOptions fine;
  fine.level = 32.0f;
  // As `gpsurf render --camera 30,60` frames it.
  const Camera camera = render_camera(renderer, mesh, {30.0f, 60.0f}, 1, adaptive, width, height);
  RenderTarget target(width, height);
  struct Buffers {
    Image color, position, normal;
  };
  const auto buffers = [&](const DrawOptions& o) {
    renderer.draw(target, camera, o);
    return Buffers{target.read(0), target.read(1), target.read(2)};
  };
  const Buffers a = buffers(adaptive), f = buffers(fine);
  // Pixels that show the same place in both (within a thousandth of the view's height: not where
  // the outline or the rim's near edge hides something else in one of them), white where their
  // normals lie more than 3 degrees apart.
  Image turned;
  turned.width = width;
  turned.height = height;
  turned.channels = 3;
  turned.pixels.assign(size_t(width) * size_t(height) * 3, 0.0f);
  long long same_place = 0, differing = 0;
  const float near = 1e-3f * view_height(camera), cos_limit = std::cos(3.0f * 3.14159265f / 180.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (a.position.at(x, y, 3) < 1.0f || f.position.at(x, y, 3) < 1.0f) continue;
      float apart = 0.0f, dot = 0.0f;
      for (int c = 0; c < 3; ++c) {
        apart += std::pow(a.position.at(x, y, c) - f.position.at(x, y, c), 2.0f);
        dot += a.normal.at(x, y, c) * f.normal.at(x, y, c);
      }
      if (std::sqrt(apart) > near) continue;
      ++same_place;
      if (dot >= cos_limit) continue;
      ++differing;
      for (size_t c = 0; c < 3; ++c) turned.pixels[3 * (size_t(y) * size_t(width) + size_t(x)) + c] = 1.0f;
    }
  if (std::getenv("GPS_KEEP_IMAGES")) {
    write_image("mug_adaptive.png", a.color);
    write_image("mug_uniform.png", f.color);
    write_image("mug_normals_turned.png", turned);
  }
  ASSERT_GT(same_place, width * height / 5) << "the mug fills much of the view";
  std::printf("%lld pixels show the same place, %lld of them with normals more than 3 degrees apart\n", same_place,
              differing);
  // A few single pixels may lie where the outline grazes the view; no streak across the rim.
  EXPECT_LE(differing, 20);
}

}  // namespace
}  // namespace gps
