#include "core/io/mesh_import.h"

#include <array>
#include <charconv>
#include <cstring>
#include <map>
#include <sstream>

#include "core/mesh/error.h"
#include "core/io/number_text.h"
#include "core/io/quoted_text.h"
#include "core/io/text_words.h"

namespace gps {

namespace {

// `source` is already as messages show it (escaped).
CovarianceMesh plain_mesh(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& faces,
                          const std::string& source) {
  for (size_t i = 0; i < points.size(); ++i)
    if (const std::string why = position_problem(points[i]); !why.empty())
      throw Error(source + ": vertex " + std::to_string(i) + " " + why);
  return make_covariance_mesh(points, std::vector<Mat3>(points.size(), Mat3::Identity()), faces, source);
}

bool parse_int(std::string_view s, long long& out) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size();
}

}  // namespace

CovarianceMesh parse_obj(const std::string& data, const std::string& source_path) {
  const std::string source = escaped(source_path);
  if (data.empty()) throw Error(source + ": the file is empty");
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  std::istringstream in(data);
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::string at = source + ": line " + std::to_string(line_number) + ": ";
    const auto words = words_of(line);
    if (words.empty() || words[0][0] == '#') continue;
    if (words[0] == "v") {
      Vec3 p;
      if (words.size() < 4) throw Error(at + "a vertex needs three coordinates");
      for (int k = 0; k < 3; ++k)
        if (const std::string why = parse_number(words[size_t(k + 1)], p[k]); !why.empty()) throw Error(at + why);
      points.push_back(p);
    } else if (words[0] == "f") {
      std::vector<int> face;
      for (size_t k = 1; k < words.size(); ++k) {
        long long index = 0;
        if (!parse_int(words[k].substr(0, words[k].find('/')), index))
          throw Error(at + quoted_token(words[k]) + " is not a vertex index");
        const long long written = index;
        if (index < 0) index += (long long)points.size() + 1;  // relative to the end
        if (index < 1 || index > (long long)points.size())
          throw Error(at + "vertex index " + std::to_string(written) + " is out of range (" +
                      std::to_string(points.size()) + " vertices so far)");
        face.push_back(int(index - 1));
      }
      if (face.size() < 3) throw Error(at + "a face needs at least 3 vertices");
      faces.push_back(face);
    }
  }
  if (points.empty()) throw Error(source + ": no vertices");
  return plain_mesh(points, faces, source);
}

CovarianceMesh parse_off(const std::string& data, const std::string& source_path) {
  const std::string source = escaped(source_path);
  if (data.empty()) throw Error(source + ": the file is empty");
  WordCursor t(data);
  const auto at = [&](int line) { return source + ": line " + std::to_string(line) + ": "; };
  // The keyword: OFF or a variant (COFF, NOFF, STCNOFF, ...) whose extra vertex values are skipped below.
  if (!t.done() && t.word().size() >= 3 && t.word().ends_with("OFF")) {
    if (t.word().find('4') != std::string_view::npos || t.word().starts_with("n"))
      throw Error(at(t.line()) + quoted_token(t.word()) + " (4D or n-dimensional OFF) is not supported");
    t.next();
  }
  const auto next_int = [&](const char* what) {
    if (t.done()) throw Error(source + ": the file ends early (expected " + what + ")");
    long long v = 0;
    if (!parse_int(t.word(), v) || v < 0)
      throw Error(at(t.line()) + quoted_token(t.word()) + " is not a valid " + what);
    t.next();
    return v;
  };
  const long long nv = next_int("vertex count"), nf = next_int("face count");
  next_int("edge count");
  // Every vertex takes at least 6 characters ("0 0 0\n"), every face at least 8 ("3 0 1 2\n").
  if (nv > (long long)data.size() / 6 || nf > (long long)data.size() / 8)
    throw Error(source + ": the header declares more vertices or faces than the file holds");
  // Arrays grow as records arrive (never sized from the header): memory follows what the file holds.
  std::vector<Vec3> points;
  for (long long v = 0; v < nv; ++v) {
    Vec3& p = points.emplace_back();
    int line = t.line();
    for (int k = 0; k < 3; ++k) {
      if (t.done()) throw Error(source + ": the file ends early (truncated vertex list)");
      line = t.line();
      if (const std::string why = parse_number(t.word(), p[k]); !why.empty()) throw Error(at(line) + why);
      t.next();
    }
    t.skip_line(line);  // normals, colours, texture coordinates
  }
  std::vector<std::vector<int>> faces;
  for (long long f = 0; f < nf; ++f) {
    std::vector<int>& face = faces.emplace_back();
    const int line = t.line();
    const long long n = next_int("face size");
    if (n < 3) throw Error(at(line) + "face " + std::to_string(f) + " has fewer than 3 vertices");
    for (long long k = 0; k < n; ++k) {
      const long long index = next_int("vertex index");
      if (index >= nv)
        throw Error(at(line) + "face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                    ", but there are " + std::to_string(nv));
      face.push_back(int(index));
    }
    t.skip_line(line);  // colour values
  }
  return plain_mesh(points, faces, source);
}

void check_text_head(std::string_view head, size_t size) {
  if (size == 0) throw Error("the file is empty");
  if (const size_t nul = head.find('\0'); nul != std::string_view::npos)
    throw Error("byte " + std::to_string(nul + 1) + " is a NUL: not a text file");
}

void check_stl_head(std::string_view head, size_t size) {
  if (size == 0) throw Error("the file is empty");
  if (head.starts_with("solid") && head.find('\0') == std::string_view::npos) return;  // ASCII
  if (size < 84) throw Error("binary STL shorter than its 84-byte header (truncated)");
  uint32_t declared = 0;
  std::memcpy(&declared, head.data() + 80, 4);
  if (size != 84 + size_t(declared) * 50)
    throw Error("binary STL of " + std::to_string(size) + " bytes whose header declares " + std::to_string(declared) +
                " triangles (" + std::to_string(84 + size_t(declared) * 50) + " bytes)");
}

CovarianceMesh parse_stl(const std::string& data, const std::string& source_path) {
  const std::string source = escaped(source_path);
  if (data.empty()) throw Error(source + ": the file is empty");
  std::vector<Vec3> corners;
  // Some binary STL headers start with "solid" too: a size matching the triangle count means binary.
  uint32_t declared = 0;
  if (data.size() >= 84) std::memcpy(&declared, data.data() + 80, 4);
  const bool binary_size = data.size() >= 84 && data.size() == 84 + size_t(declared) * 50;
  const bool looks_ascii = !binary_size && data.compare(0, 5, "solid") == 0 && data.find("facet") != std::string::npos;
  if (!looks_ascii) {
    if (data.size() < 84) throw Error(source + ": binary STL shorter than its 84-byte header (truncated)");
    uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    if (84 + size_t(n) * 50 > data.size())
      throw Error(source + ": binary STL declares " + std::to_string(n) + " triangles but holds fewer (truncated)");
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) {
        float xyz[3];
        std::memcpy(xyz, data.data() + 84 + i * 50 + 12 + size_t(c) * 12, 12);
        corners.emplace_back(xyz[0], xyz[1], xyz[2]);
      }
  } else {
    std::istringstream in(data);
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_number;
      const auto words = words_of(line);
      if (words.empty() || words[0] != "vertex") continue;
      Vec3 p;
      if (words.size() != 4)
        throw Error(source + ": line " + std::to_string(line_number) + ": a vertex needs three coordinates");
      for (int k = 0; k < 3; ++k)
        if (const std::string why = parse_number(words[size_t(k + 1)], p[k]); !why.empty())
          throw Error(source + ": line " + std::to_string(line_number) + ": " + why);
      corners.push_back(p);
    }
    if (corners.size() % 3 != 0) throw Error(source + ": a facet does not have three vertices");
  }
  if (corners.empty()) throw Error(source + ": no triangles");
  for (size_t c = 0; c < corners.size(); ++c)  // before welding: NaN keys would break the ordered map
    if (!corners[c].allFinite())
      throw Error(source + ": triangle " + std::to_string(c / 3) + " has a corner that is not finite");
  std::map<std::array<double, 3>, int> index;
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  for (size_t i = 0; i < corners.size(); i += 3) {
    std::vector<int> face;
    for (size_t c = i; c < i + 3; ++c) {
      const auto [it, added] = index.try_emplace({corners[c].x(), corners[c].y(), corners[c].z()}, int(points.size()));
      if (added) points.push_back(corners[c]);
      face.push_back(it->second);
    }
    if (face[0] != face[1] && face[1] != face[2] && face[0] != face[2]) faces.push_back(face);
  }
  return plain_mesh(points, faces, source);
}

}  // namespace gps
