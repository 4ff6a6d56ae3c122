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

std::vector<int> topology_of_faces(const PolyMesh& m) {
  std::vector<int> out;
  for (const auto f : m.faces()) {
    out.push_back(int(m.valence(f)));
    for (const auto v : m.fv_range(f)) out.push_back(v.idx());
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
  const PolyMesh& m = mesh.mesh;
  const auto h = m.find_halfedge(m.vertex_handle(a), m.vertex_handle(b));
  if (!h.is_valid()) return false;
  bool has_face = false;
  for (const auto side : {h, m.opposite_halfedge_handle(h)}) {
    const auto f = m.face_handle(side);
    if (!f.is_valid()) continue;
    if (!face_hidden(f.idx())) return false;
    has_face = true;
  }
  return has_face;
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
  std::vector<char> mask(mesh.mesh.n_edges(), 0);
  if (empty()) return mask;
  for (const auto e : mesh.mesh.edges()) mask[size_t(e.idx())] = edge_hidden(mesh, e.v0().idx(), e.v1().idx());
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
  for (const auto e : mesh.mesh.edges()) {
    const int a = e.v0().idx(), b = e.v1().idx();
    if (edge_hidden(mesh, a, b)) out.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

size_t HiddenElements::hide(const CovarianceMesh& mesh, Selection& selection, SelectMode mode, bool unselected) {
  const PolyMesh& m = mesh.mesh;
  std::vector<int> faces, vertices;
  if (mode == SelectMode::vertex) {
    vertices = unselected ? complement(m.n_vertices(), selection.vertices()) : selection.vertices();
    for (const auto f : m.faces())
      for (const auto v : m.fv_range(f))
        if (std::binary_search(vertices.begin(), vertices.end(), v.idx())) {
          faces.push_back(f.idx());
          break;
        }
  } else if (mode == SelectMode::edge) {
    const std::vector<EdgeEnds> selected = selection.edges(mesh);
    for (const auto f : m.faces())
      for (const auto h : m.fh_range(f)) {
        const int a = m.from_vertex_handle(h).idx(), b = m.to_vertex_handle(h).idx();
        const bool is_selected =
            std::binary_search(selected.begin(), selected.end(), EdgeEnds{std::min(a, b), std::max(a, b)});
        if (is_selected != unselected) {
          faces.push_back(f.idx());
          break;
        }
      }
  } else {
    const std::vector<int> selected = selection.faces(mesh);
    faces = unselected ? complement(m.n_faces(), selected) : selected;
  }
  const size_t before = faces_.size();
  topology_ = topology_of_faces(m);
  faces_ = united(faces_, sorted(faces));
  vertices_ = united(vertices_, vertices);
  if (mode != SelectMode::vertex) {  // a vertex goes with its last face
    std::vector<int> last;
    for (const auto v : m.vertices()) {
      bool any = false, all = true;
      for (const auto f : m.vf_range(v)) any = true, all = all && face_hidden(f.idx());
      if (any && all) last.push_back(v.idx());
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

bool HiddenElements::fits(const CovarianceMesh& mesh) const {
  return empty() || topology_ == topology_of_faces(mesh.mesh);
}

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
