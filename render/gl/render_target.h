#pragma once
// An off-screen framebuffer: colour (RGBA8) plus world position and normal AOVs (RGBA32F) and depth.
#include <array>
#include <cstdint>

#include "render/gl/gl_object.h"
#include "render/image/image.h"

namespace gps {

class RenderTarget {
public:
  /// The largest width and height a target is made with.
  static constexpr int kLargestSide = 16384;

  RenderTarget(int width, int height);
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  unsigned framebuffer() const { return fbo_; }
  /// Unique in the process: a target made where another was is not taken for it.
  std::uint64_t serial() const { return serial_; }
  /// Binds it for drawing, with all three outputs, and sets the viewport.
  void bind() const;
  /// Whether draws write the colour alone (overlays: their shaders leave the position and normal
  /// outputs undefined, which would then read as surface) or all three outputs.
  void set_colour_only(bool colour_only) const;
  /// Attachment 0 as RGBA in [0,1]; 1 (position) and 2 (normal) as xyz + coverage (w ≥ 1 where drawn;
  /// the normal's w is 2 where a regular plan node was evaluated, 3 where a terminal one).
  Image read(int attachment) const;
  /// The texture of attachment 0, 1 or 2.
  unsigned texture(int attachment) const { return textures_[size_t(attachment)]; }

private:
  int width_, height_;
  std::uint64_t serial_;
  GlFramebuffer fbo_;
  std::array<GlTexture, 3> textures_;  // colour, position, normal
  GlRenderbuffer depth_;
};

}  // namespace gps
