#pragma once
// One pass's shader programs per patch shape and point precision, each compiled the first time it is
// used: a mesh of quads never compiles the triangles' programs, nor one of triangles the quads', and
// double points compile theirs only once a mesh needs them.
#include <functional>
#include <string>
#include <vector>

#include "core/plans/patch_plans.h"
#include "render/gl/point_precision.h"
#include "render/gl/shader_program.h"

namespace gps {

class ShapePrograms {
public:
  /// The program of a shape at a precision (throws gps::Error where the driver refuses it).
  using Build = std::function<ShaderProgram(PatchShape shape, PointPrecision precision)>;
  explicit ShapePrograms(Build build);
  ShapePrograms(const ShapePrograms&) = delete;
  ShapePrograms& operator=(const ShapePrograms&) = delete;

  /// Uses `precision` from now on. Where `check` and no program of it is built yet, the quads' is
  /// built first, so that a precision the driver cannot compile is refused here, the previous one kept.
  void set_precision(PointPrecision precision, bool check = true);
  PointPrecision precision() const { return precision_; }
  /// The shape's program at the current precision, compiled now where it is not yet.
  const ShaderProgram& operator()(PatchShape shape) const;
  /// Whether the shape's program at the current precision is compiled.
  bool built(PatchShape shape) const;

private:
  ShaderProgram& slot(PatchShape shape, PointPrecision precision) const;

  Build build_;
  PointPrecision precision_ = PointPrecision::single_float;
  mutable ShaderProgram programs_[2][2];  // [precision][quads, triangles]
};

/// The Build of a compute pass over the plans' evaluation: `gpu_layout`, `patch_basis`, `plan_eval` and
/// `canonical_edge`, then the pass's own `sources`; for triangles with their define, Loop's evaluation
/// too where `loop_evaluation`, and named `name` + "_triangles". `defines` (lines of `#define`) come
/// first.
ShapePrograms::Build plan_compute_programs(std::string name, bool loop_evaluation, std::vector<const char*> sources,
                                           const char* defines = "");

}  // namespace gps
