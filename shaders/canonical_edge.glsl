// Shared patch edges and corners, bit for bit: a tessellation vertex on a patch's boundary is
// evaluated from one canonical patch at one parameter, whichever patch generated it, so that the
// patches beside an edge or around a corner produce bit-identical positions there and no background
// pixel shows through (core/plans/patch_adjacency.h has the tables and the rules). The canonical
// point is found with integers only; the one float step, parameter = step / level, is the same on
// every side.
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
    bool reversed = code >= 4;
    int j = first ? (reversed ? h - e.i : e.i) : (reversed ? e.n - e.i : e.i - h);
    return EdgePoint(q, code & 3, j, h);
  }
  int q = patch_neighbours[r], code = patch_neighbours[r + 1];
  if (q < 0) return e;  // a mesh boundary
  int m = code & 3;
  if (part >= kEdgeFirstHalf && patch_edges[kPatchEdgeStride * q + kPatchEdgeInts * m + 2] == kEdgeWholeBesideHalves) return e;  // a half beside a whole quad edge
  if (q > e.patch_id || (q == e.patch_id && m > e.edge)) return e;        // the lower patch evaluates
  return EdgePoint(q, m, code >= 4 ? e.n - e.i : e.i, e.n);
}

// The canonical form of a boundary point: the canonical edge point, or for a corner its owner's
// corner as step 0 of the owner's edge that starts there.
EdgePoint canonical_boundary_point(EdgePoint e, int corners) {
  e = canonical_edge_point(e, corners);
  if (e.i > 0 && e.i < e.n) return e;
  int c = e.i <= 0 ? e.edge : (e.edge + 1) % corners;
  int o = 2 * (corners * e.patch_id + c);
  return EdgePoint(corner_owners[o], corner_owners[o + 1], 0, 1);
}

// i / n and (n − i) / n, the parameters of an edge point.
vec2 edge_fractions(EdgePoint e) {
  precise float a = float(e.i) / float(e.n);
  precise float b = float(e.n - e.i) / float(e.n);
  return vec2(a, b);
}
