#include "core/modelling/loop_cut.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <sstream>
#include <string>
#include <unordered_map>

#include "core/support/error.h"
#include "core/modelling/operation_words.h"

namespace gps {

namespace {

// The ring as edges and the quads between them: quads[i] lies between edges[i] and edges[i + 1]
// (for a closed ring, the last between the last edge and the first).
struct Ring {
  EdgeRing ring;
  std::vector<int> quads;
};

// Across quad `f` from its edge {x, y} to the opposite edge, directed with x's neighbour first.
std::array<int, 2> opposite_edge(const CovarianceMesh& mesh, int f, int x, int y) {
  const std::span<const int> c = mesh.face(size_t(f));
  const int k = int(std::find(c.begin(), c.end(), x) - c.begin());
  if (c[size_t(k + 1) % 4] == y) return {c[size_t(k + 3) % 4], c[size_t(k + 2) % 4]};  // x → y in the face
  return {c[size_t(k + 1) % 4], c[size_t(k + 2) % 4]};                                 // y → x in the face
}

// The face on the other side of {x, y} from `from`, or −1 at the boundary.
int face_across(const CovarianceMesh& mesh, int x, int y, int from) {
  const int e = mesh.find_edge(x, y);
  if (e < 0) return -1;
  for (int s = 0; s < 2; ++s)
    if (const int f = mesh.connectivity().edge_faces[2 * size_t(e) + size_t(s)]; f >= 0 && f != from) return f;
  return -1;
}

// The face that runs along x → y, or −1.
int face_running(const CovarianceMesh& mesh, int x, int y) {
  const int e = mesh.find_edge(x, y);
  if (e < 0) return -1;
  for (int s = 0; s < 2; ++s) {
    const int f = mesh.connectivity().edge_faces[2 * size_t(e) + size_t(s)];
    if (f < 0) continue;
    const std::span<const int> c = mesh.face(size_t(f));
    for (size_t k = 0; k < c.size(); ++k)
      if (c[k] == x && c[(k + 1) % c.size()] == y) return f;
  }
  return -1;
}

// From edge x → y, first into `face`, across quads: the edges and quads passed, until a face that is
// not a quad, the boundary or the start edge again (then `closed`).
void walk(const CovarianceMesh& mesh, std::array<int, 2> edge, int face, std::vector<std::array<int, 2>>& passed_edges,
          std::vector<int>& passed_quads, bool& closed) {
  const std::array<int, 2> start = edge;
  const size_t limit = mesh.n_corners();
  while (face >= 0 && mesh.face_size(size_t(face)) == 4 && passed_edges.size() <= limit) {
    const std::array<int, 2> next = opposite_edge(mesh, face, edge[0], edge[1]);
    passed_quads.push_back(face);
    if (edge_key(next[0], next[1]) == edge_key(start[0], start[1])) {
      closed = true;
      return;
    }
    passed_edges.push_back(next);
    face = face_across(mesh, next[0], next[1], face);
    edge = next;
  }
}

Ring ring_of(const CovarianceMesh& mesh, int a, int b) {
  check_vertex(mesh.n_vertices(), a);
  check_vertex(mesh.n_vertices(), b);
  if (mesh.find_edge(a, b) < 0) throw Error(edge_name(a, b) + " is not in the mesh");
  Ring r;
  std::vector<std::array<int, 2>> forward_edges, backward_edges;
  std::vector<int> forward_quads, backward_quads;
  walk(mesh, {a, b}, face_running(mesh, a, b), forward_edges, forward_quads, r.ring.closed);
  if (r.ring.closed) {
    r.ring.edges.push_back({a, b});
    r.ring.edges.insert(r.ring.edges.end(), forward_edges.begin(), forward_edges.end());
    r.quads = forward_quads;
    return r;
  }
  bool closed_backward = false;
  walk(mesh, {a, b}, face_running(mesh, b, a), backward_edges, backward_quads, closed_backward);
  r.ring.edges.assign(backward_edges.rbegin(), backward_edges.rend());
  r.ring.edges.push_back({a, b});
  r.ring.edges.insert(r.ring.edges.end(), forward_edges.begin(), forward_edges.end());
  r.quads.assign(backward_quads.rbegin(), backward_quads.rend());
  r.quads.insert(r.quads.end(), forward_quads.begin(), forward_quads.end());
  return r;
}

double cut_fraction(int k, int cuts, double slide) {
  const double s = double(k) / double(cuts + 1);
  return slide <= 0 ? s * (1 + slide) : s + slide * (1 - s);
}

}  // namespace

EdgeRing edge_ring(const CovarianceMesh& mesh, int a, int b) { return ring_of(mesh, a, b).ring; }

Modelled loop_cut(const CovarianceMesh& mesh, int a, int b, int cuts, double slide) {
  if (cuts < 1 || cuts > 64) throw Error("the number of cuts must be 1..64, got " + std::to_string(cuts));
  if (!(std::abs(slide) < 1)) throw usage_error("the slide must be in (−1, 1), got " + short_number(slide));
  const Ring r = ring_of(mesh, a, b);
  MeshArrays arrays = arrays_of(mesh);
  if (r.quads.empty()) throw Error(edge_name(a, b) + " has no quad beside it to cut across");
  std::vector<int> sorted_quads = r.quads;
  std::sort(sorted_quads.begin(), sorted_quads.end());
  const auto twice = std::adjacent_find(sorted_quads.begin(), sorted_quads.end());
  if (twice != sorted_quads.end())
    throw Error("the ring through " + edge_name(a, b) + " crosses itself in face " + std::to_string(*twice));

  // Each ring edge's rail: its first end, the new vertices, its second end.
  const int n_vertices = arrays.n_vertices();
  std::vector<std::vector<int>> rails;
  std::unordered_map<uint64_t, size_t> rail_of;
  for (const auto& [x, y] : r.ring.edges) {
    std::vector<int> rail = {x};
    for (int k = 1; k <= cuts; ++k) {
      const double t = cut_fraction(k, cuts, slide);
      rail.push_back(arrays.add_vertex(blend_gaussians(arrays, {{x, 1 - t}, {y, t}})));
    }
    rail.push_back(y);
    // A creased ring edge's pieces keep its sharpness (as Blender's loop cut does).
    if (const double s = arrays.sharpness.crease(x, y); s > 0.0)
      for (size_t k = 0; k + 1 < rail.size(); ++k) arrays.sharpness.set_crease(rail[k], rail[k + 1], s);
    rail_of[edge_key(x, y)] = rails.size();
    rails.push_back(std::move(rail));
  }

  // The ring's quads, each into cuts + 1 strips between consecutive rails.
  std::vector<std::vector<int>> appended;
  for (size_t i = 0; i < r.quads.size(); ++i) {
    const int f = r.quads[i];
    const std::vector<int>& p = rails[i];
    const std::vector<int>& q = rails[(i + 1) % rails.size()];
    const bool forward = face_running(mesh, p.front(), p.back()) == f;
    std::vector<std::vector<int>> strips;
    for (int j = 0; j <= cuts; ++j)
      strips.push_back(forward ? std::vector<int>{p[size_t(j)], p[size_t(j) + 1], q[size_t(j) + 1], q[size_t(j)]}
                               : std::vector<int>{p[size_t(j) + 1], p[size_t(j)], q[size_t(j)], q[size_t(j) + 1]});
    arrays.faces[size_t(f)] = strips[0];
    appended.insert(appended.end(), strips.begin() + 1, strips.end());
  }

  // Other faces on ring edges (the ends of an open ring) take the new vertices as extra corners.
  std::vector<int> ends;
  for (const auto& [x, y] : r.ring.edges)
    for (int s = 0; s < 2; ++s)
      if (const int f = mesh.connectivity().edge_faces[2 * size_t(mesh.find_edge(x, y)) + size_t(s)];
          f >= 0 && !std::binary_search(sorted_quads.begin(), sorted_quads.end(), f))
        ends.push_back(f);
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  for (const int f : ends) {
    const std::vector<int> c = arrays.faces[size_t(f)];
    std::vector<int> corners;
    for (size_t k = 0; k < c.size(); ++k) {
      const int u = c[k], v = c[(k + 1) % c.size()];
      corners.push_back(u);
      const auto it = rail_of.find(edge_key(u, v));
      if (it == rail_of.end()) continue;
      const std::vector<int>& rail = rails[it->second];
      if (rail.front() == u)
        corners.insert(corners.end(), rail.begin() + 1, rail.end() - 1);
      else
        corners.insert(corners.end(), rail.rbegin() + 1, rail.rend() - 1);
    }
    arrays.faces[size_t(f)] = corners;
  }
  arrays.faces.insert(arrays.faces.end(), appended.begin(), appended.end());

  std::vector<int> selection;
  for (int v = n_vertices; v < arrays.n_vertices(); ++v) selection.push_back(v);
  Modelled out = modelled(mesh, std::move(arrays), selection);
  out.summary = "cut " + std::to_string(cuts) + (cuts == 1 ? " loop" : " loops") + " across " +
                std::to_string(r.quads.size()) + (r.quads.size() == 1 ? " quad: " : " quads: ") +
                std::to_string(selection.size()) + (selection.size() == 1 ? " vertex, " : " vertices, ") +
                std::to_string(appended.size()) + (appended.size() == 1 ? " face added" : " faces added");
  return out;
}

}  // namespace gps
