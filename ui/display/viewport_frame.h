#pragma once
// The editor's 3D view, drawn each frame into an off-screen target the size of the window: the shown
// surface, then the target points over it. A frame that would draw what the target already holds
// (SurfaceRenderer::draws_as_last, no target points over it) keeps it, so that an idle editor draws
// only its UI. Once a change of the surface has settled, the frame's non-finite pixels are counted.
#include <cstdint>
#include <memory>

#include "render/gl/draw_options.h"
#include "render/gl/frame_finite_check.h"
#include "render/gl/render_target.h"
#include "ui/display/shown_surface.h"
#include "ui/display/target_points_layer.h"
#include "ui/panels/view_options.h"
#include "view/camera.h"

namespace gps {

class ViewportFrame {
public:
  ViewportFrame() = default;  // a current GL context needed from the first draw on

  /// Draws `shown` under `camera` and `options`, then the target points of `points` as `view` asks,
  /// into the target, made anew at width × height where it is of another size; or keeps the target
  /// where it holds that frame already. `settled` (no edit this frame): where the shown surface
  /// changed since the last count, counts the frame's non-finite pixels. Returns that count (0 where
  /// none, or not counted).
  long long draw(ShownSurface& shown, const TargetPointsLayer& points, const Camera& camera, const DrawOptions& options,
                 const TargetPointsView& view, int width, int height, bool settled);

  /// The target as the last draw left it; nullptr before the first.
  const RenderTarget* target() const { return target_.get(); }
  /// The frames that kept the target, drawing nothing into it.
  long long kept_frames() const { return kept_frames_; }

private:
  std::unique_ptr<RenderTarget> target_;
  std::unique_ptr<FrameFiniteCheck> finite_check_;
  std::uint64_t finite_seen_ = 0;  // the shown surface's revision last counted
  long long kept_frames_ = 0;
  bool target_points_drawn_ = false;  // over the target's surface by the last frame
};

}  // namespace gps
