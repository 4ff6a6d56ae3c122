#pragma once
// The dense target shown as points over the surface (File → Show target points…, and after Fit to…):
// its file read, and every point's distance from the limit surface shown measured, on a thread of its
// own (core/fitting/surface_distance.h). After a change of the surface the distances are measured
// again once it has stayed for a moment (not for every frame of a drag); until then the old ones stay.
#include <chrono>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/fitting/surface_distance.h"
#include "core/mesh/covariance_mesh.h"
#include "core/plans/planned_surface.h"

namespace gps {

class TargetPoints {
public:
  using Clock = std::chrono::steady_clock;
  /// How long the surface stays unchanged before it is measured again.
  static constexpr std::chrono::milliseconds kSettle{150};
  /// The tessellation measured against: the level of every patch, lowered while it has more triangles.
  static constexpr int kLevel = 6;
  static constexpr double kMaxTriangles = 3e5;

  TargetPoints() = default;
  ~TargetPoints();  // waits for a measurement still running
  TargetPoints(const TargetPoints&) = delete;
  TargetPoints& operator=(const TargetPoints&) = delete;

  /// Reads the points of `path` (the vertices of any mesh file the editor opens; faces, where it has
  /// any, are not needed) and measures them, in the background. A target shown stays until it is read.
  void load(const std::string& path);
  /// Forgets the target (and drops what the background is doing for it).
  void clear();
  /// The surface changed at `now`: measured again once it has stayed for kSettle.
  void surface_changed(Clock::time_point now);

  /// What a poll() took from the background.
  struct Taken {
    bool points = false;     // a new target's points (with their distances)
    bool distances = false;  // new distances
    std::string error;       // a file that did not read, or a surface that could not be measured
  };
  /// Once a frame: takes what the background finished and starts what is due. `surface` gives the
  /// mesh shown (called only when a measurement starts); `plans` how its limit surface is planned.
  Taken poll(Clock::time_point now, const std::function<std::shared_ptr<const CovarianceMesh>()>& surface,
             const PlanOptions& plans);

  bool loaded() const { return points_ != nullptr; }
  /// Reading or measuring, or a measurement due: a replay waits for it.
  bool busy() const { return task_.valid() || pending_path_ || (points_ && dirty_); }
  /// Whether the distances held are of the surface as it is now.
  bool current() const { return loaded() && !busy(); }
  const std::string& path() const { return path_; }
  const std::vector<Vec3>& points() const { return *points_; }
  /// Each point's distance from the surface (world units), in the points' order.
  const std::vector<float>& distances() const { return distances_; }
  /// Their rms, 99th percentile and maximum, relative to the points' bounding-box diagonal.
  const DistanceSummary& summary() const { return summary_; }

private:
  struct Measured {
    long long generation = 0;
    std::string path;                                // of a load
    std::shared_ptr<const std::vector<Vec3>> points;  // set by a load
    std::vector<float> distances;
    DistanceSummary summary;
    std::string error;
  };
  static Measured measure(const CovarianceMesh& surface, const PlanOptions& plans,
                          const std::vector<Vec3>& points);

  std::shared_ptr<const std::vector<Vec3>> points_;
  std::string path_;
  std::vector<float> distances_;
  DistanceSummary summary_;
  std::optional<std::string> pending_path_;  // a load asked for, not yet started
  bool dirty_ = false;                       // the surface changed since the last measurement started
  Clock::time_point changed_at_{};
  long long generation_ = 0;  // bumped by load() and clear(): older results are dropped
  std::future<Measured> task_;
};

}  // namespace gps
