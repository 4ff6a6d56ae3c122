// The descent through a plan's nodes (core/plans/patch_plans.h) to the leaf under (u, v), and the weights
// of an extraordinary leaf's table rows: ONE source for core/evaluation/patch_eval.cpp (C++, double) and
// shaders/plan_eval.glsl (GLSL, float), which includes it after its node buffer; cmake/embed_shaders.cmake
// puts the file in place of the #include there. In GLSL the nodes are that buffer, `nodes[]`; in C++
// the first parameter. Uses the macros of core/patches/patch_basis.h, which comes first in both languages.
#ifndef GPS_GLSL
#pragma once
#include <cstdint>

#include "core/patches/patch_basis.h"
namespace gps {
#define GPS_NODES_PARAM const int32_t *nodes,
#define GPS_NODES_ARG nodes,
#else
#define GPS_NODES_PARAM
#define GPS_NODES_ARG
#endif

// No plan is deeper (core/plans/plan_builder.cpp; smooth meshes stop at 8, semi-sharp creases refine
// further): the descent is a bounded loop (after a divergent while loop, Mesa's llvmpipe runs the
// extraordinary node's loops with wrong values).
GPS_CONST int kMaxPlanDepth = 12;

/// One step down a quad node: child ubit + 2·vbit, ubit = (u ≥ ½), vbit = (v ≥ ½), with (u, v)
/// mapped into the child's [0,1]²; d(child)/d(node) = 2.
GPS_FN int quad_child(GPS_INOUT_REF(GPS_REAL) u, GPS_INOUT_REF(GPS_REAL) v) {
  int ubit = u >= 0.5 ? 1 : 0, vbit = v >= 0.5 ? 1 : 0;
  u = 2.0 * u - GPS_REAL(ubit);
  v = 2.0 * v - GPS_REAL(vbit);
  return ubit + 2 * vbit;
}

/// From node `node` down to the leaf under (u, v) of a quad (`triangle` false) or triangle plan:
/// returns the leaf, its kind and depth; (u, v) become the leaf's own parameters and `scale`
/// = d(leaf parameter)/d(patch parameter), with the half turns of middle triangle children. The
/// kind is read into a variable once per node: re-reading nodes[node] after the loop gives a stale
/// value on Mesa 22.3's llvmpipe.
GPS_FN int descend_plan(GPS_NODES_PARAM int node, bool triangle, GPS_INOUT_REF(GPS_REAL) u, GPS_INOUT_REF(GPS_REAL) v,
                        GPS_OUT_REF(GPS_REAL) scale, GPS_OUT_REF(int) kind, GPS_OUT_REF(int) depth) {
  scale = 1.0;
  kind = node_kind(nodes[node]);
  int level = 0;
  for (; level < kMaxPlanDepth && kind == kNodeInternal; ++level) {
    int child;
    if (triangle) {
      GPS_REAL sign;
      child = triangle_child(u, v, sign);
      scale *= 2.0 * sign;
    } else {
      child = quad_child(u, v);
      scale *= 2.0;
    }
    node = nodes[node + 1 + child];
    kind = node_kind(nodes[node]);
  }
  depth = level;
  return node;
}

/// An extraordinary node (core/extraordinary/quad_extraordinary_tables.h,
/// core/extraordinary/loop_extraordinary_tables.h) with its extraordinary vertex at corner r, at (u, v)
/// of its own domain: turned so that corner is at (0, 0) and located in a regular child n levels down,
/// whose net is a block of `net` rows of the node's table (net = 16 for quads, 12 for triangles); at
/// the corner the limit masks (3 rows: position, d/ds, d/dt).
/// Returns the rows' count; `first_row` is the first, w/ws/wt the rows' weights for the point and
/// its s and t derivatives, and d/du = scale (d[0] ∂s + d[1] ∂t), d/dv = scale (d[2] ∂s + d[3] ∂t).
/// Past the table's levels the rows apply to the node's points after `steps` steps of the table's
/// matrix A, where `stepping` (the CPU); without it (the GPU, whose tessellations stay within the
/// levels: core/patches/patch_basis.h, kExtraordinaryLevels) the limit masks stand in, steps = 0.
GPS_FN int extraordinary_rows(bool quad, int r, GPS_REAL u, GPS_REAL v, bool stepping, GPS_OUT_REF(int) first_row,
                              GPS_OUT_REF(int) steps, GPS_OUT GPS_REAL w[16], GPS_OUT GPS_REAL ws[16],
                              GPS_OUT GPS_REAL wt[16], GPS_OUT GPS_REAL d[4], GPS_OUT_REF(GPS_REAL) scale) {
  int net = quad ? 16 : 12;
  GPS_REAL s, t;
  int block;
  if (quad) {
    quad_turn_to_corner(r, u, v, s, t);
    quad_turned_derivative_coefficients(r, d);
    block = quad_extraordinary_locate(s, t, scale, steps);
  } else {
    triangle_turn_to_corner(r, u, v, s, t);
    triangle_turned_derivative_coefficients(r, d);
    block = loop_extraordinary_locate(s, t, scale, steps);
  }
  if (block < 0 || (steps > 0 && !stepping)) {  // the limit masks
    steps = 0;
    for (int j = 0; j < 3; ++j) {
      w[j] = j == 0 ? 1.0 : 0.0;
      ws[j] = j == 1 ? 1.0 : 0.0;
      wt[j] = j == 2 ? 1.0 : 0.0;
    }
    first_row = 3 * net * kExtraordinaryLevels;
    scale = 1.0;
    return 3;
  }
  if (quad) {
    quad_leaf_basis(kNodeRegular, 0, s, t, w, ws, wt);  // the tables' nets hold their phantoms
  } else {
    GPS_REAL w12[12], ws12[12], wt12[12];
    loop_box_spline_basis(s, t, w12, ws12, wt12);
    for (int j = 0; j < 12; ++j) {
      w[j] = w12[j];
      ws[j] = ws12[j];
      wt[j] = wt12[j];
    }
  }
  first_row = net * block;
  return net;
}

#ifndef GPS_GLSL
}  // namespace gps
#endif
