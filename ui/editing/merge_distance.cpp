#include "ui/editing/merge_distance.h"

#include <cmath>

#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

Modelled merge_by_distance(const CovarianceMesh& mesh, const std::vector<int>& vertices, double fraction) {
  if (!(std::isfinite(fraction) && fraction > 0 && fraction <= 1))
    throw Error("the merge distance must be more than 0 and at most 1 (of the bounding-box diagonal), got " +
                short_number(fraction));
  return weld_by_distance(mesh, vertices, fraction * bounding_box_diagonal(mesh));
}

}  // namespace gps
