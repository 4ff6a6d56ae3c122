#include "render/gl/image_texture.h"

#include <glad/gl.h>

#include <algorithm>
#include <vector>

#include "render/gl/gl_context.h"

namespace gps {

GlTexture image_texture(const Image& m) {
  GlTexture texture(GL_TEXTURE_2D);
  glTextureStorage2D(texture, 1, GL_RGBA32F, m.width, m.height);
  std::vector<float> rgba(size_t(m.width) * size_t(m.height) * 4, 1.0f);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      for (int c = 0; c < 3; ++c)
        rgba[(size_t(m.height - 1 - y) * size_t(m.width) + size_t(x)) * 4 + size_t(c)] =
            m.at(x, y, std::min(c, m.channels - 1));
  glTextureSubImage2D(texture, 0, 0, 0, m.width, m.height, GL_RGBA, GL_FLOAT, rgba.data());
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  check_gl_errors("uploading a texture");
  return texture;
}

}  // namespace gps
