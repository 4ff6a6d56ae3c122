// The map between patches and base faces: a quad is one patch, a k-gon k (Catmull-Clark), a
// triangle one under Loop; the patches of some faces follow it back.
#include "core/plans/patch_faces.h"

#include <gtest/gtest.h>

#include "core/modelling/samples.h"
#include "core/plans/planned_surface.h"
#include "core/support/error.h"
#include "tests/support/error_of.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using V = std::vector<int>;

TEST(PatchFaces, CylinderQuadsAreOnePatchAndEachOctagonEight) {
  const CovarianceMesh cylinder = make_sample("cylinder");  // 16 quads and two octagons
  const PlannedSurface surface(cylinder, PlanOptions{});
  const PatchPlans& plans = surface.tables().plans;
  ASSERT_EQ(plans.n_patches(), 16 + 2 * 8);
  const V faces = patch_faces(cylinder.topology(), plans);
  ASSERT_EQ(faces.size(), size_t(plans.n_patches()));
  std::vector<int> per_face(cylinder.n_faces(), 0);
  for (size_t p = 0; p < faces.size(); ++p) {
    ++per_face[size_t(faces[p])];
    if (p > 0) {
      EXPECT_LE(faces[p - 1], faces[p]);  // base-face order
    }
  }
  for (int f = 0; f < int(cylinder.n_faces()); ++f) {
    const int valence = cylinder.face_size(size_t(f));
    EXPECT_EQ(per_face[size_t(f)], valence == 4 ? 1 : valence) << "face " << f;
    // And back: the patches of the face are exactly those mapped to it.
    V expected;
    for (size_t p = 0; p < faces.size(); ++p)
      if (faces[p] == f) expected.push_back(int(p));
    EXPECT_EQ(patches_of_faces(cylinder.topology(), plans, {f}), expected);
  }
}

TEST(PatchFaces, LoopPlansHaveOnePatchPerTriangle) {
  const CovarianceMesh ico = test::icosahedron_mesh();
  const PlannedSurface surface(ico, PlanOptions{});
  ASSERT_EQ(surface.tables().plans.shape, PatchShape::triangle);
  const V faces = patch_faces(ico.topology(), surface.tables().plans);
  for (size_t p = 0; p < faces.size(); ++p) EXPECT_EQ(faces[p], int(p));
  EXPECT_EQ(patches_of_faces(ico.topology(), surface.tables().plans, {7, 3, 7}), (V{3, 7}));
}

TEST(PatchFaces, PlansOfAnotherMeshOrAFaceNotInTheMeshAreRefused) {
  const CovarianceMesh cube = make_sample("cube");
  const CovarianceMesh cylinder = make_sample("cylinder");
  const PlannedSurface surface(cylinder, PlanOptions{});
  EXPECT_EQ(test::error_of([&] { patch_faces(cube.topology(), surface.tables().plans); }),
            "the surface's patches do not follow its mesh's faces");
  const PlannedSurface cube_surface(cube, PlanOptions{});
  EXPECT_EQ(test::error_of([&] { patches_of_faces(cube.topology(), cube_surface.tables().plans, {6}); }),
            "face 6 is not in the mesh (6 faces)");
  EXPECT_EQ(test::error_of([&] { patches_of_faces(cube.topology(), cube_surface.tables().plans, {-1}); }),
            "face -1 is not in the mesh (6 faces)");
}

}  // namespace
}  // namespace gps
