// The editor's S Z 0 (ui/editing/transform_mode.h apply_transform) and `gpsurf edit`'s transform op carry the
// Gaussians by one rule (core/modelling/affine_transform.h carried_gaussian): the same mesh, byte for
// byte, positions flattened and Gaussians held at the flatness floor.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "core/modelling/affine_transform.h"
#include "core/modelling/operation_list.h"
#include "tests/support/test_meshes.h"
#include "ui/editing/edit_reach.h"
#include "ui/document/editor_document.h"
#include "ui/editing/transform_mode.h"

namespace gps {
namespace {

TEST(TransformFlatten, TheEditorsScaleZeroIsTheOperationListsTransform) {
  MeshArrays a = arrays_of(test::cube_mesh());
  a.means[6].z() += 0.5;  // the top face (4..7) no longer flat
  const CovarianceMesh cube = build_mesh(a);
  const std::vector<int> top = {4, 5, 6, 7};

  EditorDocument document;
  document.apply(Modelled{cube, {}, "", {}, {}}, {});
  TransformMode scale(TransformKind::scale, document.mesh(), top, top[0], TransformPivot::median, Viewport{},
                      glm::vec2(0.0f));
  scale.constrain_axis(2, false);
  scale.set_typed("0", 0.0);
  std::vector<Vec3> means;
  for (size_t v = 0; v < cube.n_vertices(); ++v) means.push_back(cube.mean(v));
  document.begin_edit();
  const size_t clamped = apply_transform(document, scale, edit_reach(means, top, ReachOptions{}), 0, true);
  document.commit_edit();
  EXPECT_EQ(clamped, 4u);

  char matrix[160];
  std::snprintf(matrix, sizeof matrix, "[1,0,0,0, 0,1,0,0, 0,0,0,%.17g, 0,0,0,1]", scale.pivot(0).z());
  const Modelled listed =
      OperationList::parse("[{\"op\":\"transform\",\"vertices\":[4,5,6,7],\"matrix\":" + std::string(matrix) + "}]",
                           "ops.json")
          .apply(cube);
  const CovarianceMesh& edited = document.mesh();
  ASSERT_EQ(edited.n_vertices(), listed.mesh.n_vertices());
  for (size_t v = 0; v < edited.n_vertices(); ++v) {
    EXPECT_EQ(edited.mean(v), listed.mesh.mean(v)) << v;
    EXPECT_EQ(edited.covariance(v), listed.mesh.covariance(v)) << v;
  }
  EXPECT_EQ(arrays_of(edited).faces, arrays_of(listed.mesh).faces);
  for (int v : top) {
    EXPECT_EQ(edited.mean(size_t(v)).z(), 1.125) << v;
    EXPECT_TRUE(covariance_problem(edited.covariance(size_t(v))).empty()) << v;
  }
}

}  // namespace
}  // namespace gps
