#pragma once
// The check that a frame is fit to show: pixels whose position or normal AOV is not finite mean
// the GPU's float evaluation failed there, and such a frame is reported, never written as an image;
// so is a frame framed on the surface that shows none of it.
#include "render/image/image.h"

namespace gps {

/// Pixels where any channel of `position` or `normal` (the same size) is NaN or infinite. Pixels the
/// surface does not cover hold the cleared zeros and never count.
long long count_non_finite_pixels(const Image& position, const Image& normal);

/// Pixels the surface covers: those whose normal AOV is not the cleared zero.
long long count_covered_pixels(const Image& normal);

}  // namespace gps
