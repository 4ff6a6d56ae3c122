#include "core/evaluation/surface_samples.h"
#include "core/fitting/surface_distance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "core/evaluation/tessellation_size.h"
#include "core/fitting/distance_tree_size.h"
#include "core/evaluation/tessellator.h"
#include "core/support/error.h"

namespace gps {

LimitTriangles limit_surface_triangles(const CovarianceMesh& mesh, int level, const PlanOptions& options,
                                       double max_triangles) {
  const PlannedSurface surface(mesh, options);
  const PatchPlans& plans = surface.tables().plans;
  while (level > 1 && tessellation_size(plans, level).faces > max_triangles) --level;
  // What measuring to the triangles holds besides them is sized with them, before either is made.
  OutputSize size = tessellation_size(plans, level);
  size.bytes += distance_tree_bytes(size.faces);
  check_output_size(size,
                    "measuring distances to " + std::to_string(plans.n_patches()) + " patches tessellated at level " +
                        std::to_string(level),
                    "triangles", "use a lower level");
  return {tessellate(surface, level), level};
}

struct SurfaceDistance::Tree {
  using Kernel = CGAL::Simple_cartesian<double>;
  using Triangle = Kernel::Triangle_3;
  using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
  using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

  std::vector<Triangle> triangles;
  AabbTree tree;
};

SurfaceDistance::SurfaceDistance(const TriangleMesh& surface) : tree_(std::make_unique<Tree>()), surface_(surface) {
  if (surface.triangles.empty()) throw Error("the surface to measure distances to has no triangles");
  const auto point = [&](int i) {
    const Vec3& p = surface.positions[size_t(i)];
    return Tree::Kernel::Point_3(p[0], p[1], p[2]);
  };
  tree_->triangles.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles) tree_->triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
  // The search tree of distance queries is built here, once, so that queries may run in parallel.
  tree_->tree.accelerate_distance_queries();
  distance(surface.positions.front());
}

SurfaceDistance::~SurfaceDistance() = default;

double SurfaceDistance::distance(const Vec3& point) const {
  return std::sqrt(tree_->tree.squared_distance(Tree::Kernel::Point_3(point[0], point[1], point[2])));
}

std::vector<double> SurfaceDistance::distances(const std::vector<Vec3>& points) const {
  std::vector<double> d(points.size());
  const long n = long(points.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < n; ++i) d[size_t(i)] = distance(points[size_t(i)]);
  return d;
}

Vec3 SurfaceDistance::normal_nearest(const Vec3& point) const {
  const auto [nearest, primitive] =
      tree_->tree.closest_point_and_primitive(Tree::Kernel::Point_3(point[0], point[1], point[2]));
  const auto& t = surface_.triangles[size_t(primitive - tree_->triangles.cbegin())];
  const Vec3 a = surface_.positions[size_t(t[0])], b = surface_.positions[size_t(t[1])],
             c = surface_.positions[size_t(t[2])];
  const Vec3 own = (b - a).cross(c - a);
  if (surface_.normals.size() != surface_.positions.size()) return own.normalized();
  // Barycentric weights of the nearest point: the sub-triangles' areas over the whole's.
  const Vec3 x(nearest.x(), nearest.y(), nearest.z());
  const double area2 = own.squaredNorm();
  if (!(area2 > 0)) return surface_.normals[size_t(t[0])];
  const double wa = (b - x).cross(c - x).dot(own) / area2, wb = (c - x).cross(a - x).dot(own) / area2;
  const Vec3 n = wa * surface_.normals[size_t(t[0])] + wb * surface_.normals[size_t(t[1])] +
                 (1 - wa - wb) * surface_.normals[size_t(t[2])];
  return n.isZero(0.0) ? own.normalized() : n.normalized();
}

std::vector<double> SurfaceDistance::normal_angles(const std::vector<Vec3>& points,
                                                   const std::vector<Vec3>& normals) const {
  std::vector<long> with_normal;
  for (size_t i = 0; i < points.size() && i < normals.size(); ++i)
    if (!normals[i].isZero(0.0) && normals[i].allFinite()) with_normal.push_back(long(i));
  std::vector<double> angles(with_normal.size());
  const long n = long(with_normal.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (long j = 0; j < n; ++j) {
    const size_t i = size_t(with_normal[size_t(j)]);
    const Vec3 own = normals[i].normalized(), surface = normal_nearest(points[i]);
    angles[size_t(j)] = std::atan2(own.cross(surface).norm(), std::abs(own.dot(surface))) * 180.0 / M_PI;
  }
  return angles;
}

AngleSummary summarise_angles(const std::vector<double>& degrees, size_t points) {
  AngleSummary s;
  s.count = degrees.size();
  s.left_out = points > s.count ? points - s.count : 0;
  double sum = 0;
  for (const double d : degrees) {
    sum += d * d;
    s.max = std::max(s.max, d);
  }
  if (s.count) s.rms = std::sqrt(sum / double(s.count));
  return s;
}

std::string describe(const AngleSummary& s) {
  if (s.count == 0)
    return "normals: none to compare (no measured point has one: each lies on no face, or on a sharp edge or corner)\n";
  char text[240];
  const int n =
      std::snprintf(text, sizeof text, "normals: rms angle %.3g° (max %.3g°) over %zu points", s.rms, s.max, s.count);
  if (s.left_out > 0)
    std::snprintf(text + n, sizeof text - size_t(n),
                  " (%zu without a normal left out: on a sharp edge or corner, or on no face)", s.left_out);
  return std::string(text) + "\n";
}

DistanceSummary summarise_distances(std::vector<double> distances, double length) {
  DistanceSummary s;
  s.count = distances.size();
  s.length = length;
  if (distances.empty()) return s;
  double sum = 0;
  for (const double d : distances) sum += d * d;
  s.rms = std::sqrt(sum / double(distances.size()));
  // Nearest rank: the smallest distance that at least 99% of the distances do not exceed.
  const size_t rank = size_t(std::ceil(0.99 * double(distances.size())));
  std::nth_element(distances.begin(), distances.begin() + long(rank - 1), distances.end());
  s.percentile_99 = distances[rank - 1];
  s.max = *std::max_element(distances.begin() + long(rank - 1), distances.end());
  return s;
}

std::string describe(const DistanceSummary& s) {
  std::string out;
  const auto line = [&](const char* name, double distance) {
    char text[96];
    if (s.length > 0)
      std::snprintf(text, sizeof text, "%s %.6g (%.3e of the diagonal)\n", name, distance, s.relative(distance));
    else
      std::snprintf(text, sizeof text, "%s %.6g (the points measured span no length)\n", name, distance);
    out += text;
  };
  line("rms", s.rms);
  line("99th percentile", s.percentile_99);
  line("max", s.max);
  return out;
}

double bounding_box_diagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).norm();
}

std::vector<Vec3> vertex_means(const CovarianceMesh& mesh) { return mesh.means(); }

DistanceSummary distances_to_surface(const std::vector<Vec3>& points, const TriangleMesh& surface) {
  const double diagonal = bounding_box_diagonal(points);
  return summarise_distances(SurfaceDistance(surface).distances(points), diagonal);
}

}  // namespace gps
