#include "core/modelling/fill.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "core/io/mesh_repair.h"
#include "core/mesh/face_area.h"
#include "core/support/error.h"
#include "core/modelling/mesh_queries.h"
#include "core/modelling/operation_words.h"

namespace gps {

namespace {

// Where each boundary vertex lies: (loop, position in it); (−1, −1) for a vertex on no boundary.
struct BoundaryPlaces {
  std::vector<std::vector<int>> loops;
  std::vector<std::pair<int, int>> place;
};

BoundaryPlaces boundary_places(const CovarianceMesh& mesh) {
  BoundaryPlaces b{boundary_loops(mesh), std::vector<std::pair<int, int>>(mesh.n_vertices(), {-1, -1})};
  for (size_t l = 0; l < b.loops.size(); ++l)
    for (size_t k = 0; k < b.loops[l].size(); ++k) b.place[size_t(b.loops[l][k])] = {int(l), int(k)};
  return b;
}

void check_open(const CovarianceMesh& mesh, const BoundaryPlaces& b, int v) {
  if (b.place[size_t(v)].first < 0 && mesh.valence(size_t(v)) != 0)
    throw Error("vertex " + std::to_string(v) + " is not on a boundary");
}

// Whether the vertices, all on one loop, come in the loop's direction (+1), against it (−1), or neither (0).
int loop_direction(const BoundaryPlaces& b, const std::vector<int>& vertices) {
  const int loop = b.place[size_t(vertices.front())].first;
  for (int v : vertices)
    if (b.place[size_t(v)].first != loop) return 0;
  int ascents = 0, descents = 0;
  for (size_t k = 0; k < vertices.size(); ++k) {
    const int p = b.place[size_t(vertices[k])].second, q = b.place[size_t(vertices[(k + 1) % vertices.size()])].second;
    (q > p ? ascents : descents) += 1;
  }
  if (descents == 1) return 1;
  if (ascents == 1) return -1;
  return 0;
}

}  // namespace

Modelled fill(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  MeshArrays a = arrays_of(mesh);
  if (vertices.size() < 3) throw Error("a face needs at least 3 vertices");
  const std::vector<int> sorted = sorted_vertices(a, vertices);
  if (sorted.size() != vertices.size()) {
    std::vector<int> listed = vertices;
    std::sort(listed.begin(), listed.end());
    throw Error("vertex " + std::to_string(*std::adjacent_find(listed.begin(), listed.end())) + " is listed twice");
  }
  const BoundaryPlaces b = boundary_places(mesh);
  for (int v : vertices) check_open(mesh, b, v);
  const DirectedEdges edges(mesh);
  // Each existing boundary edge among the new face's votes for the direction that runs opposite to it.
  int keep = 0, reverse = 0;
  const size_t n = vertices.size();
  for (size_t k = 0; k < n; ++k) {
    const int u = vertices[k], w = vertices[(k + 1) % n];
    const bool along = edges.count(directed_key(u, w)) != 0, against = edges.count(directed_key(w, u)) != 0;
    if (along && against) throw Error(edge_name(u, w) + " is an interior edge (it has two faces)");
    if (along) ++reverse;
    if (against) ++keep;
  }
  if (keep > 0 && reverse > 0) throw Error("the face's edges on the boundary run both ways: no orientation fits");
  // Without a shared edge, a face within a hole runs against the loop of the faces' boundary edges.
  const bool reversed =
      reverse > 0 || (keep == 0 && b.place[size_t(vertices.front())].first >= 0 && loop_direction(b, vertices) > 0);
  std::vector<int> face = vertices;
  if (reversed) std::reverse(face.begin(), face.end());
  // A face of no area (its vertices in a line) is one the repair would drop.
  const auto mean = [&](int v) -> const Vec3& { return a.means[size_t(v)]; };
  if (without_area(face, mean, RepairOptions().weld_tolerance * bounding_box_diagonal(mesh)))
    throw Error("the vertices lie in a line: the face would have no area");
  a.faces.push_back(face);
  return modelled(
      mesh, std::move(a), sorted,
      "filled a face of " + std::to_string(n) + " vertices" + (reversed ? " (reversed to fit its neighbours)" : ""));
}

Modelled fill_selected(const CovarianceMesh& mesh, const std::vector<int>& vertices) {
  const MeshArrays a = arrays_of(mesh);
  const std::vector<int> selected = sorted_vertices(a, vertices);
  const BoundaryPlaces b = boundary_places(mesh);
  for (int v : selected) check_open(mesh, b, v);
  if (selected.size() < 3)
    throw Error("select at least 3 boundary vertices (" + std::to_string(selected.size()) + " selected)");
  const int loop = b.place[size_t(selected.front())].first;
  const bool one_loop = std::all_of(selected.begin(), selected.end(),
                                    [&](int v) { return loop >= 0 && b.place[size_t(v)].first == loop; });
  if (one_loop && selected.size() == b.loops[size_t(loop)].size()) return fill(mesh, b.loops[size_t(loop)]);
  if (selected.size() > 4)
    throw Error(
        "the " + std::to_string(selected.size()) +
        " selected vertices are not one whole boundary loop (select a whole loop, or 3 or 4 boundary vertices)");
  std::vector<int> order = selected;
  if (one_loop) {
    std::sort(order.begin(), order.end(),
              [&](int u, int w) { return b.place[size_t(u)].second < b.place[size_t(w)].second; });
  } else {
    // By angle around the centroid, in the plane of least spread.
    Vec3 centroid = Vec3::Zero();
    for (int v : order) centroid += a.means[size_t(v)];
    centroid /= double(order.size());
    Mat3 spread = Mat3::Zero();
    for (int v : order) spread += (a.means[size_t(v)] - centroid) * (a.means[size_t(v)] - centroid).transpose();
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(spread);
    const Vec3 x = eigen.eigenvectors().col(2), y = eigen.eigenvectors().col(1);
    const auto angle = [&](int v) {
      const Vec3 d = a.means[size_t(v)] - centroid;
      return std::atan2(d.dot(y), d.dot(x));
    };
    std::sort(order.begin(), order.end(), [&](int u, int w) { return angle(u) < angle(w); });
  }
  return fill(mesh, order);
}

}  // namespace gps
