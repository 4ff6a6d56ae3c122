#include "core/modelling/bisect.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/modelling/edge_operations.h"
#include "core/modelling/extrude.h"
#include "core/modelling/face_pieces.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

namespace {

// Vertices this close to the plane, relative to the mesh's bounding-box diagonal, lie on it.
constexpr double kOnPlane = 1e-9;

// The positions in `cycle` (signs by position, 0 on the plane) where it crosses from one side to the
// other: the first vertex of each run of on-plane vertices between opposite signs. `cycle` starts at a
// vertex off the plane, so that no run wraps around.
std::vector<size_t> crossings(const std::vector<int>& sign) {
  std::vector<size_t> out;
  const size_t n = sign.size();
  int before = sign[0];
  for (size_t k = 1; k <= n; ++k) {
    if (sign[k % n] == 0) continue;
    if (sign[k - 1] == 0 && sign[k % n] != before) {
      size_t first = k - 1;
      while (sign[first - 1] == 0) --first;
      out.push_back(first);
    }
    before = sign[k % n];
  }
  return out;
}

}  // namespace

Modelled bisect(const CovarianceMesh& mesh, const Vec3& point, const Vec3& normal) {
  if (!point.allFinite() || !normal.allFinite()) throw Error("the plane has a number that is not finite");
  if (!(normal.norm() > 0)) throw Error("the plane's normal is zero");
  const Vec3 n = normal.normalized();
  MeshArrays a = arrays_of(mesh);
  const int n_faces = a.n_faces();
  const bool triangles_only =
      std::all_of(a.faces.begin(), a.faces.end(), [](const std::vector<int>& f) { return f.size() == 3; });
  const double tolerance = kOnPlane * bounding_box_diagonal(mesh);
  std::vector<double> distance(size_t(a.n_vertices()));
  std::vector<int> side(distance.size());
  for (size_t v = 0; v < distance.size(); ++v) {
    distance[v] = n.dot(a.means[v] - point);
    side[v] = std::abs(distance[v]) <= tolerance ? 0 : distance[v] > 0 ? 1 : -1;
  }

  // One new vertex per crossed edge, at the crossing of its means.
  std::unordered_map<uint64_t, int> cut_vertex;
  for (int f = 0; f < n_faces; ++f) {
    const std::vector<int> face = a.faces[size_t(f)];
    for (size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], v = face[(k + 1) % face.size()];
      if (side[size_t(u)] * side[size_t(v)] >= 0 || cut_vertex.count(edge_key(u, v))) continue;
      // From the edge's lower-numbered end, so that the blend does not depend on the face it is met in.
      const int lo = std::min(u, v), hi = std::max(u, v);
      const double t = distance[size_t(lo)] / (distance[size_t(lo)] - distance[size_t(hi)]);
      const int m = add_edge_vertex(a, lo, hi, t);
      side.push_back(0);
      cut_vertex.emplace(edge_key(u, v), m);
    }
  }

  std::vector<int> on_cut;
  int split_faces = 0;
  const size_t faces_before = a.faces.size();
  for (int f = 0; f < n_faces; ++f) {
    const std::vector<int>& face = a.faces[size_t(f)];
    // The face with its edges' new vertices, starting at a corner off the plane.
    const auto start = std::find_if(face.begin(), face.end(), [&](int v) { return side[size_t(v)] != 0; });
    if (start == face.end()) continue;
    std::vector<int> cycle;
    for (size_t k = 0, s = size_t(start - face.begin()); k < face.size(); ++k) {
      const int u = face[(s + k) % face.size()], v = face[(s + k + 1) % face.size()];
      cycle.push_back(u);
      if (const auto cut = cut_vertex.find(edge_key(u, v)); cut != cut_vertex.end()) cycle.push_back(cut->second);
    }
    std::vector<int> sign;
    for (int v : cycle) sign.push_back(side[size_t(v)]);
    const std::vector<size_t> at = crossings(sign);
    if (at.empty()) continue;
    // Chords between the crossings in their order along the plane's trace on the face.
    std::vector<int> points;
    for (size_t k : at) points.push_back(cycle[k]);
    const Vec3 along = n.cross(newell_normal(a, f));
    std::stable_sort(points.begin(), points.end(),
                     [&](int x, int y) { return along.dot(a.means[size_t(x)]) < along.dot(a.means[size_t(y)]); });
    std::vector<std::vector<int>> pieces = {cycle};
    for (size_t k = 0; k + 1 < points.size(); k += 2)
      if (!split_along(pieces, {points[k], points[k + 1]}))
        throw Error("face " + std::to_string(f) + " is crossed by the plane " + std::to_string(points.size()) +
                    " times in a way that does not cut it into pieces");
    if (triangles_only) triangulate_pieces(pieces, a.means, newell_normal(a, f));
    a.faces[size_t(f)] = pieces[0];
    a.faces.insert(a.faces.end(), pieces.begin() + 1, pieces.end());
    on_cut.insert(on_cut.end(), points.begin(), points.end());
    ++split_faces;
  }
  if (split_faces == 0)
    throw Error(std::count(side.begin(), side.end(), 1) > 0 && std::count(side.begin(), side.end(), -1) > 0
                    ? "the plane runs along edges of the mesh, which cut it there already: nothing to cut"
                    : "the plane crosses no face of the mesh");
  std::sort(on_cut.begin(), on_cut.end());
  on_cut.erase(std::unique(on_cut.begin(), on_cut.end()), on_cut.end());
  const size_t faces_added = a.faces.size() - faces_before;
  Modelled out = modelled(mesh, std::move(a), on_cut);
  out.summary = "bisected " + count_of(size_t(split_faces), "face", "faces") + ": " +
                count_of(cut_vertex.size(), "vertex", "vertices") + ", " + count_of(faces_added, "face", "faces") +
                " added";
  return out;
}

}  // namespace gps
