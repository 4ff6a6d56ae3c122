#pragma once
// The C heap tuned for a software GL driver's frames (Mesa's llvmpipe bins each frame's triangles
// into 64 KiB blocks it mallocs and frees again): called when a GL context is made.

namespace gps {

/// Keeps freed memory at the top of the heap instead of returning it to the system each time:
/// otherwise glibc trims the heap after every frame and the next frame faults its pages in again.
/// With it, a cached frame on llvmpipe costs what the same triangles from a static buffer do. Once
/// per process; harmless where the driver does not allocate so.
void retain_freed_heap();

}  // namespace gps
