#include "ui/display/target_points_layer.h"

#include <filesystem>

namespace gps {

namespace {

/// The ramp's end where no maximum was chosen: the 99th percentile, else the largest distance, else
/// a millionth of the points' size (all on the surface).
double automatic_max_distance(const DistanceSummary& d) {
  if (d.percentile_99 > 0.0) return d.percentile_99;
  if (d.max > 0.0) return d.max;
  return 1e-6 * d.length;
}

}  // namespace

TargetPointsLayer::TargetPointsLayer() : overlay_(std::make_unique<PointOverlay>()) {}

TargetPointsLayer::Report TargetPointsLayer::update(const ShownSurface& shown, const CovarianceMesh& document,
                                                    const PlanOptions& plans, TargetPointsView& view,
                                                    Clock::time_point now) {
  if (shown.changed_since(seen_)) points_.surface_changed(now);
  const NormalisedFrame& frame = shown.renderer().frame();
  // Hidden, nothing is measured; shown again, the changes missed meanwhile are.
  const TargetPoints::Taken taken =
      !view.shown ? TargetPoints::Taken{}
                  : points_.poll(
                        now,
                        [&]() -> std::shared_ptr<const CovarianceMesh> {
                          if (shown.preview())
                            return shown.preview();  // a modal tool's preview (a crease's sharpness, a bevel)
                          return std::make_shared<const CovarianceMesh>(document);
                        },
                        plans);
  if (taken.points) {
    overlay_->set_points(points_.points(), frame);
  } else if (!points_.loaded()) {
    if (overlay_->count() > 0) overlay_->set_points({}, frame);  // forgotten
  } else if (overlay_->frame() != frame) {
    overlay_->set_frame(points_.points(), frame);  // the surface's frame moved
  }
  if (taken.distances) overlay_->set_distances(points_.distances());
  view.name = points_.loaded() ? std::filesystem::path(points_.path()).filename().string() : "";
  view.count = points_.loaded() ? points_.points().size() : 0;
  view.measuring = points_.busy();
  const DistanceSummary& d = points_.summary();
  view.rms = d.rms, view.percentile_99 = d.percentile_99, view.largest = d.max, view.length = d.length;
  if (view.automatic || !(view.max_distance > 0.0f)) view.max_distance = float(automatic_max_distance(d));
  return {taken.points, taken.error};
}

bool TargetPointsLayer::draws(const TargetPointsView& view) const { return view.shown && overlay_->count() > 0; }

void TargetPointsLayer::draw(const RenderTarget& target, const Camera& camera, const TargetPointsView& view) const {
  if (!draws(view)) return;
  PointOverlay::Style style;
  style.max_distance = view.max_distance;
  style.point_size = view.point_size;
  overlay_->draw(target, camera, style);
}

}  // namespace gps
