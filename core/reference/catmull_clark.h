#pragma once
// One Catmull-Clark step on any polygon mesh, boundaries by the cubic B-spline curve rules and
// one-face vertices as fixed corners (docs/design.md §1, §3). Values are any linear type: the 9D duals
// for GPS subdivision (thesis Eq. 2.10 makes it linear), 3D points for the plain scheme.
//
// Output numbering: vertex points keep the input vertex indices, then one edge point per edge
// (MeshConnectivity order), then one face point per face. Face f with corners c_0..c_{n−1} gives
// quads k = (c_k', e'(c_k, c_{k+1}), f', e'(c_{k−1}, c_k)), in face order then k order — the
// patch convention of core/plans/patch_layout.h.
#include <vector>

#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/sharpness.h"

namespace gps {

/// The refined topology of one Catmull-Clark step.
PolygonTopology catmull_clark_topology(const PolygonTopology& t, const MeshConnectivity& c);

/// The refined values of one Catmull-Clark step (face, edge and vertex rules; boundary curve rules).
/// With `creases` (sharpness laid out on `c`), OpenSubdiv's crease rules (core/reference/crease_rules.h);
/// without, or where it is empty, the smooth rules alone.
template <class T>
std::vector<T> catmull_clark_values(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& values,
                                    const CreaseLevel* creases = nullptr);

}  // namespace gps
