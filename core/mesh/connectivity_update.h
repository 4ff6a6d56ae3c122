#pragma once
// The connectivity of a mesh made from another by a modelling operation, carried over from the other's
// instead of built again: the work follows what changed, the result is what connectivity_of gives.
#include <optional>
#include <vector>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

/// Where a mesh made from another came from: per vertex and per face of the new mesh, the element of
/// the old one it continues, −1 for a new one. `faces` may be shorter than the new mesh's faces (those
/// past its end are new). A face continues an old one only where it has the old face's corners,
/// renumbered; any other face counts as new.
struct MeshOrigins {
  std::vector<int> vertices, faces;
};

/// connectivity_of(`after`), vertex rows included, built from `before`'s connectivity `c`: the edges of
/// the faces that continue old ones are carried over and renumbered, those of the new faces are sorted
/// in. Everything a change reaches is checked as check_manifold and make_covariance_mesh check a whole
/// mesh (new faces' corners, edges with more than two faces, flipped faces, fans, pillows); what it does
/// not reach was checked when `before` was made. Empty where it cannot vouch for the result (a check
/// fails, the old vertices change their order, most faces are new): the caller then builds and checks
/// the mesh whole, which names what is wrong. `continued`, where given and the result is not empty,
/// gets per new face the old face it continues as checked (its corners are the old face's, renumbered;
/// −1: new).
std::optional<MeshConnectivity> updated_connectivity(const PolygonTopology& before, const MeshConnectivity& c,
                                                     const PolygonTopology& after, const MeshOrigins& origins,
                                                     std::vector<int>* continued = nullptr);

}  // namespace gps
