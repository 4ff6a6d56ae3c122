#pragma once
// What one refinement step's connectivity shares between Catmull-Clark and Loop
// (core/reference/catmull_clark_connectivity.h, core/reference/loop_connectivity.h): each coarse edge e splits at its
// edge point nv + e into two outer halves (v, nv + e), and sorted by lower then higher vertex, as
// connectivity_of numbers edges, the halves at v come first and in v's own edge order: the outer
// half of e at v is refined edge i, the place of e in v's coarse vertex_edges row.
#include <vector>

#include "core/mesh/mesh_connectivity.h"

namespace gps {

/// The outer half of each coarse edge e at its end edge_verts[2e + s], at [2e + s].
std::vector<int> outer_half_edges(const MeshConnectivity& c, int n_vertices, bool parallel);

/// Vertex v's row of refined edges: its outer halves (v, n_vertices + e), written into `r` (sized).
void write_outer_half_edges(const MeshConnectivity& c, int v, int n_vertices, MeshConnectivity& r);

}  // namespace gps
