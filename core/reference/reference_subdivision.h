#pragma once
// The exact CPU reference: iterative GPS subdivision with limit projection (docs/design.md §2).
// Gaussians go to 9D once (thesis Eq. 2.10), a linear scheme refines them, and they come back once.
#include <vector>

#include "core/mesh/covariance_mesh.h"
#include "core/reference/loop.h"
#include "core/reference/patch_param.h"

namespace gps {

enum class Scheme { catmull_clark, loop };

struct SubdivisionOptions {
  Scheme scheme = Scheme::catmull_clark;
  int levels = 1;  // 0..8
  bool limit = false;
  LoopBeta loop_beta = LoopBeta::loop;
  bool normals = false;  // with limit: the exact limit normals and the corners' params too (for drawing)
};

struct SubdivisionResult {
  CovarianceMesh mesh;
  /// For each output vertex, one (patch, u, v) where it lies: Catmull-Clark in the input mesh's patch
  /// layout (core/plans/patch_layout.h), Loop in its triangle patches (core/plans/loop_plan_builder.h).
  std::vector<PatchParam> vertex_params;
  /// With options.normals, the same for each face corner, in face order: the corners of one face
  /// share its patch.
  std::vector<PatchParam> corner_params;
  /// With options.normals: the unit limit normal at each vertex, zero where it has no tangent masks
  /// and on creases and sharp corners, where the surface has a normal on each side.
  std::vector<Vec3> normals;
};

/// N levels of GPS subdivision (map to 9D, linear scheme, optional exact limit projection, map back).
/// The mesh's sharpness applies by OpenSubdiv's crease rules (core/reference/crease_rules.h); the
/// result carries what is left of it after the N levels.
SubdivisionResult subdivide(const CovarianceMesh& mesh, const SubdivisionOptions& options);

/// The same scheme applied to the means alone (the ordinary linear surface, for comparison).
std::vector<Vec3> subdivide_points(const CovarianceMesh& mesh, const SubdivisionOptions& options);

}  // namespace gps
