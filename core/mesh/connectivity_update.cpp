#include "core/mesh/connectivity_update.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <utility>

#include "core/mesh/spare_connectivity.h"

namespace gps {

namespace {

// A corner of a new face, standing for the edge from its vertex to the next corner's: the edge's ends
// (new numbering, the lower first), its face, the corner's index in the topology's verts, and whether
// the face runs the edge from its lower end.
struct NewCorner {
  int low, high, face, corner;
  bool up;
};

bool before_key(const NewCorner& x, int low, int high) { return x.low < low || (x.low == low && x.high < high); }

// The passes over every face or vertex take them in this many blocks, one core each, and walk a block
// in runs of elements that continue old ones in order (copied or renumbered in one go).
constexpr int kBlocks = 64;

// The update's state: the old mesh, the new one, and what corresponds.
class Update {
public:
  Update(const PolygonTopology& t0, const MeshConnectivity& c0, const PolygonTopology& t, const MeshOrigins& o)
      : t0_(t0), c0_(c0), t_(t), o_(o) {}

  std::optional<MeshConnectivity> run(std::vector<int>* continued) {
    if (o_.vertices.size() != size_t(t_.n_vertices) || o_.faces.empty()) return std::nullopt;
    c_ = take_spare_connectivity();  // every array sized and every element written below
    if (!map_vertices() || !match_faces() || !collect_new_corners() || !merge_edges()) return std::nullopt;
    carry_kept_corners();
    if (makes_pillow()) return std::nullopt;
    if (kept_faces_in_order())
      carry_vertex_rows();
    else
      add_vertex_rows(t_, c_);
    if (!fans_hold()) return std::nullopt;
    if (continued) *continued = std::move(face_old_);
    return std::move(c_);
  }

private:
  int next_corner(const PolygonTopology& t, int f, int k) const {
    return k + 1 == t.offsets[size_t(f) + 1] ? t.offsets[size_t(f)] : k + 1;
  }
  int previous_corner(const PolygonTopology& t, int f, int k) const {
    return k == t.offsets[size_t(f)] ? t.offsets[size_t(f) + 1] - 1 : k - 1;
  }

  // Old vertex → new. The old vertices must keep their order: then edges ordered by their ends stay so.
  bool map_vertices() {
    vertex_new_.assign(size_t(t0_.n_vertices), -1);
    vertices_keep_numbers_ = t_.n_vertices >= t0_.n_vertices;
    int last = -1;
    for (int v = 0; v < t_.n_vertices; ++v) {
      const int w = o_.vertices[size_t(v)];
      vertices_keep_numbers_ = vertices_keep_numbers_ && w == (v < t0_.n_vertices ? v : -1);
      if (w < 0) continue;
      if (w >= t0_.n_vertices || w <= last) return false;
      vertex_new_[size_t(w)] = v;
      last = w;
    }
    return true;
  }

  // Whether new face f has the corners of old face g, renumbered.
  bool same_corners(int f, int g) const {
    if (g < 0 || g >= t0_.n_faces() || t0_.face_size(g) != t_.face_size(f)) return false;
    const int* corners = t_.verts.data() + t_.offsets[size_t(f)];
    const int* old_corners = t0_.verts.data() + t0_.offsets[size_t(g)];
    for (int k = 0; k < t_.face_size(f); ++k) {
      const int v = corners[k];
      if (v < 0 || v >= t_.n_vertices || o_.vertices[size_t(v)] != old_corners[k]) return false;
    }
    return true;
  }

  // The faces that continue an old one: the origin names it and the corners are its corners renumbered
  // (compared on all cores), the first such face where several name one. Where the old vertices keep
  // their numbers, a run of faces whose old faces follow each other, face for face of the same size,
  // is compared in one go first: the corners are then the old corners themselves.
  bool match_faces() {
    face_new_.assign(size_t(t0_.n_faces()), -1);
    face_old_.assign(size_t(t_.n_faces()), -1);
    const int n = std::min(t_.n_faces(), int(o_.faces.size()));
#pragma omp parallel for schedule(static) if (n >= kParallelFaces)
    for (int b = 0; b < kBlocks; ++b) {
      const int last = int(int64_t(n) * (b + 1) / kBlocks);
      for (int f = int(int64_t(n) * b / kBlocks); f < last;) {
        const int g = o_.faces[size_t(f)];
        int end = f + 1;
        if (vertices_keep_numbers_ && g >= 0 && g < t0_.n_faces() && t0_.face_size(g) == t_.face_size(f))
          while (end < last && o_.faces[size_t(end)] == g + (end - f) && g + (end - f) < t0_.n_faces() &&
                 t0_.face_size(g + (end - f)) == t_.face_size(end))
            ++end;
        const size_t corners = size_t(t_.offsets[size_t(end)] - t_.offsets[size_t(f)]);
        if (end - f > 1 && std::memcmp(t_.verts.data() + t_.offsets[size_t(f)],
                                       t0_.verts.data() + t0_.offsets[size_t(g)], corners * sizeof(int)) == 0) {
          for (int h = f; h < end; ++h) face_old_[size_t(h)] = g + (h - f);
        } else {
          for (int h = f; h < end; ++h)
            if (same_corners(h, o_.faces[size_t(h)])) face_old_[size_t(h)] = o_.faces[size_t(h)];
        }
        f = end;
      }
    }
    int kept = 0;
    for (int f = 0; f < n; ++f) {
      int& g = face_old_[size_t(f)];
      if (g < 0) continue;
      if (face_new_[size_t(g)] >= 0) {
        g = -1;
        continue;
      }
      face_new_[size_t(g)] = f;
      kept_faces_keep_numbers_ = kept_faces_keep_numbers_ && f == g;
      ++kept;
    }
    return 2 * kept >= t_.n_faces();  // mostly new: building the whole costs less
  }

  // The new faces' corners, each face checked as make_covariance_mesh checks it (three corners or
  // more, each a vertex of the mesh, none twice), sorted by edge and then face.
  bool collect_new_corners() {
    std::vector<int> last_face(size_t(t_.n_vertices), -1);
    for (int f = 0; f < t_.n_faces(); ++f) {
      if (face_old_[size_t(f)] >= 0) continue;
      if (t_.face_size(f) < 3) return false;
      for (int k = t_.offsets[size_t(f)]; k < t_.offsets[size_t(f) + 1]; ++k) {
        const int v = t_.verts[size_t(k)];
        if (v < 0 || v >= t_.n_vertices || last_face[size_t(v)] == f) return false;
        last_face[size_t(v)] = f;
      }
      for (int k = t_.offsets[size_t(f)]; k < t_.offsets[size_t(f) + 1]; ++k) {
        const int a = t_.verts[size_t(k)], b = t_.verts[size_t(next_corner(t_, f, k))];
        new_corners_.push_back({std::min(a, b), std::max(a, b), f, k, a < b});
      }
      touch_face(t_, f, [](int v) { return v; });
    }
    for (int g = 0; g < t0_.n_faces(); ++g)
      if (face_new_[size_t(g)] < 0) touch_face(t0_, g, [&](int v) { return vertex_new_[size_t(v)]; });
    std::sort(new_corners_.begin(), new_corners_.end(), [](const NewCorner& x, const NewCorner& y) {
      return std::array<int, 3>{x.low, x.high, x.face} < std::array<int, 3>{y.low, y.high, y.face};
    });
    return true;
  }

  // Marks the (new) vertices of face f of `t` as ones whose fan the change reaches.
  template <class ToNew>
  void touch_face(const PolygonTopology& t, int f, const ToNew& to_new) {
    if (touched_.empty()) touched_.assign(size_t(t_.n_vertices), 0);
    for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) {
      const int v = to_new(t.verts[size_t(k)]);
      if (v >= 0 && !touched_[size_t(v)]) {
        touched_[size_t(v)] = 1;
        touched_list_.push_back(v);
      }
    }
  }

  // The corner of vertex v in face g of topology t (rows of connectivity c): from the face's corners or
  // from v's row, whichever is shorter, so that neither a face of many corners nor a vertex of many
  // faces is read over and over.
  static int corner_of(const PolygonTopology& t, const MeshConnectivity& c, int v, int g) {
    const int row = c.vertex_face_offsets[size_t(v)], row_end = c.vertex_face_offsets[size_t(v) + 1];
    if (t.face_size(g) <= row_end - row) {
      for (int k = t.offsets[size_t(g)]; k < t.offsets[size_t(g) + 1]; ++k)
        if (t.verts[size_t(k)] == v) return k;
    } else {
      for (int i = row; i < row_end; ++i)
        if (c.vertex_faces[size_t(i)] == g) return t.offsets[size_t(g)] + c.vertex_face_corners[size_t(i)];
    }
    return -1;
  }

  // Whether the kept face f (old face g) runs old edge e from its lower end.
  bool kept_runs_up(int g, int e) const {
    const int low = c0_.edge_verts[2 * size_t(e)], high = c0_.edge_verts[2 * size_t(e) + 1];
    const int k = corner_of(t0_, c0_, low, g);
    return k >= 0 && t0_.verts[size_t(next_corner(t0_, g, k))] == high;
  }

  // The edges in connectivity_of's order: the old edges that a kept face still has (in their order,
  // which the vertices' order keeps) merged with the new faces' edges (sorted). The old edges are taken
  // in blocks, on all cores, each with the new corners whose edges sort between its first kept edge and
  // the next block's: counted first, then written where the counts before theirs put them.
  bool merge_edges() {
    const int n_old = c0_.n_edges();
    c_.face_edges.resize(t_.verts.size());  // every corner's edge written: here, and by carry_kept_corners
    edge_new_.assign(size_t(n_old), -1);
    const int blocks = n_old >= kParallelFaces ? kBlocks : 1;
    const auto block_edge = [&](int b) { return int(int64_t(n_old) * b / blocks); };
    // Per block, its first new corner: the first whose edge does not sort before the block's first
    // kept edge (the first block: the first); a block without kept edges takes none.
    std::vector<size_t> first_corner(size_t(blocks) + 1, new_corners_.size());
#pragma omp parallel for schedule(static) if (blocks > 1)
    for (int b = 1; b < blocks; ++b)
      for (int e = block_edge(b); e < block_edge(b + 1); ++e)
        if (kept_faces(e).second > 0) {
          const int low = vertex_new_[size_t(c0_.edge_verts[2 * size_t(e)])];
          const int high = vertex_new_[size_t(c0_.edge_verts[2 * size_t(e) + 1])];
          first_corner[size_t(b)] =
              size_t(std::partition_point(new_corners_.begin(), new_corners_.end(),
                                          [&](const NewCorner& x) { return before_key(x, low, high); }) -
                     new_corners_.begin());
          break;
        }
    first_corner[0] = 0;
    for (int b = blocks - 1; b > 0; --b)
      first_corner[size_t(b)] = std::min(first_corner[size_t(b)], first_corner[size_t(b) + 1]);
    std::vector<int> first_edge(size_t(blocks) + 1, 0);  // counts first, then where each block's edges start
    std::vector<std::vector<int>> new_edges(static_cast<size_t>(blocks));
    bool valid = true;
#pragma omp parallel for schedule(static) reduction(&& : valid) if (blocks > 1)
    for (int b = 0; b < blocks; ++b)
      valid = valid && merge_block<false>(block_edge(b), block_edge(b + 1), first_corner[size_t(b)],
                                          first_corner[size_t(b) + 1], first_edge[size_t(b) + 1], new_edges[size_t(b)]);
    if (!valid) return false;
    for (int b = 0; b < blocks; ++b) first_edge[size_t(b) + 1] += first_edge[size_t(b)];
    c_.edge_verts.resize(2 * size_t(first_edge.back()));
    c_.edge_faces.resize(2 * size_t(first_edge.back()));
#pragma omp parallel for schedule(static) if (blocks > 1)
    for (int b = 0; b < blocks; ++b) {
      int at = first_edge[size_t(b)];
      merge_block<true>(block_edge(b), block_edge(b + 1), first_corner[size_t(b)], first_corner[size_t(b) + 1], at,
                        new_edges[size_t(b)]);
    }
    for (const std::vector<int>& edges : new_edges) new_edges_.insert(new_edges_.end(), edges.begin(), edges.end());
    return true;
  }

  // Old edge e's faces that are kept, by their new numbers, and how many.
  std::pair<std::array<int, 2>, int> kept_faces(int e) const {
    int n_kept = 0;
    std::array<int, 2> kept{-1, -1};
    for (int s = 0; s < 2; ++s) {
      const int g = c0_.edge_faces[2 * size_t(e) + size_t(s)];
      if (g >= 0 && face_new_[size_t(g)] >= 0) kept[size_t(n_kept++)] = face_new_[size_t(g)];
    }
    return {kept, n_kept};
  }

  // merge_edges for old edges [e_begin, e_end) and new corners [j, j_end): counts the edges into `at`
  // (from 0), or (kWrite) writes them from edge `at` on, with the new ones in `new_edges`. False where an
  // edge would not be manifold.
  template <bool kWrite>
  bool merge_block(int e_begin, int e_end, size_t j, size_t j_end, int& at, std::vector<int>& new_edges) {
    // Where the old vertices and the kept faces keep their numbers, a run of old edges whose faces all
    // stay, before the next new face's edge, is the same edges: copied in one go.
    const bool same_numbers = vertices_keep_numbers_ && kept_faces_keep_numbers_;
    const auto stays = [&](int e) {
      const int a = c0_.edge_faces[2 * size_t(e)], b = c0_.edge_faces[2 * size_t(e) + 1];
      return a >= 0 && face_new_[size_t(a)] == a && (b < 0 || face_new_[size_t(b)] == b);
    };
    const auto before_new_corner = [&](int e) {
      if (j == j_end) return true;
      const int low = c0_.edge_verts[2 * size_t(e)], high = c0_.edge_verts[2 * size_t(e) + 1];
      return low < new_corners_[j].low || (low == new_corners_[j].low && high < new_corners_[j].high);
    };
    for (int e = e_begin; e < e_end; ++e) {
      if (same_numbers) {
        int end = e;
        while (end < e_end && stays(end) && before_new_corner(end)) ++end;
        if (end > e) {
          if constexpr (kWrite) {
            const size_t to = 2 * size_t(at), from = 2 * size_t(e), count = 2 * size_t(end - e);
            std::copy_n(c0_.edge_verts.begin() + long(from), count, c_.edge_verts.begin() + long(to));
            std::copy_n(c0_.edge_faces.begin() + long(from), count, c_.edge_faces.begin() + long(to));
            for (int k = e; k < end; ++k) edge_new_[size_t(k)] = at++;
          } else {
            at += end - e;
          }
          e = end - 1;
          continue;
        }
      }
      const auto [kept, n_kept] = kept_faces(e);
      if (n_kept == 0) continue;
      const int low = vertex_new_[size_t(c0_.edge_verts[2 * size_t(e)])];
      const int high = vertex_new_[size_t(c0_.edge_verts[2 * size_t(e) + 1])];
      while (j < j_end && before_key(new_corners_[j], low, high))
        if (!add_edge<kWrite>(-1, new_corners_[j].low, new_corners_[j].high, {-1, -1}, 0, j, j_end, at, new_edges))
          return false;
      if constexpr (kWrite) edge_new_[size_t(e)] = at;
      if (!add_edge<kWrite>(e, low, high, kept, n_kept, j, j_end, at, new_edges)) return false;
    }
    while (j < j_end)
      if (!add_edge<kWrite>(-1, new_corners_[j].low, new_corners_[j].high, {-1, -1}, 0, j, j_end, at, new_edges))
        return false;
    return true;
  }

  // Adds edge low–high as edge `at` (then advanced; written only where kWrite): old edge `e` (−1 for
  // none) with its kept faces, and the new corners from `j` on (before j_end) that run along it
  // (advancing j past them). False where it would not be manifold.
  template <bool kWrite>
  bool add_edge(int e, int low, int high, std::array<int, 2> faces, int n_kept, size_t& j, size_t j_end, int& at,
                std::vector<int>& new_edges) {
    std::array<bool, 2> up{false, false};
    int n = n_kept;
    for (; j < j_end && new_corners_[j].low == low && new_corners_[j].high == high; ++j) {
      if (n == 2) return false;  // a third face on the edge
      faces[size_t(n)] = new_corners_[j].face;
      up[size_t(n++)] = new_corners_[j].up;
      if constexpr (kWrite) c_.face_edges[size_t(new_corners_[j].corner)] = at;
    }
    // Two faces run an edge in opposite directions (a flipped face otherwise); old pairs were checked.
    if (n == 2 && n_kept < 2) {
      if (n_kept == 1) up[0] = kept_runs_up(face_old_[size_t(faces[0])], e);
      if (up[0] == up[1]) return false;
    }
    if constexpr (kWrite) {
      if (n == 2 && faces[0] > faces[1]) std::swap(faces[0], faces[1]);
      if (e < 0) new_edges.push_back(at);
      const size_t to = 2 * size_t(at);
      c_.edge_verts[to] = low;
      c_.edge_verts[to + 1] = high;
      c_.edge_faces[to] = faces[0];
      c_.edge_faces[to + 1] = faces[1];
    }
    ++at;
    return true;
  }

  // The kept faces' corners keep their old edges, renumbered: a run of kept faces whose old faces
  // follow each other has its corners one after the other in both, renumbered in one go.
  void carry_kept_corners() {
    const int n = t_.n_faces();
#pragma omp parallel for schedule(static) if (n >= kParallelFaces)
    for (int b = 0; b < kBlocks; ++b) {
      const int last = int(int64_t(n) * (b + 1) / kBlocks);
      for (int f = int(int64_t(n) * b / kBlocks); f < last;) {
        const int g = face_old_[size_t(f)];
        if (g < 0) {
          ++f;
          continue;
        }
        int end = f + 1;
        while (end < last && face_old_[size_t(end)] == g + (end - f)) ++end;
        const auto old_edges = c0_.face_edges.begin() + t0_.offsets[size_t(g)];
        std::transform(old_edges, old_edges + (t_.offsets[size_t(end)] - t_.offsets[size_t(f)]),
                       c_.face_edges.begin() + t_.offsets[size_t(f)], [&](int e) { return edge_new_[size_t(e)]; });
        f = end;
      }
    }
  }

  // Whether the kept faces keep their order: then so do they in the rows of the vertices they share.
  bool kept_faces_in_order() const {
    int last = -1;
    for (const int f : face_new_)
      if (f >= 0) {
        if (f < last) return false;
        last = f;
      }
    return true;
  }

  // The vertices' rows, as add_vertex_rows makes them (faces and edges in their order): a vertex the
  // change does not reach keeps its old row, renumbered (its faces and edges all stay, in order); the
  // others' rows are their kept faces and edges with the new ones sorted in.
  void carry_vertex_rows() {
    const int n = t_.n_vertices;
    if (touched_.empty()) touched_.assign(size_t(n), 0);
    std::vector<int> slot(size_t(n), -1);
    for (size_t i = 0; i < touched_list_.size(); ++i) slot[size_t(touched_list_[i])] = int(i);
    // A reached vertex's row: its kept faces (and edges), renumbered, and the new ones, sorted.
    std::vector<std::vector<std::array<int, 2>>> face_rows(touched_list_.size());
    std::vector<std::vector<int>> edge_rows(touched_list_.size());
    for (size_t i = 0; i < touched_list_.size(); ++i) {
      const int o = o_.vertices[size_t(touched_list_[i])];
      if (o < 0) continue;
      for (int r = c0_.vertex_face_offsets[size_t(o)]; r < c0_.vertex_face_offsets[size_t(o) + 1]; ++r)
        if (const int f = face_new_[size_t(c0_.vertex_faces[size_t(r)])]; f >= 0)
          face_rows[i].push_back({f, c0_.vertex_face_corners[size_t(r)]});
      for (int r = c0_.vertex_edge_offsets[size_t(o)]; r < c0_.vertex_edge_offsets[size_t(o) + 1]; ++r)
        if (const int e = edge_new_[size_t(c0_.vertex_edges[size_t(r)])]; e >= 0) edge_rows[i].push_back(e);
    }
    for (int f = 0; f < t_.n_faces(); ++f)
      if (face_old_[size_t(f)] < 0)
        for (int i = t_.offsets[size_t(f)], k = 0; i < t_.offsets[size_t(f) + 1]; ++i, ++k)
          face_rows[size_t(slot[size_t(t_.verts[size_t(i)])])].push_back({f, k});
    for (const int e : new_edges_)
      for (int s = 0; s < 2; ++s)
        edge_rows[size_t(slot[size_t(c_.edge_verts[2 * size_t(e) + size_t(s)])])].push_back(e);
    for (size_t i = 0; i < touched_list_.size(); ++i) {
      std::sort(face_rows[i].begin(), face_rows[i].end());
      std::sort(edge_rows[i].begin(), edge_rows[i].end());
    }
    // The rows' offsets: the old counts where the change does not reach.
    const auto count = [&](std::vector<int>& offsets, const std::vector<int>& old_offsets, auto reached_size) {
      offsets.assign(size_t(n) + 1, 0);
      for (int v = 0; v < n; ++v) {
        const int o = o_.vertices[size_t(v)];
        const int size = touched_[size_t(v)] ? reached_size(size_t(slot[size_t(v)]))
                         : o >= 0            ? old_offsets[size_t(o) + 1] - old_offsets[size_t(o)]
                                             : 0;
        offsets[size_t(v) + 1] = offsets[size_t(v)] + size;
      }
    };
    count(c_.vertex_face_offsets, c0_.vertex_face_offsets, [&](size_t i) { return int(face_rows[i].size()); });
    count(c_.vertex_edge_offsets, c0_.vertex_edge_offsets, [&](size_t i) { return int(edge_rows[i].size()); });
    c_.vertex_faces.resize(size_t(c_.vertex_face_offsets.back()));
    c_.vertex_face_corners.resize(c_.vertex_faces.size());
    c_.vertex_edges.resize(size_t(c_.vertex_edge_offsets.back()));
    // A run of vertices the change does not reach whose origins follow each other has its old rows one
    // after the other: copied (the corners; the faces too where every kept face keeps its number) or
    // renumbered in one go, a block of vertices per core.
#pragma omp parallel for schedule(static) if (n >= kParallelFaces)
    for (int b = 0; b < kBlocks; ++b) {
      const int last = int(int64_t(n) * (b + 1) / kBlocks);
      for (int v = int(int64_t(n) * b / kBlocks); v < last;) {
        if (touched_[size_t(v)]) {
          int out = c_.vertex_face_offsets[size_t(v)], edge_out = c_.vertex_edge_offsets[size_t(v)];
          const size_t i = size_t(slot[size_t(v)]);
          for (const auto& [f, k] : face_rows[i]) {
            c_.vertex_faces[size_t(out)] = f;
            c_.vertex_face_corners[size_t(out++)] = k;
          }
          for (const int e : edge_rows[i]) c_.vertex_edges[size_t(edge_out++)] = e;
          ++v;
          continue;
        }
        const int o = o_.vertices[size_t(v)];
        if (o < 0) {
          ++v;
          continue;
        }
        int end = v + 1;
        while (end < last && !touched_[size_t(end)] && o_.vertices[size_t(end)] == o + (end - v)) ++end;
        const int o_end = o + (end - v);
        const auto old_rows = [&](const std::vector<int>& offsets, const std::vector<int>& rows) {
          return std::pair(rows.begin() + offsets[size_t(o)], rows.begin() + offsets[size_t(o_end)]);
        };
        const auto [faces, faces_end] = old_rows(c0_.vertex_face_offsets, c0_.vertex_faces);
        const auto [corners, corners_end] = old_rows(c0_.vertex_face_offsets, c0_.vertex_face_corners);
        const auto [edges, edges_end] = old_rows(c0_.vertex_edge_offsets, c0_.vertex_edges);
        const auto face_out = c_.vertex_faces.begin() + c_.vertex_face_offsets[size_t(v)];
        if (kept_faces_keep_numbers_)
          std::copy(faces, faces_end, face_out);
        else
          std::transform(faces, faces_end, face_out, [&](int g) { return face_new_[size_t(g)]; });
        std::copy(corners, corners_end, c_.vertex_face_corners.begin() + c_.vertex_face_offsets[size_t(v)]);
        std::transform(edges, edges_end, c_.vertex_edges.begin() + c_.vertex_edge_offsets[size_t(v)],
                       [&](int e) { return edge_new_[size_t(e)]; });
        v = end;
      }
    }
  }

  // Whether a new face shares all its edges with one other face of its size (check_manifold's pillow).
  bool makes_pillow() const {
    for (int f = 0; f < t_.n_faces(); ++f) {
      if (face_old_[size_t(f)] >= 0) continue;
      const auto other_face = [&](int k) {
        const int e = c_.face_edges[size_t(k)];
        const int a = c_.edge_faces[2 * size_t(e)], b = c_.edge_faces[2 * size_t(e) + 1];
        return a == f ? b : a;
      };
      const int begin = t_.offsets[size_t(f)], end = t_.offsets[size_t(f) + 1];
      const int g = other_face(begin);
      if (g < 0 || t_.face_size(g) != end - begin) continue;
      bool shares_all = true;
      for (int k = begin + 1; k < end && shares_all; ++k) shares_all = other_face(k) == g;
      if (shares_all) return true;
    }
    return false;
  }

  // The faces at each vertex the change reaches form one fan, as check_manifold walks it: at most one
  // boundary edge comes into the vertex along its face, and circling from there across the corners'
  // own edges meets every face at it.
  bool fans_hold() const {
    for (const int v : touched_list_) {
      const int begin = c_.vertex_face_offsets[size_t(v)], end = c_.vertex_face_offsets[size_t(v) + 1];
      const int n_faces = end - begin;
      if (n_faces == 0) continue;
      const auto corner_at = [&](int i) {
        return t_.offsets[size_t(c_.vertex_faces[size_t(i)])] + c_.vertex_face_corners[size_t(i)];
      };
      int start = corner_at(begin), start_face = c_.vertex_faces[size_t(begin)], boundary_in = 0;
      for (int i = begin; i < end; ++i) {
        const int f = c_.vertex_faces[size_t(i)], k = corner_at(i);
        if (!c_.is_boundary_edge(c_.face_edges[size_t(previous_corner(t_, f, k))])) continue;
        if (++boundary_in > 1) return false;
        start = k;
        start_face = f;
      }
      int count = 1;
      for (int k = start, f = start_face; count <= n_faces; ++count) {
        const int e = c_.face_edges[size_t(k)];
        const int a = c_.edge_faces[2 * size_t(e)], b = c_.edge_faces[2 * size_t(e) + 1];
        const int g = a == f ? b : a;
        if (g < 0) break;
        const int at = corner_of(t_, c_, v, g);
        if (at < 0 || at == start) break;
        k = at;
        f = g;
      }
      if (count != n_faces) return false;
    }
    return true;
  }

  const PolygonTopology& t0_;
  const MeshConnectivity& c0_;
  const PolygonTopology& t_;
  const MeshOrigins& o_;
  MeshConnectivity c_;
  std::vector<int> vertex_new_, face_new_, face_old_, edge_new_;
  bool kept_faces_keep_numbers_ = true;  // every old face kept is the new face of its number
  bool vertices_keep_numbers_ = false;   // every old vertex is the new vertex of its number, the new ones after
  std::vector<int> new_edges_;  // the edges that are no old edge
  std::vector<NewCorner> new_corners_;
  std::vector<char> touched_;
  std::vector<int> touched_list_;
};

}  // namespace

std::optional<MeshConnectivity> updated_connectivity(const PolygonTopology& before, const MeshConnectivity& c,
                                                     const PolygonTopology& after, const MeshOrigins& origins,
                                                     std::vector<int>* continued) {
  return Update(before, c, after, origins).run(continued);
}

}  // namespace gps
