#pragma once
// Select similar, as Blender's Shift+G: the elements of a mesh like one of the selected ones in a
// chosen respect (an edge's length or crease; a face's area, number of sides or normal; a vertex's
// number of edges).
#include <array>
#include <vector>

#include "core/mesh/covariance_mesh.h"

namespace gps {

enum class Similarity { edge_length, edge_crease, face_area, face_sides, face_normal, vertex_edges };
/// "length", "crease", "area", "sides", "normal", "number of edges".
const char* similarity_name(Similarity similarity);

/// The edges (a < b, ascending) whose length is within `tolerance` (a fraction of it) of a selected
/// edge's, or whose crease is within `tolerance` of one's. The selected edges are among them.
std::vector<std::array<int, 2>> similar_edges(const CovarianceMesh& mesh,
                                              const std::vector<std::array<int, 2>>& selected, Similarity similarity,
                                              double tolerance);
/// The faces (ascending) whose area is within `tolerance` (a fraction) of a selected face's, whose
/// number of sides equals one's, or whose normal turns from one's by at most `tolerance` · 180°.
std::vector<int> similar_faces(const CovarianceMesh& mesh, const std::vector<int>& selected, Similarity similarity,
                               double tolerance);
/// The vertices (ascending) with as many edges as a selected vertex.
std::vector<int> similar_vertices(const CovarianceMesh& mesh, const std::vector<int>& selected, Similarity similarity);

}  // namespace gps
