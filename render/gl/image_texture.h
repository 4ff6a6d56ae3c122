#pragma once
// An image as a GL texture, for the shaders that sample one (the MatCap).
#include "render/gl/gl_object.h"
#include "render/image/image.h"

namespace gps {

/// `image` as an immutable RGBA32F 2D texture, linear filtering, clamped at the edges. Texture rows
/// run bottom-up, so the image's top row is v = 1; a grey image fills red, green and blue alike and
/// alpha is 1. Needs a current GL context.
GlTexture image_texture(const Image& image);

}  // namespace gps
