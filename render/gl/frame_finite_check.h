#pragma once
// The pixels of a frame whose position or normal is not finite, counted on the GPU (a compute pass
// over the render target's float attachments) and read back as one number: the editor checks every
// frame that settles after a change, where reading both images back stalled the frame.
#include "render/gl/gl_object.h"
#include "render/gl/render_target.h"
#include "render/gl/shader_program.h"

namespace gps {

class FrameFiniteCheck {
public:
  /// Needs a current GL 4.5 context.
  FrameFiniteCheck();
  FrameFiniteCheck(const FrameFiniteCheck&) = delete;
  FrameFiniteCheck& operator=(const FrameFiniteCheck&) = delete;

  /// What count_non_finite_pixels(target.read(1), target.read(2)) counts (render/image/non_finite_pixels.h).
  long long non_finite_pixels(const RenderTarget& target) const;

private:
  ShaderProgram program_;
  GlBuffer count_;
};

}  // namespace gps
