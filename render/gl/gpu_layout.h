// What the C++ pipeline and its shaders agree on: buffer bindings, the compute work-group size and
// the layout of a 9D point. ONE source: compiled as C++ and embedded, with GPS_GLSL defined, ahead
// of the shaders that use it (cmake/embed_shaders.cmake), like core/patches/patch_basis.h.
#ifndef GPS_GLSL
#pragma once
namespace gps::gpu {
#define GPS_LAYOUT_CONST inline constexpr
#else
#define GPS_LAYOUT_CONST const
#endif

// Shader storage buffer bindings.
GPS_LAYOUT_CONST int kBindingGaussians = 0;     // per base vertex μ, Σ⁻¹ xx xy xz yy yz zz (shaders/dual_map_comp.glsl)
GPS_LAYOUT_CONST int kBindingPoints = 1;        // the plan points, kVec4PerPoint vec4 each
GPS_LAYOUT_CONST int kBindingOffsets = 2;       // stencil table (core/plans/patch_plans.h)
GPS_LAYOUT_CONST int kBindingIndices = 3;
GPS_LAYOUT_CONST int kBindingWeights = 4;
GPS_LAYOUT_CONST int kBindingNodes = 5;         // plan nodes
GPS_LAYOUT_CONST int kBindingRoots = 6;
GPS_LAYOUT_CONST int kBindingCorners = 7;
GPS_LAYOUT_CONST int kBindingChanged = 8;       // an edit's changed vertices
GPS_LAYOUT_CONST int kBindingRows = 9;          // the stencil rows that read them
GPS_LAYOUT_CONST int kBindingExtraordinaryTables = 10;     // core/extraordinary/loop_extraordinary_tables.h
GPS_LAYOUT_CONST int kBindingPatchEdges = 11;   // quads: patch edges and their parts (core/plans/patch_plans.h)
GPS_LAYOUT_CONST int kBindingPatchNeighbours = 12;  // per patch edge: the patch across (core/plans/patch_adjacency.h)
GPS_LAYOUT_CONST int kBindingCornerOwners = 13;     // per patch corner: the patch that evaluates it
GPS_LAYOUT_CONST int kBindingCornerLimits = 14;     // per patch corner: its owner's limit point, normal, node kind
GPS_LAYOUT_CONST int kBindingCornerList = 15;       // the corner pass's items (kCornerItemOps)
GPS_LAYOUT_CONST int kBindingCurveMidpoints = 16;   // per patch corner: the limit point halfway along its edge (canonical_edge.glsl)
GPS_LAYOUT_CONST int kBindingCount = 17;          // the plan buffers' bindings (render/pipeline/plan_buffers.h)
// The surface cache's weld (shaders/weld_comp.glsl), past the plan buffers'.
GPS_LAYOUT_CONST int kBindingStoredVertices = 17;
GPS_LAYOUT_CONST int kBindingWeldTable = 18;
GPS_LAYOUT_CONST int kBindingStoredIndices = 19;
GPS_LAYOUT_CONST int kBindingBlockStarts = 20;
GPS_LAYOUT_CONST int kBindingScanValues = 21;      // render/cache/exclusive_scan.h
GPS_LAYOUT_CONST int kBindingWeldedVertices = 22;  // the welded vertices, numbered block by block
GPS_LAYOUT_CONST int kBindingWeldedParameters = 23;  // their patch and (u, v) (render/cache/stored_vertex_evaluation.h)
GPS_LAYOUT_CONST int kBindingWeldedCounts = 24;      // per block: how many welded vertices it has
GPS_LAYOUT_CONST int kBindingEvaluationBlocks = 25;  // the blocks an evaluation of welded vertices runs over
GPS_LAYOUT_CONST int kBindingEvaluationGroups = 26;  // its dispatch and each block's first work group
GPS_LAYOUT_CONST int kBindingCopyRuns = 27;          // the runs of captured vertices a copy back writes
GPS_LAYOUT_CONST int kBindingPatchLevels = 28;       // per patch: its outer levels (render/cache/stored_patch_levels.h)
GPS_LAYOUT_CONST int kBindingLevelPatches = 29;      // the patches a level check runs over, with their listed block
GPS_LAYOUT_CONST int kBindingLevelChanges = 30;      // per listed block: whether a patch's levels changed
// Per patch before a change of topology: its number after it (render/cache/stored_patch_renumbering.h).
// It shares the level check's slot, never bound in the same pass: llvmpipe has 32 binding points.
GPS_LAYOUT_CONST int kBindingPatchNumbers = kBindingLevelPatches;
// The patches a triangle count runs over and their counts (render/cache/patch_triangle_counts.h), in
// the level check's slots likewise.
GPS_LAYOUT_CONST int kBindingCountedPatches = kBindingLevelPatches;
GPS_LAYOUT_CONST int kBindingPatchTriangles = kBindingLevelChanges;
GPS_LAYOUT_CONST int kBindingLevelBound = 31;        // the largest level of a range of patches (render/pipeline/patch_level_bound.h)

// The corner pass's items (shaders/corner_limit_comp.glsl): kCornerItemOps · slot + what it does there.
GPS_LAYOUT_CONST int kCornerItemMidpoint = 0;       // evaluate the limit halfway along the edge that starts there
GPS_LAYOUT_CONST int kCornerItemCorner = 1;         // evaluate the corner's limit point and normal
GPS_LAYOUT_CONST int kCornerItemClearMidpoint = 2;  // the slot holds no midpoint: zero
GPS_LAYOUT_CONST int kCornerItemClearCorner = 3;    // the slot holds no corner: zero
GPS_LAYOUT_CONST int kCornerItemOps = 4;

// Compute passes: invocations per work group.
GPS_LAYOUT_CONST int kWorkGroupSize = 64;
// The surface cache's weld: stored vertices per entry of the table that finds a vertex's block
// (shaders/stored_blocks.glsl).
GPS_LAYOUT_CONST int kBlockChunk = 64;
// A plan point q = (q̂, q̄) about its anchor a is three vec4 (dvec4 in double): (xx xy xz yy) (yz zz y0 y1) (y2 a0 a1 a2),
// y = q̄ − q̂ a (shaders/plan_point.glsl).
GPS_LAYOUT_CONST int kVec4PerPoint = 3;

#ifdef GPS_GLSL
// The scalars of the plan points and base Gaussians, their sums and the back map: float, or double
// where `#define GPS_DOUBLE` precedes the shader (render/gl/point_precision.h); the surface's
// positions and normals leave the evaluation in float either way.
#ifdef GPS_DOUBLE
#define point_real double
#define point_vec3 dvec3
#define point_vec4 dvec4
#define point_mat3 dmat3
#else
#define point_real float
#define point_vec3 vec3
#define point_vec4 vec4
#define point_mat3 mat3
#endif
#endif

#ifndef GPS_GLSL
}  // namespace gps::gpu
#endif
