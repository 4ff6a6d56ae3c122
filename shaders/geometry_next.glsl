// Put ahead of a vertex or tessellation evaluation stage that a wireframe geometry stage follows
// (mesh_geom.glsl): its outputs take the names that mesh_geom.glsl reads.
#define v_position g_position
#define v_normal g_normal
#define v_grid g_grid
#define v_kind g_kind
