#pragma once
// Insetting a face region: a smaller copy of the region inside it, joined to its old border by a band
// of quads. Follows the modelling contract (core/modelling/mesh_arrays.h): the input is never changed,
// a refusal throws a one-line gps::Error, existing vertices and faces keep their indices and new ones
// are appended.
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Insets a face region by `thickness` (> 0). Each boundary vertex of the region (one per fan of
/// region faces around it) gets an inner copy moved into the region's faces along the bisector of its
/// two region-boundary edges, in the plane of the fan's faces, by thickness / cos(half the corner's
/// angle) so that the inner edges lie `thickness` from the outer ones (for a single face: along each
/// corner's bisector). The region's faces are re-pointed at the inner copies, and one quad per
/// region-boundary edge joins outer to inner. The copy's mean is that geometric position; its
/// covariance is that of the 9D blend (1 − t) q_v + t q_c of the corner v with the 9D average q_c of
/// the fan's face points, t being the fraction of the way to q_c's mean the vertex moved, so the
/// ellipsoid shrinks towards the faces' as the vertex moves in. Refuses a thickness that is not
/// positive and finite, one that would carry a vertex past its faces' centre or turn a face inside out,
/// and a region that is the whole of a closed part (it has no border). Selection: the inner vertices.
Modelled inset_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, double thickness);
/// inset_faces made in `arrays` (a run of steps on arrays, core/modelling/operation_list.h): the
/// selection, with `summary` saying what was added.
std::vector<int> inset_faces_in(MeshArrays& arrays, const std::vector<int>& faces, double thickness,
                                std::string& summary);

}  // namespace gps
