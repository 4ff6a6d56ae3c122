#include "core/reference/vertex_ring.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

#include "core/reference/catmull_clark.h"

namespace gps {

bool ordered_ring(const PolygonTopology& t, const MeshConnectivity& c, int v, int face_size, OrderedRing& ring) {
  struct Corner {
    int next, diagonal, previous;
  };
  std::vector<Corner> corners;
  for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i) {
    const int f = c.vertex_faces[size_t(i)], k = c.vertex_face_corners[size_t(i)], n = t.face_size(f);
    if (n != face_size) return false;
    const int* corner = &t.verts[size_t(t.offsets[size_t(f)])];
    corners.push_back({corner[(k + 1) % n], n == 4 ? corner[(k + 2) % n] : -1, corner[(k + n - 1) % n]});
  }
  if (corners.empty()) return false;
  // Face i + 1 follows face i where its next neighbour is face i's previous one. A boundary fan
  // starts at the face whose next neighbour follows no face.
  const auto following = [&](int neighbour) {
    return std::find_if(corners.begin(), corners.end(), [&](const Corner& x) { return x.next == neighbour; });
  };
  auto start = corners.begin();
  ring.boundary = false;
  for (auto it = corners.begin(); it != corners.end(); ++it)
    if (std::none_of(corners.begin(), corners.end(), [&](const Corner& x) { return x.previous == it->next; })) {
      start = it;
      ring.boundary = true;
    }
  ring.edges.assign(1, start->next);
  ring.diagonals.clear();
  auto at = start;
  for (size_t walked = 0; walked < corners.size(); ++walked) {
    ring.diagonals.push_back(at->diagonal);
    if (walked + 1 == corners.size()) break;
    ring.edges.push_back(at->previous);
    at = following(at->previous);
    if (at == corners.end()) return false;  // not one fan
  }
  if (ring.boundary) {
    ring.edges.push_back(at->previous);
    return true;
  }
  return at->previous == start->next;  // the fan closes
}

Eigen::MatrixXd ring_step_matrix(int k, bool quads, bool boundary, LoopBeta kind, int sharp_edge) {
  const int n_edges = boundary ? k + 1 : k, n_points = 1 + n_edges + (quads ? k : 0);
  PolygonTopology fan;
  fan.n_vertices = n_points;
  fan.offsets = {0};
  for (int i = 0; i < k; ++i) {
    const int next_edge = 1 + (i + 1) % n_edges;
    if (quads)
      fan.verts.insert(fan.verts.end(), {0, 1 + i, 1 + n_edges + i, next_edge});
    else
      fan.verts.insert(fan.verts.end(), {0, 1 + i, next_edge});
    fan.offsets.push_back(int(fan.verts.size()));
  }
  const MeshConnectivity c = connectivity_of(fan);
  CreaseLevel creases;
  if (sharp_edge >= 0) {
    creases.edges.assign(size_t(c.n_edges()), 0.0);
    for (int e = 0; e < c.n_edges(); ++e)
      if (std::min(c.edge_verts[2 * size_t(e)], c.edge_verts[2 * size_t(e) + 1]) == 0 &&
          std::max(c.edge_verts[2 * size_t(e)], c.edge_verts[2 * size_t(e) + 1]) == 1 + sharp_edge)
        creases.edges[size_t(e)] = kInfiniteSharpness;
  }
  std::vector<Eigen::VectorXd> unit(static_cast<size_t>(n_points));
  for (int i = 0; i < n_points; ++i) unit[size_t(i)] = Eigen::VectorXd::Unit(n_points, i);
  const CreaseLevel* sharpness = sharp_edge >= 0 ? &creases : nullptr;
  const std::vector<Eigen::VectorXd> refined =
      quads ? catmull_clark_values(fan, c, unit, sharpness) : loop_values(fan, c, unit, kind, sharpness);
  // The refined ring: v's vertex point, the edge points of (v, e_i), the face points.
  Eigen::MatrixXd step(n_points, n_points);
  step.row(0) = refined[0].transpose();
  for (int e = 0; e < c.n_edges(); ++e) {
    const int a = c.edge_verts[2 * size_t(e)], b = c.edge_verts[2 * size_t(e) + 1];
    if (a == 0 || b == 0) step.row(a + b) = refined[size_t(n_points + e)].transpose();
  }
  if (quads)
    for (int f = 0; f < k; ++f) step.row(1 + n_edges + f) = refined[size_t(n_points + c.n_edges() + f)].transpose();
  return step;
}

std::vector<Eigen::VectorXd> tangent_eigenvectors(const Eigen::MatrixXd& step, const Eigen::MatrixXd& flat) {
  const long n = step.rows();
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(step.transpose());
  const Eigen::VectorXcd values = solver.eigenvalues();
  std::vector<long> order(static_cast<size_t>(n));
  for (long i = 0; i < n; ++i) order[size_t(i)] = i;
  std::sort(order.begin(), order.end(), [&](long a, long b) { return std::abs(values[a]) > std::abs(values[b]); });
  const auto real = [&](int i) { return std::abs(values[order[size_t(i)]].imag()) < 1e-12; };
  const bool separated = n == 3 || std::abs(values[order[2]]) > std::abs(values[order[3]]) + 1e-9;
  if (!real(0) || !real(1) || !real(2) || std::abs(values[order[0]].real() - 1.0) > 1e-12 || !separated) return {};
  std::vector<Eigen::VectorXd> pair = {solver.eigenvectors().col(order[1]).real(),
                                       solver.eigenvectors().col(order[2]).real()};
  // An eigenvector's sign is arbitrary: orient the pair by its turn on the flat ring.
  const Eigen::Vector2d a = flat.transpose() * pair[0], b = flat.transpose() * pair[1];
  const double turn = a.x() * b.y() - a.y() * b.x();
  if (std::abs(turn) < 1e-9 * a.norm() * b.norm()) return {};
  if (turn < 0) pair[1] = -pair[1];
  return pair;
}

}  // namespace gps
