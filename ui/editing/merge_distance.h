#pragma once
// The editor's merge "By distance": its distance field, a fraction of the mesh's bounding-box
// diagonal (so that one value suits a mesh of any size), and the weld it runs.
#include <vector>

#include "core/modelling/merge_vertices.h"

namespace gps {

/// The field's default: vertices closer than 1e-4 of the diagonal are welded.
inline constexpr double kDefaultMergeDistance = 1e-4;

/// Welds the vertices (all where `vertices` is empty) closer than `fraction` of the mesh's
/// bounding-box diagonal (weld_by_distance); refuses a fraction outside (0, 1], naming it, with
/// nothing changed.
Modelled merge_by_distance(const CovarianceMesh& mesh, const std::vector<int>& vertices, double fraction);

}  // namespace gps
