#pragma once
// glTF 2.0 meshes (.gltf JSON, its buffers embedded as base64 or in files beside it; .glb binary),
// read and written through Debian's tinygltf. A covariance mesh keeps its Gaussians in the custom
// vertex attribute "_COVARIANCE" (MAT3, float); creases and corners are not stored.
#include <array>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/polygon_soup.h"
#include "core/mesh/covariance_mesh.h"

namespace gps {

/// The first bytes of a glTF file: a .glb header ("glTF", version 2, its length the file's size) or
/// JSON text.
void check_gltf_head(std::string_view head, size_t size);

/// The triangle primitives (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN) of every mesh the default scene's
/// node trees place (every mesh once where the file has no scene), each morphed by its default weights
/// (the node's, else the mesh's: Σ w_k times target k's POSITION) and placed at its node's world
/// transform, as one soup: corners of one primitive of one instance at bit-identical positions are
/// welded into one vertex, as glTF splits a vertex at a seam of its normals or texture coordinates;
/// each primitive of each instance has vertices of its own. `has_covariances` says whether every
/// primitive gave "_COVARIANCE" (transformed as A Σ Aᵀ by the linear part A of its node's transform).
/// `data` is .glb or .gltf bytes; buffers in files are read from `base_dir` (none where it is empty).
/// Throws gps::Error
/// naming `source` and the element as the file numbers it ("mesh 0 primitive 1: accessor 3 reads past
/// its buffer view"); tinygltf's warnings become the soup's notes.
PolygonSoup parse_gltf_soup(const std::string& data, const std::string& source, const std::string& base_dir,
                            bool& has_covariances);

/// A triangle mesh as written to glTF: positions, unit normals and, where not empty, covariances, one
/// per vertex.
struct GltfTriangles {
  std::vector<Vec3> positions, normals;
  std::vector<Mat3> covariances;
  std::vector<std::array<int, 3>> triangles;
};

/// The mesh's faces cut into triangles inside each face (triangulate_face: ear clipping in its plane,
/// diagonals that are no edges of the mesh nor diagonals made before where it can, so that the file
/// reads back as a manifold mesh), with its vertex normals (the area-weighted normals of their faces,
/// by Newell's method) and its covariances.
GltfTriangles gltf_triangles_of(const CovarianceMesh& mesh);

/// Writes one mesh of one primitive (POSITION with its min and max, NORMAL, "_COVARIANCE" where there
/// are covariances, 32-bit indices) in one buffer: .glb where `binary`, else .gltf with the buffer
/// embedded as base64. Values are written as float; throws gps::Error (without a path: the caller adds
/// it) naming the vertex whose position does not fit a float or whose covariance in float is not one.
void write_gltf(std::ostream& out, const GltfTriangles& mesh, bool binary);

}  // namespace gps
