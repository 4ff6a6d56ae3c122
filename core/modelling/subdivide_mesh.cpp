#include "core/modelling/subdivide_mesh.h"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "core/support/error.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/plans/planned_surface.h"
#include "core/reference/reference_subdivision.h"

namespace gps {

namespace {

std::string counted(size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The 9D midpoints of the chosen faces' edges, made once per undirected edge.
struct Midpoints {
  std::unordered_map<uint64_t, int> of_edge;

  int make(MeshArrays& a, int u, int v) {
    const auto [it, added] = of_edge.try_emplace(edge_key(u, v), 0);
    if (added) {
      it->second = a.add_vertex(blend_gaussians(a, {{u, 0.5}, {v, 0.5}}));
      split_crease(a, u, v, it->second);
    }
    return it->second;
  }
  // The midpoint of {u, v}, or −1 when the edge is not split.
  int find(int u, int v) const {
    const auto it = of_edge.find(edge_key(u, v));
    return it == of_edge.end() ? -1 : it->second;
  }
};

// An unchosen triangle [c0, c1, c2] with midpoints m[k] on edge k (c_k → c_{k+1}; −1 where unsplit),
// as triangles.
std::vector<std::vector<int>> split_triangle(const MeshArrays& a, const std::vector<int>& c, const int m[3]) {
  const int n_split = int(m[0] >= 0) + int(m[1] >= 0) + int(m[2] >= 0);
  if (n_split == 0) return {c};
  if (n_split == 3) return {{c[0], m[0], m[2]}, {m[0], c[1], m[1]}, {m[2], m[1], c[2]}, {m[0], m[1], m[2]}};
  if (n_split == 1) {
    const int k = m[0] >= 0 ? 0 : m[1] >= 0 ? 1 : 2;
    const int u = c[size_t(k)], v = c[size_t(k + 1) % 3], w = c[size_t(k + 2) % 3], mid = m[k];
    return {{u, mid, w}, {mid, v, w}};
  }
  // Two edges split, k and k + 1, at their common corner v: the triangle at v, and the quad left over
  // cut along its shorter diagonal.
  const int k = m[0] < 0 ? 1 : m[1] < 0 ? 2 : 0;
  const int u = c[size_t(k)], v = c[size_t(k + 1) % 3], w = c[size_t(k + 2) % 3];
  const int muv = m[k], mvw = m[(k + 1) % 3];
  std::vector<std::vector<int>> quad_halves;
  if ((a.means[size_t(u)] - a.means[size_t(mvw)]).norm() <= (a.means[size_t(muv)] - a.means[size_t(w)]).norm())
    quad_halves = {{u, muv, mvw}, {u, mvw, w}};
  else
    quad_halves = {{u, muv, w}, {muv, mvw, w}};
  return {quad_halves[0], quad_halves[1], {muv, v, mvw}};
}

// The pieces of a split face with the first one holding the face's corner 0 moved to the front.
void put_corner_piece_first(std::vector<std::vector<int>>& pieces, int corner) {
  const auto holds = [corner](const std::vector<int>& p) { return std::count(p.begin(), p.end(), corner) != 0; };
  const auto it = std::find_if(pieces.begin(), pieces.end(), holds);
  std::rotate(pieces.begin(), it, it + 1);
}

}  // namespace

Modelled subdivide_all(const CovarianceMesh& mesh) {
  SubdivisionOptions options;
  options.scheme = scheme_for(mesh.topology(), PlanOptions{});
  options.levels = 1;
  SubdivisionResult r = subdivide(mesh, options);
  Modelled out{std::move(r.mesh), {}, "", {}, {}};
  out.summary = std::string("subdivided the whole mesh (") +
                (options.scheme == Scheme::loop ? "Loop" : "Catmull-Clark") +
                "): " + counted(out.mesh.n_vertices(), "vertex", "vertices") + ", " +
                counted(out.mesh.n_faces(), "face", "faces");
  return out;
}

Modelled subdivide_faces(const CovarianceMesh& mesh, const std::vector<int>& faces) {
  MeshArrays a = arrays_of(mesh);
  const std::vector<int> chosen = sorted_faces(a, faces);
  if (chosen.empty()) throw Error("no faces to subdivide");
  const int n_vertices = a.n_vertices(), n_faces = a.n_faces();
  const bool triangles = all_triangles(a);

  std::vector<int> face_points(size_t(n_faces), -1);
  Midpoints midpoints;
  for (int f : chosen) {
    const std::vector<int> face = a.faces[size_t(f)];
    if (!triangles) face_points[size_t(f)] = a.add_vertex(face_point(a, f));
    for (size_t k = 0; k < face.size(); ++k) midpoints.make(a, face[k], face[(k + 1) % face.size()]);
  }

  // The faces that change: the chosen ones and those across their edges (the rest have no midpoint).
  std::vector<int> changing;
  const MeshConnectivity& connectivity = mesh.connectivity();
  const PolygonTopology& topology = mesh.topology();
  for (const int f : chosen)
    for (int k = topology.offsets[size_t(f)]; k < topology.offsets[size_t(f) + 1]; ++k)
      for (int s = 0; s < 2; ++s)
        if (const int g = connectivity.edge_faces[2 * size_t(connectivity.face_edges[size_t(k)]) + size_t(s)]; g >= 0)
          changing.push_back(g);
  std::sort(changing.begin(), changing.end());
  changing.erase(std::unique(changing.begin(), changing.end()), changing.end());

  std::vector<int> selection;
  std::vector<std::vector<int>> appended;
  for (const int f : changing) {
    const std::vector<int> c = a.faces[size_t(f)];
    const size_t n = c.size();
    std::vector<int> mid(n);
    for (size_t k = 0; k < n; ++k) mid[k] = midpoints.find(c[k], c[(k + 1) % n]);
    std::vector<std::vector<int>> pieces;
    if (face_points[size_t(f)] >= 0) {
      for (size_t k = 0; k < n; ++k) pieces.push_back({c[k], mid[k], face_points[size_t(f)], mid[(k + n - 1) % n]});
    } else if (triangles) {
      pieces = split_triangle(a, c, mid.data());
      put_corner_piece_first(pieces, c[0]);
    } else {
      pieces.emplace_back();
      for (size_t k = 0; k < n; ++k) {
        pieces[0].push_back(c[k]);
        if (mid[k] >= 0) pieces[0].push_back(mid[k]);
      }
    }
    if (std::binary_search(chosen.begin(), chosen.end(), f))
      for (const auto& piece : pieces) selection.insert(selection.end(), piece.begin(), piece.end());
    a.faces[size_t(f)] = pieces[0];
    appended.insert(appended.end(), pieces.begin() + 1, pieces.end());
  }
  a.faces.insert(a.faces.end(), appended.begin(), appended.end());
  std::sort(selection.begin(), selection.end());
  selection.erase(std::unique(selection.begin(), selection.end()), selection.end());

  const std::string added = counted(size_t(a.n_vertices() - n_vertices), "vertex", "vertices") + ", " +
                            counted(appended.size(), "face", "faces") + " added";
  Modelled out = modelled(mesh, std::move(a), selection);
  out.summary = "subdivided " + counted(chosen.size(), "face", "faces") + ": " + added;
  return out;
}

}  // namespace gps
