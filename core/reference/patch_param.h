#pragma once
// A point of the limit surface named by its patch (the patch layout of core/plans/patch_layout.h)
// and its parameters: what the reference records for each vertex it makes, and what plans evaluate.

namespace gps {

/// A point on the limit surface named by patch and parameters in [0,1]².
struct PatchParam {
  int patch = -1;
  double u = 0.0;
  double v = 0.0;
};

}  // namespace gps
