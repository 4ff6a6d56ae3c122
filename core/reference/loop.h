#pragma once
// One Loop step on a triangle mesh, with the same boundary curve and corner rules as
// catmull_clark.h. Output numbering: vertex points keep the input indices, then one edge point per
// edge; triangle (a, b, c) gives (a', e'ab, e'ca), (b', e'bc, e'ab), (c', e'ca, e'bc), (e'ab, e'bc, e'ca).
#include <vector>

#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/sharpness.h"

namespace gps {

/// Loop's vertex weight β(n): Loop's original (5/8 − (3/8 + cos(2π/n)/4)²)/n, or Warren's 3/(8n) (3/16 for n = 3).
enum class LoopBeta { loop, warren };
double loop_beta(int valence, LoopBeta kind);

/// The refined topology of one Loop step; throws gps::Error naming the first face that is not a triangle.
PolygonTopology loop_topology(const PolygonTopology& t, const MeshConnectivity& c);

/// The refined values of one Loop step: vertex (1 − nβ)v + βΣn_i, edge 3/8(a + b) + 1/8(c + d).
/// With `creases` (sharpness laid out on `c`), OpenSubdiv's crease rules (core/reference/crease_rules.h);
/// without, or where it is empty, the smooth rules alone.
template <class T>
std::vector<T> loop_values(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<T>& values,
                           LoopBeta kind, const CreaseLevel* creases = nullptr);

}  // namespace gps
