#pragma once
// Exact limit positions of subdivision vertices (docs/design.md §2 "limit projection"): the masks of
// core/reference/vertex_mask.h applied to every vertex.
#include <functional>
#include <vector>

#include "core/reference/loop.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/sharpness.h"

namespace gps {

/// Whether every face around every vertex is a quad (the Catmull-Clark mask below needs it).
bool all_quads(const PolygonTopology& t);

/// Catmull-Clark limit of each vertex of an all-quad mesh: interior (n²v + 4Σe_i + Σf_i)/(n(n+5)),
/// boundary (a + 4v + b)/6, corners stay.
template <class T>
std::vector<T> catmull_clark_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& values);

/// Loop limit of each vertex: interior (1 − nχ)v + χΣn_i with χ = 1/(3/(8β) + n), boundary (a + 4v + b)/6, corners
/// stay.
template <class T>
std::vector<T> loop_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& values,
                          LoopBeta kind);

/// Takes each limit as it is made, put(v, limit of vertex v), from all cores for a large mesh: the
/// limits need not be stored before their use (the reference maps them straight back to Gaussians).
template <class T>
using PutLimit = std::function<void(int, const T&)>;

/// The Catmull-Clark limits of vertices 0 .. n − 1 (n ≤ t.n_vertices), as above, handed to put.
/// With `creases` (the sharpness left on `c`), each vertex's rule under it picks the mask, as
/// OpenSubdiv's Far::PrimvarRefiner::Limit does: a corner stays, a crease vertex goes to
/// (a + 4v + b)/6 with its crease neighbours, a smooth vertex takes the smooth mask. A dart of an
/// infinitely sharp edge takes its exact mask (core/reference/dart_masks.h), where Far takes
/// the smooth one; a semi-sharp dart the smooth one, as Far.
template <class T>
void catmull_clark_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& values, int n,
                         const PutLimit<T>& put, const CreaseLevel* creases = nullptr);

/// The Loop limits of all vertices, as above, handed to put; `creases` as for catmull_clark_limit.
template <class T>
void loop_limit(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& values, LoopBeta kind,
                const PutLimit<T>& put, const CreaseLevel* creases = nullptr);

}  // namespace gps
