#pragma once
// The memory a GL device holds buffers in, which sizes what the surface cache may take.

namespace gps {

/// Bytes of the current context's device memory: a GPU's dedicated memory where its driver says
/// (GL_NVX_gpu_memory_info; GL_ATI_meminfo's free memory), the machine's physical memory for a
/// software renderer (llvmpipe's buffers are the process's); 0 where neither is known.
long long device_memory_bytes();

}  // namespace gps
