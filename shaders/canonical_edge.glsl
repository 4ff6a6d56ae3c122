// Shared patch edges and corners, bit for bit: a tessellation vertex on a patch's boundary is
// evaluated from one canonical patch at one parameter, whichever patch generated it, so that the
// patches beside an edge or around a corner produce bit-identical positions there and no background
// pixel shows through (core/plans/patch_adjacency.h has the tables and the rules). The canonical
// point is found with integers only; the one float step, parameter = step / level, is the same on
// every side. On an infinitely sharp crease the records carry flags (kNeighbourSharpEdge,
// kOwnerSharpCorner): there the position is still the canonical patch's, the normal the patch's own
// (limit_point.glsl).
layout(std430, binding = kBindingPatchNeighbours) readonly buffer PatchNeighbours { int patch_neighbours[]; };
layout(std430, binding = kBindingCornerOwners) readonly buffer CornerOwners { int corner_owners[]; };

// Step i of n along edge `edge` of a patch; the edge runs from corner `edge` to corner `edge` + 1.
struct EdgePoint {
  int patch_id;
  int edge;
  int i;
  int n;
};

// The same point on the edge of the canonical patch (ends of the edge: unchanged).
EdgePoint canonical_edge_point(EdgePoint e, int corners) {
  if (e.i <= 0 || e.i >= e.n) return e;
  int r = 4 * (corners * e.patch_id + e.edge);
  int part = corners == 4 ? patch_edges[kPatchEdgeStride * e.patch_id + kPatchEdgeInts * e.edge + 2] : kEdgeWhole;
  if (part == kEdgeWholeBesideHalves) {  // a whole quad edge beside two half-size patches, which evaluate it: step h of 2h is their corner
    int h = e.n / 2;
    bool first = e.i <= h;
    int q = patch_neighbours[r + (first ? 0 : 2)], code = patch_neighbours[r + (first ? 1 : 3)];
    if (q < 0 || 2 * h != e.n) return e;
    bool reversed = (code & kNeighbourReversed) != 0;
    int j = first ? (reversed ? h - e.i : e.i) : (reversed ? e.n - e.i : e.i - h);
    return EdgePoint(q, code & kNeighbourEdgeMask, j, h);
  }
  int q = patch_neighbours[r], code = patch_neighbours[r + 1];
  if (q < 0) return e;  // a mesh boundary
  int m = code & kNeighbourEdgeMask;
  if (part >= kEdgeFirstHalf && patch_edges[kPatchEdgeStride * q + kPatchEdgeInts * m + 2] == kEdgeWholeBesideHalves) return e;  // a half beside a whole quad edge
  if (q > e.patch_id || (q == e.patch_id && m > e.edge)) return e;        // the lower patch evaluates
  return EdgePoint(q, m, (code & kNeighbourReversed) != 0 ? e.n - e.i : e.i, e.n);
}

// The patch edge that names the limit curve edge k of patch p lies on, for both sides alike
// (tess_levels.glsl measures it, corner_limit_comp.glsl keeps its midpoint): of an edge beside two
// half-size patches, that edge, and of each half beside it, the same; of a whole edge, and of a half
// beside another half or on the boundary (whose curve is then that half's own), the lower patch's.
// `part`: the patch edge's PatchEdgePart (whole for triangles).
ivec2 curve_edge(int p, int k, int part, int corners) {
  int r = 4 * (corners * p + k), q = patch_neighbours[r], m = patch_neighbours[r + 1] & kNeighbourEdgeMask;
  if (part == kEdgeWholeBesideHalves) return ivec2(p, k);
  if (part != kEdgeWhole && q >= 0 && patch_edges[kPatchEdgeStride * q + kPatchEdgeInts * m + 2] == kEdgeWholeBesideHalves)
    return ivec2(q, m);
  return q >= 0 && (q < p || (q == p && m < k)) ? ivec2(q, m) : ivec2(p, k);
}

// The canonical form of a boundary point: the canonical edge point, or for a corner its owner's
// corner as step 0 of the owner's edge that starts there.
EdgePoint canonical_boundary_point(EdgePoint e, int corners) {
  e = canonical_edge_point(e, corners);
  if (e.i > 0 && e.i < e.n) return e;
  int c = e.i <= 0 ? e.edge : (e.edge + 1) % corners;
  int o = 2 * (corners * e.patch_id + c);
  return EdgePoint(corner_owners[o], corner_owners[o + 1] & kOwnerCornerMask, 0, 1);
}

// The patch corner an edge point is at, or −1 inside its edge.
int edge_point_corner(EdgePoint e, int corners) {
  return e.i <= 0 ? e.edge : e.i >= e.n ? (e.edge + 1) % corners : -1;
}

// Whether a boundary point lies on an infinitely sharp crease of its patch, an edge or a corner
// (core/plans/patch_adjacency.h): its normal is then the patch's own.
bool sharp_boundary_point(EdgePoint e, int corners) {
  int c = edge_point_corner(e, corners);
  if (c >= 0) return (corner_owners[2 * (corners * e.patch_id + c) + 1] & kOwnerSharpCorner) != 0;
  int r = 4 * (corners * e.patch_id + e.edge);
  return patch_neighbours[r] >= 0 && (patch_neighbours[r + 1] & kNeighbourSharpEdge) != 0;
}

// i / n and (n − i) / n, the parameters of an edge point.
vec2 edge_fractions(EdgePoint e) {
  precise float a = float(e.i) / float(e.n);
  precise float b = float(e.n - e.i) / float(e.n);
  return vec2(a, b);
}

// (u, v) of an edge point. Quads: corners at (0,0), (1,0), (1,1), (0,1). Triangles: (u, v) are the
// barycentrics of corners 1 and 2.
vec2 edge_point_uv(EdgePoint e, int corners) {
  vec2 f = edge_fractions(e);
  if (corners == 3) {
    if (e.edge == 0) return vec2(f.x, 0.0);
    // Edge 1 (u + v = 1): the larger parameter is 1 − the smaller, exactly (Sterbenz), so that
    // 1 − u − v is 0 and the exact extraordinary evaluation does not step outside the triangle.
    if (e.edge == 1) return 2 * e.i >= e.n ? vec2(1.0 - f.x, f.x) : vec2(f.y, 1.0 - f.y);
    return vec2(0.0, f.y);
  }
  if (e.edge == 0) return vec2(f.x, 0.0);
  if (e.edge == 1) return vec2(1.0, f.x);
  if (e.edge == 2) return vec2(f.y, 1.0);
  return vec2(0.0, f.y);
}
