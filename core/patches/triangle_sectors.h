#pragma once
// Where Loop's regular box-spline patches apply on a triangle mesh with creases: a vertex's sector
// (the triangles reached from one of them around the vertex without crossing a boundary or an
// infinitely sharp crease) and whether it is a regular corner of a patch, as core/patches/quad_nets.h
// decides for quads (docs/design.md §2 "Creases and corners in the plans").
#include <vector>

#include "core/patches/local_mesh.h"

namespace gps {

/// The neighbours of v counter-clockwise through the sector of triangle q: from the cut edge that
/// opens it where v has one (the ring closes otherwise), as TriangleWalker::fan gives them at a boundary.
std::vector<int> sector_fan(const LocalMesh& m, int v, int q);

/// Whether v is a regular corner of the box-spline patch of triangle q: complete, no semi-sharp edge
/// or corner at v, and six triangles around a smooth vertex or three in the sector of a vertex with
/// the crease rule (a boundary vertex, or one on an infinitely sharp crease).
bool regular_loop_corner(const LocalMesh& m, int v, int q);

}  // namespace gps
