#pragma once
// The connectivity of one Loop step read off the coarse one, as core/reference/catmull_clark_connectivity.h
// does for Catmull-Clark, instead of pairing the refined mesh's half-edges again (connectivity_of's sort).
#include "core/mesh/mesh_connectivity.h"

namespace gps {

/// Equals connectivity_of(loop_topology(t, c)) element for element (the same edge order, by lower
/// then higher vertex; the same incidence order), in time linear in the refined mesh. `t` is a
/// triangle mesh; `c` must be connectivity_of(t) or this function's own output.
MeshConnectivity loop_connectivity(const PolygonTopology& t, const MeshConnectivity& c);

}  // namespace gps
