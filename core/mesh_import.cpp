#include "core/mesh_import.h"

#include <array>
#include <charconv>
#include <cstring>
#include <map>
#include <sstream>

#include "core/error.h"

namespace gps {

namespace {

CovarianceMesh plain_mesh(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& faces,
                          const std::string& source) {
  for (size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite()) throw Error(source + ": vertex " + std::to_string(i) + " has a position that is not finite");
  return make_covariance_mesh(points, std::vector<Mat3>(points.size(), Mat3::Identity()), faces, source);
}

bool parse_double(std::string_view s, double& out) {
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size();
}

bool parse_int(std::string_view s, long long& out) {
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && p == s.data() + s.size();
}

std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

}  // namespace

CovarianceMesh parse_obj(const std::string& data, const std::string& source) {
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
        if (!parse_double(words[size_t(k + 1)], p[k])) throw Error(at + "'" + words[size_t(k + 1)] + "' is not a number");
      points.push_back(p);
    } else if (words[0] == "f") {
      std::vector<int> face;
      for (size_t k = 1; k < words.size(); ++k) {
        long long index = 0;
        if (!parse_int(std::string_view(words[k]).substr(0, words[k].find('/')), index))
          throw Error(at + "'" + words[k] + "' is not a vertex index");
        if (index < 0) index += (long long)points.size() + 1;  // relative to the end
        if (index < 1 || index > (long long)points.size())
          throw Error(at + "vertex index " + words[k] + " is out of range (" + std::to_string(points.size()) + " vertices so far)");
        face.push_back(int(index - 1));
      }
      if (face.size() < 3) throw Error(at + "a face needs at least 3 vertices");
      faces.push_back(face);
    }
  }
  if (points.empty()) throw Error(source + ": no vertices");
  return plain_mesh(points, faces, source);
}

CovarianceMesh parse_off(const std::string& data, const std::string& source) {
  if (data.empty()) throw Error(source + ": the file is empty");
  // Tokens with their line numbers, comments removed.
  std::vector<std::pair<std::string, int>> tokens;
  std::istringstream in(data);
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    line = line.substr(0, line.find('#'));
    for (auto& w : words_of(line)) tokens.emplace_back(w, line_number);
  }
  size_t t = 0;
  // The keyword: OFF or a variant (COFF, NOFF, STCNOFF, ...) whose extra vertex values are skipped below.
  if (t < tokens.size() && tokens[t].first.size() >= 3 && tokens[t].first.ends_with("OFF")) {
    if (tokens[t].first.find("4") != std::string::npos || tokens[t].first.starts_with("n"))
      throw Error(source + ": line " + std::to_string(tokens[t].second) + ": " + tokens[t].first + " (4D or n-dimensional OFF) is not supported");
    ++t;
  }
  const auto next_int = [&](const char* what) {
    if (t >= tokens.size()) throw Error(source + ": the file ends early (expected " + what + ")");
    long long v = 0;
    if (!parse_int(tokens[t].first, v) || v < 0)
      throw Error(source + ": line " + std::to_string(tokens[t].second) + ": '" + tokens[t].first + "' is not a valid " + what);
    ++t;
    return v;
  };
  const long long nv = next_int("vertex count"), nf = next_int("face count");
  next_int("edge count");
  if (size_t(nv) > tokens.size() || size_t(nf) > tokens.size())
    throw Error(source + ": the header declares more vertices or faces than the file holds");
  std::vector<Vec3> points(static_cast<size_t>(nv));
  for (auto& p : points) {
    for (int k = 0; k < 3; ++k) {
      if (t >= tokens.size()) throw Error(source + ": the file ends early (truncated vertex list)");
      if (!parse_double(tokens[t].first, p[k]))
        throw Error(source + ": line " + std::to_string(tokens[t].second) + ": '" + tokens[t].first + "' is not a number");
      ++t;
    }
    const int line = tokens[t - 1].second;
    while (t < tokens.size() && tokens[t].second == line) ++t;  // normals, colours, texture coordinates
  }
  std::vector<std::vector<int>> faces(static_cast<size_t>(nf));
  for (size_t f = 0; f < faces.size(); ++f) {
    const int line = t < tokens.size() ? tokens[t].second : line_number;
    const long long n = next_int("face size");
    if (n < 3) throw Error(source + ": line " + std::to_string(line) + ": face " + std::to_string(f) + " has fewer than 3 vertices");
    for (long long k = 0; k < n; ++k) {
      const long long index = next_int("vertex index");
      if (index >= nv) throw Error(source + ": line " + std::to_string(line) + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(index) + ", but there are " + std::to_string(nv));
      faces[f].push_back(int(index));
    }
    while (t < tokens.size() && tokens[t].second == line) ++t;  // colour values
  }
  return plain_mesh(points, faces, source);
}

CovarianceMesh parse_stl(const std::string& data, const std::string& source) {
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
      if (words.size() != 4) throw Error(source + ": line " + std::to_string(line_number) + ": a vertex needs three coordinates");
      for (int k = 0; k < 3; ++k)
        if (!parse_double(words[size_t(k + 1)], p[k]))
          throw Error(source + ": line " + std::to_string(line_number) + ": '" + words[size_t(k + 1)] + "' is not a number");
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
