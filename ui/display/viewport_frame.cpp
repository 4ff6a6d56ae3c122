#include "ui/display/viewport_frame.h"

namespace gps {

long long ViewportFrame::draw(ShownSurface& shown, const TargetPointsLayer& points, const Camera& camera,
                              const DrawOptions& options, const TargetPointsView& view, int width, int height,
                              bool settled) {
  if (!target_ || target_->width() != width || target_->height() != height) {
    target_.reset();
    target_ = std::make_unique<RenderTarget>(width, height);
  }
  SurfaceRenderer& renderer = shown.renderer();
  const bool target_points = points.draws(view);
  if (target_points || target_points_drawn_ || !renderer.draws_as_last(*target_, camera, options)) {
    renderer.draw(*target_, camera, options);
    points.draw(*target_, camera, view);
  } else {
    ++kept_frames_;
  }
  target_points_drawn_ = target_points;
  // Not on every frame of a drag: the count's read-back waits for the GPU.
  if (!settled || !shown.changed_since(finite_seen_)) return 0;
  if (!finite_check_) finite_check_ = std::make_unique<FrameFiniteCheck>();
  return finite_check_->non_finite_pixels(*target_);
}

}  // namespace gps
