#include "ui/editing/edit_reach.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/edit/covariance_edit.h"
#include "ui/document/editor_document.h"

namespace gps {

namespace {

// Points hashed into cubic cells of a given size: the points near a query point in 27 cells.
class PointGrid {
public:
  PointGrid(double cell, const std::vector<Vec3>& means, const std::vector<int>& indices) : cell_(cell) {
    for (const int i : indices) cells_[key(cell_of(means[size_t(i)]))].push_back(i);
  }
  template <typename Visit>
  void near(const Vec3& p, Visit visit) const {
    const Eigen::Vector3i c = cell_of(p);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it != cells_.end())
            for (const int i : it->second) visit(i);
        }
  }

private:
  Eigen::Vector3i cell_of(const Vec3& p) const { return (p / cell_).array().floor().cast<int>(); }
  static long long key(const Eigen::Vector3i& c) {
    return (static_cast<long long>(c.x()) * 73856093LL) ^ (static_cast<long long>(c.y()) * 19349663LL) ^
           (static_cast<long long>(c.z()) * 83492791LL);
  }
  double cell_;
  std::unordered_map<long long, std::vector<int>> cells_;
};

}  // namespace

double falloff_weight(Falloff falloff, double t) {
  t = std::clamp(t, 0.0, 1.0);
  switch (falloff) {
    case Falloff::smooth:
      return 1.0 - t * t * (3.0 - 2.0 * t);
    case Falloff::linear:
      return 1.0 - t;
    case Falloff::sharp:
      return (1.0 - t) * (1.0 - t);
    case Falloff::constant:
      return 1.0;
  }
  return 0.0;
}

std::vector<ReachedVertex> edit_reach(const std::vector<Vec3>& means, const std::vector<int>& selected,
                                      const ReachOptions& options, const std::vector<char>* hidden) {
  std::vector<ReachedVertex> reach;
  std::vector<char> reached(means.size(), 0);  // or hidden: never reached
  if (hidden)
    for (size_t v = 0; v < std::min(means.size(), hidden->size()); ++v) reached[v] = (*hidden)[v];
  for (size_t s = 0; s < selected.size(); ++s) {
    reach.push_back({selected[s], 1.0, s, false});
    reached[size_t(selected[s])] = 1;
  }
  if (options.proportional && options.radius > 0 && !selected.empty()) {
    std::vector<int> order(selected.size());
    for (size_t s = 0; s < selected.size(); ++s) order[s] = int(s);
    std::vector<Vec3> selected_means;
    for (const int v : selected) selected_means.push_back(means[size_t(v)]);
    const PointGrid grid(options.radius, selected_means, order);
    for (size_t v = 0; v < means.size(); ++v) {
      if (reached[v]) continue;
      double nearest = options.radius;
      int source = -1;
      grid.near(means[v], [&](int s) {
        const double d = (means[v] - selected_means[size_t(s)]).norm();
        if (d < nearest) nearest = d, source = s;
      });
      if (source < 0) continue;
      const double w = falloff_weight(options.falloff, nearest / options.radius);
      if (w <= 0) continue;
      reach.push_back({int(v), w, size_t(source), false});
      reached[v] = 1;
    }
  }
  if (options.mirror) {
    std::vector<int> all(means.size());
    for (size_t v = 0; v < means.size(); ++v) all[v] = int(v);
    const double tolerance = std::max(options.mirror_tolerance, 1e-12);
    const PointGrid grid(tolerance, means, all);
    const size_t n = reach.size();
    for (size_t r = 0; r < n; ++r) {
      Vec3 image = means[size_t(reach[r].vertex)];
      image[options.mirror_axis] = -image[options.mirror_axis];
      int partner = -1;
      double best = tolerance;
      grid.near(image, [&](int i) {
        const double d = (means[size_t(i)] - image).norm();
        if (d <= best) best = d, partner = i;
      });
      if (partner < 0 || reached[size_t(partner)]) continue;  // on the mirror plane, or edited itself
      reach.push_back({partner, reach[r].weight, reach[r].source, true});
      reached[size_t(partner)] = 1;
    }
  }
  return reach;
}

void apply_reach(EditorDocument& document, const std::vector<ReachedVertex>& reach,
                 const std::vector<GaussianChange>& changes, int mirror_axis) {
  for (const ReachedVertex& r : reach) {
    GaussianChange change = r.weight == 1.0 ? changes[r.source] : changes[r.source].weighted(r.weight);
    if (r.mirrored) change = change.mirrored(mirror_axis);
    const Mat3& start = document.start_covariance(r.vertex);
    document.set_mean(r.vertex, change.apply_to_mean(document.start_mean(r.vertex)));
    if (change.keeps_covariance()) {
      document.set_covariance(r.vertex, start);
    } else {
      const Mat3 edited = change.apply_to_covariance(start);
      document.set_covariance(r.vertex, is_spd(edited) ? edited : clamp_spd(edited, start));
    }
  }
}

}  // namespace gps
