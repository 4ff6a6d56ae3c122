#include "core/modelling/primitives.h"

#include <cmath>
#include <sstream>

#include "core/modelling/shapes.h"
#include "core/support/error.h"

namespace gps {

namespace {

// A 2×2 grid of quads on y = 0, facing +y.
Shape plane() {
  Shape s;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) s.points.emplace_back(-0.5 + 0.5 * i, 0, -0.5 + 0.5 * j);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const int v = 3 * i + j;
      s.faces.push_back({v, v + 1, v + 4, v + 3});  // z then x: normal +y
    }
  return s;
}

// The shape scaled about the origin.
Shape scaled(Shape s, double factor) {
  for (Vec3& p : s.points) p *= factor;
  return s;
}

// Ring radius and tube radius in the ratio of the torus sample, outer diameter 1.
Shape torus() {
  const double tube = 0.5 * 0.7 / 2.7;
  return torus_shape(8, 6, 0.5 - tube, tube);
}

// The primitive of extent 1, centred at the origin.
Shape shape_of(Primitive p) {
  switch (p) {
    case Primitive::plane:
      return plane();
    case Primitive::cube:
      return scaled(cube_shape(), 0.5);
    case Primitive::cylinder:
      return cylinder_shape(8, 2, 0.5, -0.5, 1.0);
    case Primitive::cone:
      return cone_shape(8, 0.5, 0.5, -0.5, true);
    case Primitive::sphere:
      return scaled(cube_sphere_shape(2), 0.5);
    case Primitive::torus:
      return torus();
  }
  throw Error("unknown primitive");
}

double mean_edge_length(const Shape& s) {
  double total = 0;
  int count = 0;
  for (const auto& face : s.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      total += (s.points[size_t(face[(k + 1) % face.size()])] - s.points[size_t(face[k])]).norm();
      ++count;
    }
  return total / count;  // each interior edge counted from both sides alike
}

}  // namespace

std::vector<std::string> primitive_names() { return {"plane", "cube", "cylinder", "cone", "sphere", "torus"}; }

std::optional<Primitive> primitive_named(const std::string& name) {
  const std::vector<std::string> names = primitive_names();
  for (size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return Primitive(k);
  return std::nullopt;
}

std::vector<int> append_primitive(MeshArrays& a, Primitive primitive, const Vec3& center, double size,
                                  std::string& summary) {
  if (!(size > 0) || !std::isfinite(size)) {
    std::ostringstream s;
    s << size;
    throw Error("the size must be positive and finite (got " + s.str() + ")");
  }
  if (!center.allFinite()) throw Error("the centre must be finite");
  const Shape s = shape_of(primitive);
  const double sigma = 0.5 * size * mean_edge_length(s);
  const int offset = a.n_vertices();
  std::vector<int> added;
  for (const Vec3& p : s.points) added.push_back(a.add_vertex({center + size * p, sigma * sigma * Mat3::Identity()}));
  check_gaussians(a, added);  // the first of the mesh's vertices with a problem is a new one
  for (auto face : s.faces) {
    for (int& v : face) v += offset;
    a.faces.push_back(std::move(face));
  }
  summary = "added a " + primitive_names()[size_t(primitive)] + ": " + std::to_string(s.points.size()) + " vertices, " +
            std::to_string(s.faces.size()) + " faces";
  return added;
}

Modelled add_primitive(const CovarianceMesh& mesh, Primitive primitive, const Vec3& center, double size) {
  return modelled_by(
      mesh, [&](MeshArrays& a, std::string& summary) { return append_primitive(a, primitive, center, size, summary); });
}

PrimitivePlacement primitive_placement(const CovarianceMesh& mesh, const std::vector<int>& selected) {
  if (mesh.n_vertices() == 0) return {Vec3::Zero(), 2.0};
  Vec3 lo = mesh.mean(0), hi = lo;
  for (size_t v = 1; v < mesh.n_vertices(); ++v) {
    lo = lo.cwiseMin(mesh.mean(v));
    hi = hi.cwiseMax(mesh.mean(v));
  }
  const double diagonal = (hi - lo).norm(), extent = (hi - lo).maxCoeff();
  if (!(extent > 0)) return {lo, 2.0};  // a single point
  if (!selected.empty()) {
    Vec3 sum = Vec3::Zero();
    for (const int v : selected) sum += mesh.mean(size_t(v));
    return {sum / double(selected.size()), 0.25 * diagonal};
  }
  const double size = 0.5 * extent;
  return {Vec3(hi.x() + 0.25 * extent + 0.5 * size, 0.5 * (lo.y() + hi.y()), 0.5 * (lo.z() + hi.z())), size};
}

}  // namespace gps
