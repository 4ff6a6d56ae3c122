#pragma once
// Blender's "Adjust last operation" (F9): the last modelling operation with the numbers it took, and
// how to make it again from the mesh before it, so that changing a number replaces its result as the
// same one undo step.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

struct AdjustableParameter {
  std::string label;
  double value = 0.0, min = 0.0, max = 0.0;
  bool integer = false;
};

struct AdjustableOperation {
  std::string name;  // "bevel", "spin", ...
  std::vector<AdjustableParameter> parameters;
  std::shared_ptr<const CovarianceMesh> before;  // the mesh the operation was made from
  /// The operation made again from `before` with these values (one per parameter); throws
  /// gps::Error where they are refused.
  std::function<Modelled(const CovarianceMesh& before, const std::vector<double>& values)> make;
  std::uint64_t step = 0;  // the undo step it made (EditorDocument::last_step)
};

}  // namespace gps
