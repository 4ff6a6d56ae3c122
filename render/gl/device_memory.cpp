#include "render/gl/device_memory.h"

#include <glad/gl.h>
#include <unistd.h>

#include "render/gl/gl_context.h"

namespace gps {

long long device_memory_bytes() {
  if (software_renderer()) {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? (long long)pages * page : 0;
  }
  GLint kib[4] = {0, 0, 0, 0};  // GL_ATI_meminfo gives four values, the first the total free
  if (GLAD_GL_NVX_gpu_memory_info)
    glGetIntegerv(GL_GPU_MEMORY_INFO_DEDICATED_VIDMEM_NVX, kib);
  else if (GLAD_GL_ATI_meminfo)
    glGetIntegerv(GL_VBO_FREE_MEMORY_ATI, kib);
  return (long long)kib[0] << 10;
}

}  // namespace gps
