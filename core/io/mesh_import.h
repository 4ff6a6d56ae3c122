#pragma once
// Plain polygon meshes from OBJ, OFF and STL (ASCII or binary); covariances are left as identity
// for the caller to infer (core/mesh/inference.h). Errors name `source` and show text from the file
// as core/support/quoted_text.h does.
#include <functional>
#include <string>
#include <string_view>

#include "core/io/mesh_repair.h"
#include "core/io/polygon_soup.h"
#include "core/mesh/covariance_mesh.h"

namespace gps {

/// Parses OBJ text (v and f records; f accepts v/vt/vn and negative indices; OpenSubdiv's tags
/// "t crease 2/1/0 a b s" (pairs of vertices, numbered from 0) and "t corner 1/1/0 v s" give the
/// sharpness; other records are skipped). Its messages number vertices and faces from 1, as the file does.
/// The text is taken over and freed once parsed, before the mesh is built (pass it moved).
CovarianceMesh parse_obj(std::string data, const std::string& source);

/// Adds to `numbering` the lines of OBJ text on which the given vertices and faces (numbered from 0 in
/// the order of their records, as parse_obj_soup reads them) are read: messages name a few elements,
/// so their lines are looked up again rather than kept for every element.
void find_obj_lines(std::string_view data, const std::vector<int>& vertices, const std::vector<int>& faces,
                    ElementNumbering& numbering);

/// How messages name an OBJ file's vertices and faces: from 1, each with its line in the OBJ text
/// `text` returns, called only when a message names one (without the line where it throws gps::Error,
/// the file gone, or where `text` is empty: parse_obj has freed its text by then).
ElementNames obj_element_names(std::function<std::string()> text);

/// The first bytes of an OBJ or OFF file (core/io/text_file.h): text, without NUL bytes.
void check_text_head(std::string_view head, size_t size);
/// The first bytes of an STL file: ASCII ("solid ...", text) or binary (84-byte header, its triangle
/// count matching the file's size).
void check_stl_head(std::string_view head, size_t size);

/// Parses OFF text (optionally with the 'OFF' keyword missing and '#' comments).
/// The text is taken over and freed once parsed, before the mesh is built (pass it moved).
CovarianceMesh parse_off(std::string data, const std::string& source);

/// Parses STL, ASCII or binary; triangle corners at identical positions are welded into one vertex.
/// The data is taken over and freed once parsed, before the mesh is built (pass it moved).
CovarianceMesh parse_stl(std::string data, const std::string& source);

/// The same three readers stopping at the polygon soup (positions checked, face indices in range, the
/// topology not checked), for read_mesh to repair or build (core/io/mesh_repair.h).
PolygonSoup parse_obj_soup(std::string data, const std::string& source);
PolygonSoup parse_off_soup(std::string data, const std::string& source);
PolygonSoup parse_stl_soup(std::string data, const std::string& source);

}  // namespace gps
