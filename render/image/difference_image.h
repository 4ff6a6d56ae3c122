#pragma once
// The thesis' difference images (Figs. 4.4, 4.8) between two AOV renders.
#include "render/image/image_io.h"

namespace gps {

enum class AovKind { position, normal };

struct DifferenceStats {
  double max = 0, mean = 0, share_above = 0;  // over pixels covered in both images
  int covered = 0, coverage_mismatch = 0;     // pixels covered in one image only
};

/// Position: Euclidean distance / bounding-box diagonal (of A's covered pixels) × factor, grey.
/// Normal: per-component |difference| × factor, RGB. Pixels covered in one image only are red.
/// Stats are of the unscaled differences; `threshold` is on the same scale.
Image difference_image(const Image& a, const Image& b, AovKind kind, double factor, double threshold,
                       DifferenceStats& stats);

}  // namespace gps
