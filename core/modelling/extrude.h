#pragma once
// Extruding faces, boundary edges and selected vertices: new geometry pulled off the mesh and joined
// to where it was by a band of quads oriented like their neighbours. Every operation follows the
// modelling contract (core/modelling/mesh_arrays.h): the input is never changed, a refusal throws a
// one-line gps::Error naming the element, existing vertices and faces keep their indices, new ones are
// appended, and a vertex copied off the mesh keeps its covariance with the moved mean. On a mesh of
// triangles only, each quad of the band is split into two triangles (the diagonal from its first
// corner), so that the mesh stays a triangle mesh, subdivided by Loop as before.
#include <array>
#include <string>
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// The twice-area-weighted normal of a face by Newell's method (its length is twice the face's area,
/// also for a non-planar polygon).
Vec3 newell_normal(const MeshArrays& arrays, int face);

/// A region of faces as extrude and inset see it. Its boundary is every edge of a region face whose
/// other side is not in the region, mesh-boundary edges included. Around a boundary vertex the region's
/// faces form one or more fans (sectors) separated by faces outside it; each sector gets its own copy
/// of the vertex, so that the result stays manifold.
struct FaceRegion {
  struct Sector {
    int vertex = -1;
    /// The region corners (face, corner index) at the vertex in this sector.
    std::vector<std::pair<int, int>> corners;
    /// The region-boundary edges u → vertex and vertex → w that bound the sector, as (face, corner of
    /// their first vertex).
    std::pair<int, int> incoming{-1, -1}, outgoing{-1, -1};
  };
  std::vector<int> faces;                     ///< sorted, unique
  std::vector<char> in_region;                ///< by face
  std::vector<std::pair<int, int>> boundary;  ///< region-boundary edges as (face, corner of first vertex)
  std::vector<Sector> sectors;                ///< by boundary vertex ascending
  std::vector<int> inner_vertices;            ///< vertices all of whose faces are in the region, ascending
  bool has_closed_part = false;               ///< a connected piece of the region has no boundary
};

/// The region of `faces` (checked, sorted); throws gps::Error for an empty list or a face not in the mesh.
FaceRegion face_region(const MeshArrays& arrays, const std::vector<int>& faces);

/// Detaches the region from the rest: appends `copies[s]` as the vertex of sector s, re-points the
/// region's corners in each sector at it and joins every region-boundary edge a → b to its copy by the
/// quad (a, b, b′, a′), oriented like the faces on both sides. Returns the copies' indices.
std::vector<int> detach_region(MeshArrays& arrays, const FaceRegion& region, const std::vector<Gaussian>& copies);

/// Extrudes a face region: the region's faces move off the mesh by `distance` along the region's
/// normal (the area-weighted average of its faces' normals, Newell's method for polygons), joined to
/// where they were by one quad per region-boundary edge. Vertices inside the region are moved, not
/// copied; the region's boundary vertices are duplicated (the copy, appended, moves with the region
/// and keeps the original's covariance; the region's faces are re-pointed at the copies). Distance 0
/// is allowed (the editor extrudes, then drags). Refuses a region that is the whole of a closed part
/// (nothing would be left to join to) and a non-finite distance. Selection: the region's vertices.
Modelled extrude_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, double distance);
/// extrude_faces made in `arrays` (a run of steps on arrays, core/modelling/operation_list.h): the
/// selection, with `summary` saying what was added.
std::vector<int> extrude_faces_in(MeshArrays& arrays, const std::vector<int>& faces, double distance,
                                  std::string& summary);

/// Extrudes the region of `faces` and moves it by `offset` (the editor's E in face mode): as
/// extrude_faces with distance 0, then the region's vertices moved. Refuses as extrude_faces does and
/// a non-finite offset.
Modelled extrude_faces_by(const CovarianceMesh& mesh, const std::vector<int>& faces, const Vec3& offset);

/// Extrudes mesh-boundary edges by `offset`: each edge gets a new quad whose outer edge is the edge's
/// copy moved by `offset` (one copy per vertex, shared by the edges meeting there), oriented like the
/// edge's face. Refuses an edge that is not in the mesh ("edge a–b is not in the mesh") or not on a
/// boundary ("edge a–b is not on a boundary"). Selection: the new vertices.
Modelled extrude_edges(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges, const Vec3& offset);

/// Extrude of selected vertices as the editor's E does in vertex mode: when some faces have all their
/// corners selected, those faces are extruded (distance 0) and the extruded vertices moved by
/// `offset`; otherwise the boundary edges with both ends selected are extruded by `offset`. Refuses
/// when neither exists.
Modelled extrude_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Vec3& offset);

}  // namespace gps
