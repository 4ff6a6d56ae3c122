#include "ui/editing/hidden_elements.h"

#include <algorithm>
#include <iterator>

#include "core/modelling/mesh_queries.h"

namespace gps {

namespace {

// `a` ∪ `b`, both ascending.
std::vector<int> united(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// The indices [0, n) not in `taken` (ascending).
std::vector<int> complement(size_t n, const std::vector<int>& taken) {
  std::vector<int> out;
  for (size_t i = 0; i < n; ++i)
    if (!std::binary_search(taken.begin(), taken.end(), int(i))) out.push_back(int(i));
  return out;
}

std::vector<int> topology_of_faces(const CovarianceMesh& m) {
  std::vector<int> out;
  for (size_t f = 0; f < m.n_faces(); ++f) {
    out.push_back(m.face_size(f));
    for (const int v : m.face(f)) out.push_back(v);
  }
  out.push_back(int(m.n_vertices()));
  return out;
}

}  // namespace

bool HiddenElements::face_hidden(int face) const { return std::binary_search(faces_.begin(), faces_.end(), face); }

bool HiddenElements::vertex_hidden(int vertex) const {
  return std::binary_search(vertices_.begin(), vertices_.end(), vertex);
}

bool HiddenElements::edge_hidden(const CovarianceMesh& mesh, int a, int b) const {
  if (vertex_hidden(a) || vertex_hidden(b)) return true;
  if (faces_.empty()) return false;
  const int e = mesh.find_edge(a, b);
  if (e < 0) return false;
  const std::vector<int>& sides = mesh.connectivity().edge_faces;  // the second is −1 on a boundary
  return face_hidden(sides[2 * size_t(e)]) && (sides[2 * size_t(e) + 1] < 0 || face_hidden(sides[2 * size_t(e) + 1]));
}

std::vector<char> HiddenElements::vertex_mask(size_t n_vertices) const {
  std::vector<char> mask(n_vertices, 0);
  for (const int v : vertices_)
    if (size_t(v) < n_vertices) mask[size_t(v)] = 1;
  return mask;
}

std::vector<char> HiddenElements::face_mask(size_t n_faces) const {
  std::vector<char> mask(n_faces, 0);
  for (const int f : faces_)
    if (size_t(f) < n_faces) mask[size_t(f)] = 1;
  return mask;
}

std::vector<char> HiddenElements::edge_mask(const CovarianceMesh& mesh) const {
  std::vector<char> mask(mesh.n_edges(), 0);
  if (empty()) return mask;
  for (size_t e = 0; e < mesh.n_edges(); ++e) mask[e] = edge_hidden(mesh, mesh.edge(e)[0], mesh.edge(e)[1]);
  return mask;
}

std::vector<int> HiddenElements::shown(const std::vector<int>& vertices) const {
  std::vector<int> out;
  for (const int v : vertices)
    if (!vertex_hidden(v)) out.push_back(v);
  return out;
}

std::vector<EdgeEnds> HiddenElements::edges(const CovarianceMesh& mesh) const {
  std::vector<EdgeEnds> out;
  if (empty()) return out;
  for (size_t e = 0; e < mesh.n_edges(); ++e)
    if (edge_hidden(mesh, mesh.edge(e)[0], mesh.edge(e)[1])) out.push_back(mesh.edge(e));
  std::sort(out.begin(), out.end());
  return out;
}

size_t HiddenElements::hide(const CovarianceMesh& mesh, Selection& selection, SelectMode mode, bool unselected) {
  const PolygonTopology& t = mesh.topology();
  const MeshConnectivity& c = mesh.connectivity();
  std::vector<int> faces, vertices;
  if (mode == SelectMode::vertex) {
    vertices = unselected ? complement(mesh.n_vertices(), selection.vertices()) : selection.vertices();
    for (size_t f = 0; f < mesh.n_faces(); ++f)
      for (const int v : mesh.face(f))
        if (std::binary_search(vertices.begin(), vertices.end(), v)) {
          faces.push_back(int(f));
          break;
        }
  } else if (mode == SelectMode::edge) {
    const std::vector<EdgeEnds> selected = selection.edges(mesh);
    for (int f = 0; f < t.n_faces(); ++f)
      for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) {
        const EdgeEnds ends = mesh.edge(size_t(c.face_edges[size_t(k)]));
        const bool is_selected = std::binary_search(selected.begin(), selected.end(), ends);
        if (is_selected != unselected) {
          faces.push_back(f);
          break;
        }
      }
  } else {
    const std::vector<int> selected = selection.faces(mesh);
    faces = unselected ? complement(mesh.n_faces(), selected) : selected;
  }
  const size_t before = faces_.size();
  topology_ = topology_of_faces(mesh);
  faces_ = united(faces_, sorted(faces));
  vertices_ = united(vertices_, vertices);
  if (mode != SelectMode::vertex) {  // a vertex goes with its last face
    std::vector<int> last;
    for (int v = 0; v < int(mesh.n_vertices()); ++v) {
      bool all = true;
      for (int k = c.vertex_face_offsets[size_t(v)]; k < c.vertex_face_offsets[size_t(v) + 1]; ++k)
        all = all && face_hidden(c.vertex_faces[size_t(k)]);
      if (c.n_vertex_faces(v) > 0 && all) last.push_back(v);
    }
    vertices_ = united(vertices_, last);
  }
  if (mode == SelectMode::face && !unselected) selection.deselect_faces(mesh, faces);
  deselect_hidden(mesh, selection, mode);
  return faces_.size() - before;
}

size_t HiddenElements::reveal(const CovarianceMesh& mesh, Selection& selection, SelectMode mode) {
  const size_t shown_faces = faces_.size();
  if (mode == SelectMode::edge) {
    selection.select_edges(mesh, edges(mesh), true);
  } else if (mode == SelectMode::face) {
    selection.select_faces(mesh, faces_, true);
  } else {
    selection.select(vertices_, true);
  }
  clear();
  return shown_faces;
}

bool HiddenElements::fits(const CovarianceMesh& mesh) const { return empty() || topology_ == topology_of_faces(mesh); }

void HiddenElements::deselect_hidden(const CovarianceMesh& mesh, Selection& selection, SelectMode mode) const {
  if (empty() || selection.empty()) return;
  if (mode == SelectMode::edge) {
    std::vector<EdgeEnds> hidden;
    for (const EdgeEnds& e : selection.edges(mesh))
      if (edge_hidden(mesh, e[0], e[1])) hidden.push_back(e);
    if (!hidden.empty()) selection.deselect_edges(mesh, hidden);
    return;
  }
  if (mode == SelectMode::face) {
    std::vector<int> hidden;
    for (const int f : selection.faces(mesh))
      if (face_hidden(f)) hidden.push_back(f);
    if (!hidden.empty()) selection.deselect_faces(mesh, hidden);
    return;
  }
  std::vector<int> hidden;
  for (const int v : selection.vertices())
    if (vertex_hidden(v)) hidden.push_back(v);
  if (!hidden.empty()) selection.deselect(hidden);
}

}  // namespace gps
