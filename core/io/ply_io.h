#pragma once
// The covariance PLY of docs/design.md §4: vertex x y z and cxx cxy cxz cyy cyz czz (float or double),
// faces as vertex_indices; ASCII or binary little/big endian. A PLY without the six covariance
// properties is a plain mesh. Sharpness: a vertex property `corner` and an element `edge` with
// vertex1 vertex2 crease.
#include <ostream>
#include <string>
#include <string_view>

#include "core/io/polygon_soup.h"
#include "core/mesh/covariance_mesh.h"

namespace gps {

struct PlyContents {
  CovarianceMesh mesh;  // identity covariances when the file has none
  bool has_covariances = false;
};

/// Reads a PLY file; every malformed input is a gps::Error naming the file and what is wrong.
PlyContents read_ply(const std::string& path);

/// The first bytes of a PLY file (core/io/text_file.h): its first line is "ply".
void check_ply_head(std::string_view head, size_t size);

/// Parses PLY data already in memory; `source` names it in errors, which show text from the file as
/// core/support/quoted_text.h does.
PlyContents parse_ply(const std::string& data, const std::string& source);
/// The same taking the data over, freed once parsed and before the mesh is built (pass it moved);
/// `has_covariances` says whether the file gave them.
CovarianceMesh parse_ply(std::string data, const std::string& source, bool& has_covariances);
/// The same stopping at the polygon soup (face indices in range, the topology not checked), for
/// read_mesh to repair or build (core/io/mesh_repair.h); covariances empty where the file has none.
PolygonSoup parse_ply_soup(std::string data, const std::string& source, bool& has_covariances);

/// Writes a covariance PLY (doubles, exact round trip), ASCII or binary little endian; a mesh with
/// some sharpness also gets `corner` and the `edge` element, as float where exact, else double.
void write_ply(std::ostream& out, const CovarianceMesh& mesh, bool binary);

}  // namespace gps
