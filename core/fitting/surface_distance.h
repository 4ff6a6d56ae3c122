#pragma once
// Distances from points to a surface: how far a mesh's points lie from another mesh's GPS limit
// surface, summarised as rms, 99th percentile and maximum.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/evaluation/triangle_mesh.h"
#include "core/mesh/covariance_mesh.h"
#include "core/plans/planned_surface.h"

namespace gps {

/// A limit surface as dense triangles, and the tessellation level that made them.
struct LimitTriangles {
  TriangleMesh triangles;
  int level = 0;
};

/// Triangles a measured surface is kept to unless asked otherwise: with the AABB tree and its search
/// tree over them, each holds a few hundred bytes.
inline constexpr double kMeasuredTriangles = 2e6;

/// The limit surface of `mesh` as a dense triangle mesh: every patch tessellated at `level`
/// (core/evaluation/tessellator.h), or at the highest lower level (down to 1) whose tessellation
/// has at most `max_triangles`. Throws gps::Error if the surface cannot be evaluated.
LimitTriangles limit_surface_triangles(const CovarianceMesh& mesh, int level, const PlanOptions& options = {},
                                       double max_triangles = INFINITY);

/// Exact distances from points to a triangle mesh, through an AABB tree of its triangles (CGAL), and
/// the surface's normal at the nearest point.
class SurfaceDistance {
public:
  /// Throws gps::Error if `surface` has no triangles. `surface` must outlive the object where
  /// normal_angles is called.
  explicit SurfaceDistance(const TriangleMesh& surface);
  ~SurfaceDistance();
  SurfaceDistance(const SurfaceDistance&) = delete;
  SurfaceDistance& operator=(const SurfaceDistance&) = delete;

  /// The distance from `point` to the nearest point of the surface.
  double distance(const Vec3& point) const;
  /// The distance of every point, in order (on all cores).
  std::vector<double> distances(const std::vector<Vec3>& points) const;
  /// The surface's unit normal at the point nearest `point`: its vertex normals interpolated there
  /// (barycentric), or the triangle's own where it has none.
  Vec3 normal_nearest(const Vec3& point) const;
  /// For each point with a non-zero normal, the angle in degrees between its normal and the surface's
  /// at its nearest point, taken as lines (0° to 90°: a scan's faces may be turned either way).
  std::vector<double> normal_angles(const std::vector<Vec3>& points, const std::vector<Vec3>& normals) const;

private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
  const TriangleMesh& surface_;
};

/// A set of distances in absolute units and relative to a length (the points' bounding-box diagonal).
struct DistanceSummary {
  size_t count = 0;
  double rms = 0, percentile_99 = 0, max = 0;
  double length = 1;  // what the relative figures divide by; 0: points that span no length, NaN figures
  double relative_rms() const { return relative(rms); }
  double relative_percentile_99() const { return relative(percentile_99); }
  double relative_max() const { return relative(max); }
  double relative(double distance) const { return length > 0 ? distance / length : std::nan(""); }
};

/// Three lines (rms, 99th percentile, max), each the distance and its ratio to the length (none where
/// the length is 0).
std::string describe(const DistanceSummary& summary);

/// rms, 99th percentile (nearest rank) and maximum of `distances`, relative to `length` (0: none).
DistanceSummary summarise_distances(std::vector<double> distances, double length);

/// Axis-aligned bounding-box diagonal of points (0 for none).
double bounding_box_diagonal(const std::vector<Vec3>& points);

/// The means of a covariance mesh, its points as a point set.
std::vector<Vec3> vertex_means(const CovarianceMesh& mesh);

/// Distances from `points` to `surface`, summarised relative to the points' bounding-box diagonal
/// (or 1 where the points are one).
DistanceSummary distances_to_surface(const std::vector<Vec3>& points, const TriangleMesh& surface);

/// Angles between normals (SurfaceDistance::normal_angles), summarised: how many, their rms and max.
struct AngleSummary {
  size_t count = 0;
  size_t left_out = 0;      // points measured without a normal (on a sharp edge or corner, or on no face)
  double rms = 0, max = 0;  // degrees
};
/// `points`: how many points were measured in all (0: as many as have an angle).
AngleSummary summarise_angles(const std::vector<double>& degrees, size_t points = 0);
/// "normals: rms angle 4.2° (max 31°) over 1200 points", with how many were left out, or that no
/// point has a normal.
std::string describe(const AngleSummary& summary);

}  // namespace gps
