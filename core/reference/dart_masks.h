#pragma once
// The exact limit position and tangents of a dart, an interior vertex with one infinitely sharp edge.
// The sharp edge's point is its midpoint at every step, so the step of the dart's ring is not the
// smooth one and neither are its limit and tangents: Far's Limit takes the smooth masks there, which
// the refined points only approach level by level. The masks here are the left eigenvectors of the
// ring's step under our own rules (core/reference/vertex_ring.h): for eigenvalue 1 (the position) and
// for the two subdominant ones (the tangents), exact from any level.
#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/sharpness.h"
#include "core/reference/loop.h"
#include "core/reference/vertex_mask.h"

namespace gps {

/// The limit mask of v when v is a dart under `level` whose sharp edge is infinitely sharp and
/// whose faces are all quads (`quads`, Catmull-Clark) or all triangles (Loop with β `kind`); false,
/// leaving `mask` alone, otherwise (a semi-sharp dart's rules change as its edge decays).
bool dart_limit_mask(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& level, int v, bool quads,
                     LoopBeta kind, VertexMask& mask);

/// The two tangent masks of such a dart (as dart_limit_mask), first × second the normal on the side
/// the faces' corners turn to; false, leaving them alone, otherwise or where the ring's step has no
/// tangent pair (core/reference/vertex_ring.h's tangent_eigenvectors).
bool dart_tangent_masks(const PolygonTopology& t, const MeshConnectivity& c, const CreaseLevel& level, int v,
                        bool quads, LoopBeta kind, VertexMask& first, VertexMask& second);

}  // namespace gps
