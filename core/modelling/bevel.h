#pragma once
// Bevelling edges and vertices as Blender's Bevel does: a sharp edge becomes a band of `segments`
// quads across a rounded profile, a sharp vertex a cut-off corner. Follows the modelling contract
// (core/modelling/mesh_arrays.h): the input is never changed, a refusal throws a one-line gps::Error
// naming the element, existing vertices and faces keep their indices (the bevelled vertices, which the
// bevel replaces, are deleted and the rest compacted in order) and new ones are appended. On a mesh of
// triangles only every face the bevel makes or changes is split into triangles, so that the mesh stays
// Loop's.
#include <array>
#include <string>
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// How the bevel's width is measured, as Blender's Width Type.
enum class BevelWidth {
  offset,   ///< the distance of each new edge from the bevelled edge, in the faces beside it
  width,    ///< the width of the bevel's band (the chord across the profile)
  depth,    ///< the distance from the bevelled edge to the band
  percent,  ///< a percentage of the length of the edges the new vertices move along
};

/// The width types by name ("offset", "width", "depth", "percent"); false for an unknown name.
bool bevel_width_named(const std::string& name, BevelWidth& type);

struct BevelOptions {
  double width = 0.1;  ///< > 0, in the unit `width_type` says
  BevelWidth width_type = BevelWidth::offset;
  int segments = 1;  ///< 1 to kMaxBevelSegments quads across the band
  /// The profile's shape, in (0, 1] as Blender's: 0.5 a circular arc (an elliptic one where the faces
  /// are not square), 0.25 straight, 1 the sharp corner kept; below 0.25 it curves inwards. The profile
  /// is the superellipse |x|^r + |y|^r = 1 with r = −2 ln 2 / ln(profile), in the parallelogram of its
  /// two ends and the corner it cuts, sampled at equal angles.
  double profile = 0.5;
  /// Where the width would carry new vertices past each other along an edge, the width is reduced to
  /// where they meet (and the summary says so); without it such a width is refused. New vertices that
  /// meet (within a millionth of the mesh's size) are merged, the faces left without area removed.
  bool clamp = true;
  /// The crease sharpness the band's two rim edges get (0: none). Edge bevels only.
  double crease = 0;
};

constexpr int kMaxBevelSegments = 100;

/// Bevels edges. Each end vertex v of a bevelled edge is replaced by
/// new vertices in the faces around it: where two bevelled edges at v bound one face, one vertex in
/// that face at the offsets from both; where they bound two faces, one on the edge between them;
/// otherwise one on each edge beside a bevelled edge, the faces beyond keeping v where they have edges
/// of their own to it, but at the end of a single bevelled edge among four or more, where v goes and
/// each of its other edges gets a vertex at the width along it (Blender's terminal edge: on a flat grid
/// the polygon closing the end has area). Each bevelled edge becomes a band of `segments` quads across
/// its profile; at a vertex with three or more bevelled edges, or with faces left between them, a polygon closes the
/// corner (a valence-3 vertex at the end of one bevelled edge takes the profile into its third face
/// instead, as Blender does: one edge of a cube with 1 segment gives 10 vertices and 7 faces).
/// Open shells bevel as in Blender: an edge on a boundary gets its band in its one face, between the
/// edge (which stays, its ends kept as the band's outer corners) and the new edge at the offset, the
/// band's ends straight along the edges beside it (a face beyond takes their new vertices); an edge
/// ending on a boundary vertex ends there open, the vertex replaced by new vertices slid along the
/// boundary edges (kept where faces beside them still reach it, a polygon then closing the corner); the
/// boundary loops stay closed and as many. A boundary edge's band lies in its face, so its "width" and
/// "depth" are the offset.
/// Gaussians: a vertex moved along an edge v→u by the fraction t gets the 9D blend (1 − t) q_v + t q_u;
/// one inside a face the blend of the face's corner v, u, w with the barycentric weights of its
/// position in the triangle (v, u, w) (clipped to it); profile vertex i of n the blend
/// (1 − i/n) q_left + (i/n) q_right of the profile's ends. Means are the geometric positions. Creases
/// on the edges that remain follow them; the bevelled edges' go with them. Refuses an edge that is not
/// in the mesh, an end vertex with fewer than three edges inside the mesh or where faces meet only at
/// it, options out of range, and a width that would turn a face inside out. Selection: the new
/// vertices.
Modelled bevel_edges(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                     const BevelOptions& options);

/// Bevels vertices: each selected vertex v is replaced by one new vertex on each of its edges (at
/// `width` along it, or a percentage of its length; the width types "width" and "depth" are for edges),
/// joined in each face around v by a profile of `segments` edges cutting the face's corner, and a
/// polygon of those profiles closes the hole (one vertex of a cube: 10 vertices, 7 faces). At a
/// boundary vertex the gap outside the boundary gets a profile round the vertex too, which is the
/// polygon's side on the boundary (a straight edge with 1 segment); a corner of one face (valence 2)
/// has its corner cut off by its profile, which is the new boundary, as Blender does. Gaussians as
/// bevel_edges gives them. Refuses a vertex not in the mesh, one with fewer than three edges inside the
/// mesh or where faces meet only at it, the options bevel_edges refuses, and a crease (edges only).
/// Selection: the new vertices.
Modelled bevel_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const BevelOptions& options);

}  // namespace gps
