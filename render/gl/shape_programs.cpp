#include "render/gl/shape_programs.h"

#include <glad/gl.h>

#include <utility>

#include "shaders/embedded_shaders.h"

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

ShapePrograms::Build plan_compute_programs(std::string name, bool loop_evaluation, std::vector<const char*> sources,
                                           const char* defines) {
  return [name = std::move(name), loop_evaluation, sources = std::move(sources), defines](PatchShape shape,
                                                                                          PointPrecision precision) {
    const bool triangles = shape == PatchShape::triangle;
    std::vector<const char*> all = {defines, shaders::gpu_layout, shaders::patch_basis, shaders::plan_eval};
    if (triangles) all.insert(all.begin(), "#define GPS_TRIANGLE_PATCHES\n");
    if (triangles && loop_evaluation) all.push_back(shaders::loop_eval);
    all.push_back(shaders::canonical_edge);
    all.insert(all.end(), sources.begin(), sources.end());
    return ShaderProgram(triangles ? name + "_triangles" : name, at_precision({{GL_COMPUTE_SHADER, all}}, precision));
  };
}

}  // namespace gps
