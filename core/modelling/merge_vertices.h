#pragma once
// Merging vertices into one: collapsing a group picked by hand, or welding every group of vertices
// that lie closer than a distance (a mesh read as separate pieces, a seam left by mirroring).
//
// Like every modelling operation (core/modelling/mesh_arrays.h) these take a mesh and return a new
// one with a selection and a one-line summary, never changing their input; on refusal they throw
// gps::Error with a one-line reason and nothing is changed. A merged vertex keeps the smallest index
// of its group; the others are deleted and the remaining vertices compacted in order. Faces lose
// repeated consecutive corners; a face that meets a merged vertex twice is split there into loops
// (two opposite corners of a quad: two slivers); loops and faces left with fewer than 3 corners are
// deleted (the others compacted in order).
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Where a merged group's Gaussian comes from: `center` takes the mean of the means and the
/// covariance of the 9D average of the group (the normalised product of the Gaussians,
/// docs/design.md §1); `first`/`last` take the Gaussian of the first/last vertex listed.
enum class MergePoint { center, first, last };

/// Merges the vertices (2 or more, distinct) into one. Refuses a result that is not manifold, naming
/// the element. Selection: the merged vertex.
Modelled merge_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, MergePoint at);

/// Welds the vertices (all of them when `vertices` is empty) that lie closer than `distance` (> 0) to
/// one another: each cluster (connected through pairs within the distance) merges at its `center` as
/// above. Found through a uniform grid of cells of size `distance`, in time linear in the vertices for
/// evenly spread points. The summary names how many vertices were removed. Selection: the merged vertices.
Modelled weld_by_distance(const CovarianceMesh& mesh, const std::vector<int>& vertices, double distance);

/// An operation's result whose new vertices (its selection) may have met one another or a vertex of
/// their faces: those closer than `distance` are welded, the faces left without area removed, the
/// selection kept as the new vertices (merged ones included) and the summary told what is left.
/// Unchanged where none met; throws as weld_by_distance does.
Modelled merge_met_vertices(Modelled out, double distance);

}  // namespace gps
