#include "render/device_memory.h"

#include <glad/gl.h>
#include <unistd.h>

#include <cstring>

#include "render/gl_context.h"

namespace gps {
namespace {

bool has_extension(const char* name) {
  GLint n = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &n);
  for (GLint i = 0; i < n; ++i) {
    const auto* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
    if (e && std::strcmp(e, name) == 0) return true;
  }
  return false;
}

// The extensions' tokens (glad generates the core profile only).
constexpr GLenum kDedicatedVideoMemoryNvx = 0x9047;  // GL_GPU_MEMORY_INFO_DEDICATED_VIDMEM_NVX, KiB
constexpr GLenum kVboFreeMemoryAti = 0x87FB;         // GL_VBO_FREE_MEMORY_ATI, KiB in [0]

}  // namespace

long long device_memory_bytes() {
  if (software_renderer()) {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? (long long)pages * page : 0;
  }
  GLint kib[4] = {0, 0, 0, 0};
  if (has_extension("GL_NVX_gpu_memory_info")) glGetIntegerv(kDedicatedVideoMemoryNvx, kib);
  else if (has_extension("GL_ATI_meminfo")) glGetIntegerv(kVboFreeMemoryAti, kib);
  return (long long)kib[0] << 10;
}

}  // namespace gps
