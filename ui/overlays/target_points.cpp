#include "ui/overlays/target_points.h"

#include <new>

#include "core/io/mesh_io.h"
#include "core/support/error.h"

namespace gps {

TargetPoints::~TargetPoints() {
  if (task_.valid()) task_.wait();
}

void TargetPoints::load(const std::string& path) {
  ++generation_;
  pending_path_ = path;
}

void TargetPoints::clear() {
  ++generation_;
  pending_path_.reset();
  points_.reset();
  path_.clear();
  distances_.clear();
  summary_ = {};
  dirty_ = false;
}

void TargetPoints::surface_changed(Clock::time_point now) {
  dirty_ = true;
  changed_at_ = now;
}

TargetPoints::Measured TargetPoints::measure(const CovarianceMesh& surface, const PlanOptions& plans,
                                             const std::vector<Vec3>& points) {
  Measured m;
  const LimitTriangles limit = limit_surface_triangles(surface, kLevel, plans, kMaxTriangles);
  const std::vector<double> d = SurfaceDistance(limit.triangles).distances(points);
  m.distances.assign(d.begin(), d.end());
  const double diagonal = bounding_box_diagonal(points);
  m.summary = summarise_distances(d, diagonal > 0 ? diagonal : 1.0);
  return m;
}

TargetPoints::Taken TargetPoints::poll(Clock::time_point now,
                                       const std::function<std::shared_ptr<const CovarianceMesh>()>& surface,
                                       const PlanOptions& plans) {
  Taken taken;
  if (task_.valid() && task_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
    Measured m = task_.get();
    if (m.generation != generation_) {
      // Of a target since replaced or forgotten.
    } else if (!m.error.empty()) {
      taken.error = m.error;
    } else {
      if (m.points) {
        points_ = std::move(m.points);
        path_ = std::move(m.path);
        taken.points = true;
      }
      distances_ = std::move(m.distances);
      summary_ = m.summary;
      taken.distances = true;
    }
  }
  if (task_.valid()) return taken;
  const bool settled = dirty_ && now - changed_at_ >= kSettle;
  if (!pending_path_ && !(points_ && settled)) return taken;
  std::shared_ptr<const CovarianceMesh> mesh = surface();
  const std::optional<std::string> path = std::exchange(pending_path_, std::nullopt);
  dirty_ = false;
  task_ = std::async(std::launch::async, [mesh = std::move(mesh), plans, path, points = points_,
                                          generation = generation_]() {
    Measured m;
    try {
      if (path) {
        bool has_covariances = false;
        auto read = std::make_shared<const std::vector<Vec3>>(read_polygon_soup(*path, has_covariances).positions);
        if (read->empty()) throw Error(*path + ": has no points to show");
        m = measure(*mesh, plans, *read);
        m.points = std::move(read);
        m.path = *path;
      } else {
        m = measure(*mesh, plans, *points);
      }
    } catch (const Error& e) {
      m.error = e.what();
    } catch (const std::bad_alloc&) {
      m.error = (path ? *path + ": " : std::string()) + "out of memory measuring the target's distances";
    } catch (const std::exception& e) {
      m.error = e.what();
    }
    m.generation = generation;
    return m;
  });
  return taken;
}

}  // namespace gps
