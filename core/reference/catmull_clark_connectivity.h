#pragma once
// The connectivity of one Catmull-Clark step read off the coarse one, as OpenSubdiv's Vtr refines
// its topology, instead of pairing the refined mesh's half-edges again (connectivity_of's sort).
#include "core/mesh/mesh_connectivity.h"

namespace gps {

/// Equals connectivity_of(catmull_clark_topology(t, c)) element for element (the same edge order,
/// by lower then higher vertex; the same incidence order), in time linear in the refined mesh.
/// `c` must be connectivity_of(t) or this function's own output, and no face may repeat a vertex
/// (as a covariance mesh guarantees).
MeshConnectivity catmull_clark_connectivity(const PolygonTopology& t, const MeshConnectivity& c);

}  // namespace gps
