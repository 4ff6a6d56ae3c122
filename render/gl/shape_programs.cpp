#include "render/gl/shape_programs.h"

#include <utility>

namespace gps {

ShapePrograms::ShapePrograms(Build build) : build_(std::move(build)) {}

ShaderProgram& ShapePrograms::slot(PatchShape shape, PointPrecision precision) const {
  return programs_[int(precision)][shape == PatchShape::triangle ? 1 : 0];
}

void ShapePrograms::set_precision(PointPrecision precision, bool check) {
  ShaderProgram& quads = slot(PatchShape::quad, precision);
  if (check && quads.id() == 0 && slot(PatchShape::triangle, precision).id() == 0)
    quads = build_(PatchShape::quad, precision);
  precision_ = precision;
}

const ShaderProgram& ShapePrograms::operator()(PatchShape shape) const {
  ShaderProgram& program = slot(shape, precision_);
  if (program.id() == 0) program = build_(shape, precision_);
  return program;
}

bool ShapePrograms::built(PatchShape shape) const { return slot(shape, precision_).id() != 0; }

}  // namespace gps
