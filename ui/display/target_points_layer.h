#pragma once
// A dense target (the file a fit went to, or any mesh or point file) drawn as points over the shown
// surface, coloured by their distance from it: read and measured in the background
// (ui/overlays/target_points.h), measured again after each change of the surface shown (its
// revision), and drawn in the renderer's frame (render/overlays/point_overlay.h).
#include <cstdint>
#include <memory>
#include <string>

#include "render/gl/render_target.h"
#include "render/overlays/point_overlay.h"
#include "ui/display/shown_surface.h"
#include "ui/overlays/target_points.h"
#include "ui/panels/view_options.h"
#include "view/camera.h"

namespace gps {

class TargetPointsLayer {
public:
  using Clock = TargetPoints::Clock;

  TargetPointsLayer();  // a current GL context needed

  TargetPoints& points() { return points_; }
  const TargetPoints& points() const { return points_; }

  /// What a frame's update has to say: a new target's points shown (the status says how many), or an
  /// error (a file that did not read, a surface that could not be measured); nothing else.
  struct Report {
    bool shown = false;
    std::string error;
  };
  /// Once a frame, before drawing: follows `shown` (measured against its preview, else `document`,
  /// planned under `plans`; nothing while `view.shown` is off, the changes missed meanwhile measured
  /// once it is on), and gives `view` the figures the View panel shows.
  Report update(const ShownSurface& shown, const CovarianceMesh& document, const PlanOptions& plans,
                TargetPointsView& view, Clock::time_point now);
  /// Over the surface already drawn into `target`, where shown.
  void draw(const RenderTarget& target, const Camera& camera, const TargetPointsView& view) const;
  /// Whether draw() draws anything for `view`.
  bool draws(const TargetPointsView& view) const;

private:
  TargetPoints points_;
  std::unique_ptr<PointOverlay> overlay_;
  std::uint64_t seen_ = 0;  // the shown surface's revision measured, or due
};

}  // namespace gps
