#include "core/io/mesh_repair.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Geometry>

#include "core/io/position_weld.h"
#include "core/mesh/face_area.h"
#include "core/support/disjoint_sets.h"

namespace gps {

namespace {

constexpr size_t kExamples = 3;

uint64_t edge_key(int a, int b) { return uint64_t(uint32_t(std::min(a, b))) << 32 | uint32_t(std::max(a, b)); }

class Repair {
public:
  Repair(PolygonSoup& soup, const RepairOptions& options) : soup_(soup), options_(options) {}

  RepairReport run() {
    const int n = int(soup_.positions.size());
    vertex_origin_.resize(size_t(n));
    std::iota(vertex_origin_.begin(), vertex_origin_.end(), 0);
    face_origin_.resize(size_t(soup_.faces.n_faces()));
    std::iota(face_origin_.begin(), face_origin_.end(), 0);
    in_file_face_.assign(size_t(n), 0);
    for (const int v : soup_.faces.verts) in_file_face_[size_t(v)] = 1;
    // The progress after each of the seven steps: 0, 1/7, ..., 1.
    constexpr int n_steps = 7;
    int done = 0;
    const auto step_done = [&] {
      if (options_.progress && !options_.progress(double(done++) / n_steps)) throw Cancelled();
    };
    step_done();
    weld();
    step_done();
    mend_repeated_corners();
    step_done();
    drop_zero_area_faces();
    step_done();
    drop_duplicate_faces();
    step_done();
    separate_fans();
    step_done();
    orient();
    step_done();
    drop_isolated_vertices();
    step_done();
    return report_;
  }

private:
  PolygonSoup& soup_;
  const RepairOptions& options_;
  RepairReport report_;
  double tolerance_ = 0;            // the weld distance
  std::vector<int> vertex_origin_;  // per vertex: the vertex of the file it is (a copy's original)
  std::vector<int> face_origin_;    // per face: the face of the file it comes from
  std::vector<char> welded_away_;   // per vertex of the file: merged into a lower one
  std::vector<char> in_file_face_;  // per vertex of the file: used by a face of the file
  std::vector<int> weld_root_;      // per vertex of the file: the vertex it was welded to (itself if none)
  std::vector<char> weld_joined_;   // per vertex of the file: others were welded to it
  std::vector<int> pair_;           // per corner: the corner across its edge (to the next corner), or −1
  std::vector<int> corner_face_;    // per corner: its face
  std::vector<int> edge_corners_, edge_offsets_;  // the corners of each edge (separate_fans)
  std::vector<int> fin_edges_;                    // the edges with more than two faces
  std::vector<char> flip_;                        // per face: reversed by orient()

  PolygonTopology& faces() { return soup_.faces; }
  int file_face(int f) const { return face_origin_[size_t(f)]; }
  void example(Defect d, const DefectExample& e) {
    auto& list = report_.examples[size_t(d)];
    if (list.size() < kExamples) list.push_back(e);
  }
  // Whether other vertices of the file were welded to vertex v.
  bool joined(int v) const { return size_t(v) < weld_joined_.size() && weld_joined_[size_t(v)]; }

  void found(Defect d, const DefectExample& e) {
    ++report_.counts[size_t(d)];
    example(d, e);
  }
  int next_corner(int f, int k) const {
    return k + 1 == soup_.faces.offsets[size_t(f) + 1] ? soup_.faces.offsets[size_t(f)] : k + 1;
  }

  // Rewrites the faces in order: `keep(f, corners, pieces)` puts in `pieces` the faces that take face
  // f's place (none drops it); `corners` holds f's and may be moved there.
  template <class Keep>
  void filter_faces(Keep keep) {
    PolygonTopology out;
    out.offsets.reserve(soup_.faces.offsets.size());
    out.verts.reserve(soup_.faces.verts.size());
    std::vector<int> origin;
    origin.reserve(face_origin_.size());
    std::vector<int> corners;
    std::vector<std::vector<int>> pieces;
    for (int f = 0; f < soup_.faces.n_faces(); ++f) {
      corners.assign(soup_.faces.verts.begin() + soup_.faces.offsets[size_t(f)],
                     soup_.faces.verts.begin() + soup_.faces.offsets[size_t(f) + 1]);
      pieces.clear();
      keep(f, corners, pieces);
      for (const auto& piece : pieces) {
        out.verts.insert(out.verts.end(), piece.begin(), piece.end());
        out.offsets.push_back(int(out.verts.size()));
        origin.push_back(face_origin_[size_t(f)]);
      }
    }
    soup_.faces = std::move(out);
    face_origin_ = std::move(origin);
  }

  // Vertices equal or within the tolerance of one another are welded to the lowest index of their
  // cluster (core/io/position_weld.h).
  void weld() {
    const auto& p = soup_.positions;
    welded_away_.assign(p.size(), 0);
    if (p.empty()) return;
    Vec3 lo = p[0], hi = p[0];
    for (const Vec3& x : p) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    tolerance_ = std::max(0.0, options_.weld_tolerance) * (hi - lo).norm();
    weld_root_ = weld_roots(p, tolerance_);
    std::vector<int> group_size(p.size(), 0);
    for (int v = 0; v < int(p.size()); ++v) ++group_size[size_t(weld_root_[size_t(v)])];
    weld_joined_.assign(p.size(), 0);
    for (size_t v = 0; v < p.size(); ++v) weld_joined_[v] = group_size[v] > 1;
    for (int v = 0; v < int(p.size()); ++v) {
      const int root = weld_root_[size_t(v)];
      if (group_size[size_t(root)] < 2) continue;
      ++report_.counts[size_t(Defect::coincident_vertices)];
      if (root == v) {
        ++report_.welded_groups;
      } else {
        welded_away_[size_t(v)] = 1;
        example(Defect::coincident_vertices, {v, root});
      }
    }
    for (int& v : soup_.faces.verts) v = weld_root_[size_t(v)];
  }

  // Repeated consecutive corners are removed; a face that still lists a vertex twice is cut there into
  // loops; loops of fewer than 3 corners are dropped, and a face with none left is degenerate.
  void mend_repeated_corners() {
    std::vector<int> position(soup_.positions.size(), -1);  // per vertex: its place on the path, or −1
    std::vector<int> path;
    filter_faces([&](int f, std::vector<int>& corners, std::vector<std::vector<int>>& pieces) {
      const size_t size = corners.size();
      corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
      while (corners.size() > 1 && corners.front() == corners.back()) corners.pop_back();
      bool repeated = corners.size() != size;
      path.clear();
      std::vector<std::vector<int>> loops;
      for (const int v : corners) {
        if (position[size_t(v)] < 0) {
          position[size_t(v)] = int(path.size());
          path.push_back(v);
          continue;
        }
        repeated = true;  // the loop from v's earlier place back to v is cut off
        const size_t from = size_t(position[size_t(v)]);
        if (path.size() - from >= 3) loops.emplace_back(path.begin() + long(from), path.end());
        for (size_t i = from + 1; i < path.size(); ++i) position[size_t(path[i])] = -1;
        path.resize(from + 1);
      }
      for (const int v : path) position[size_t(v)] = -1;
      if (path.size() >= 3) loops.insert(loops.begin(), path);
      if (!repeated) {
        pieces.push_back(corners);
        return;
      }
      found(loops.empty() ? Defect::degenerate_faces : Defect::repeated_corners, {file_face(f)});
      if (loops.size() > 1) ++report_.split_faces;
      pieces = std::move(loops);
    });
  }

  // A face whose area is at most the weld tolerance times its longest edge (its height below the
  // tolerance) has no surface to keep.
  void drop_zero_area_faces() {
    const auto& p = soup_.positions;
    filter_faces([&](int f, std::vector<int>& corners, std::vector<std::vector<int>>& pieces) {
      const auto position = [&](int v) -> const Vec3& { return p[size_t(v)]; };
      if (without_area(corners, position, tolerance_)) {
        found(Defect::zero_area_faces, {file_face(f)});
        return;
      }
      pieces.push_back(std::move(corners));
    });
  }

  // Faces on the same vertex set as an earlier one.
  void drop_duplicate_faces() {
    const PolygonTopology& t = soup_.faces;
    const int n = t.n_faces();
    std::vector<int> set, other;
    const auto sorted_set = [&](int f, std::vector<int>& out) {
      out.assign(t.verts.begin() + t.offsets[size_t(f)], t.verts.begin() + t.offsets[size_t(f) + 1]);
      std::sort(out.begin(), out.end());
    };
    // The faces sorted by a hash of their sorted vertex set (ties by index): equal sets fall in one run,
    // where each face is compared with the earlier ones kept.
    std::vector<uint64_t> hash(static_cast<size_t>(n));
    for (int f = 0; f < n; ++f) {
      sorted_set(f, set);
      uint64_t h = 1469598103934665603ull;
      for (const int v : set) h = (h ^ uint64_t(uint32_t(v))) * 1099511628211ull;
      hash[size_t(f)] = h;
    }
    std::vector<int> order(static_cast<size_t>(n)), duplicate_of(static_cast<size_t>(n), -1);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      return hash[size_t(a)] != hash[size_t(b)] ? hash[size_t(a)] < hash[size_t(b)] : a < b;
    });
    for (size_t i = 0, j = 0; i < order.size(); i = j) {
      for (j = i + 1; j < order.size() && hash[size_t(order[j])] == hash[size_t(order[i])];) ++j;
      for (size_t k = i + 1; k < j; ++k) {
        sorted_set(order[k], set);
        for (size_t l = i; l < k; ++l) {
          if (duplicate_of[size_t(order[l])] >= 0) continue;
          sorted_set(order[l], other);
          if (other != set) continue;
          duplicate_of[size_t(order[k])] = order[l];
          break;
        }
      }
    }
    filter_faces([&](int f, std::vector<int>& corners, std::vector<std::vector<int>>& pieces) {
      if (duplicate_of[size_t(f)] >= 0) {
        found(Defect::duplicate_faces, {file_face(f), file_face(duplicate_of[size_t(f)])});
        return;
      }
      pieces.push_back(std::move(corners));
    });
  }

  // Pairs the corners of each edge (pair_), then groups each vertex's corners into fans (corners joined
  // across paired edges) and gives every fan past the first its own copy of the vertex. Faces on an
  // edge left unpaired (a fin's extra faces) are so cut apart from the others there.
  void separate_fans() {
    PolygonTopology& t = faces();
    const size_t n_corners = t.verts.size();
    corner_face_.resize(n_corners);
    for (int f = 0; f < t.n_faces(); ++f)
      for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) corner_face_[size_t(k)] = f;
    group_corners_by_edge();
    pair_edges();
    std::vector<int> file_fans;  // without fins, every edge's faces are paired: the file's fans are the final ones
    if (!fin_edges_.empty()) {
      LowestRootSets file_fan_sets = fans_joining_every_face();
      file_fans = fans_per_vertex(file_fan_sets);
    }
    LowestRootSets fans = fans_of_pairs();
    while (cut_faces_meeting_again(fans)) fans = fans_of_pairs();
    std::vector<char> separated(size_t(t.n_faces()), 0);  // a face left unpaired on several fins counts once
    for (const int e : fin_edges_)
      for (int i = edge_offsets_[size_t(e)]; i < edge_offsets_[size_t(e) + 1]; ++i)
        if (const int k = edge_corners_[size_t(i)]; pair_[size_t(k)] < 0) {
          char& counted = separated[size_t(corner_face_[size_t(k)])];
          report_.fin_faces += !counted;
          counted = 1;
        }
    const std::vector<int> final_fans = fans_per_vertex(fans);
    if (fin_edges_.empty()) file_fans = final_fans;
    std::vector<int> fan_vertex(n_corners, -1);  // per fan (its root corner): the vertex it gets
    std::vector<char> claimed(soup_.positions.size(), 0);
    for (size_t k = 0; k < n_corners; ++k) {
      int& vertex = fan_vertex[size_t(fans.find(int(k)))];
      if (vertex < 0) {
        const int v = t.verts[k];
        if (!claimed[size_t(v)]) {
          claimed[size_t(v)] = 1;
          vertex = v;
        } else {
          vertex = int(vertex_origin_.size());
          vertex_origin_.push_back(vertex_origin_[size_t(v)]);
        }
      }
      t.verts[k] = vertex;
    }
    // A vertex the file's faces meet in several fans is a pinch, each fan past the first a copy; the
    // fans the fins' cuts make past those are the fins' copies.
    for (size_t v = 0; v < file_fans.size(); ++v) {
      if (file_fans[v] > 1) {
        found(Defect::pinch_vertices, {int(v), -1, file_fans[v], joined(int(v))});
        report_.pinch_copies += file_fans[v] - 1;
      }
      report_.fin_copies += final_fans[v] - file_fans[v];
    }
    edge_corners_ = {};
    edge_offsets_ = {};
    fin_edges_ = {};
  }

  int previous_corner(int f, int k) const {
    return k == soup_.faces.offsets[size_t(f)] ? soup_.faces.offsets[size_t(f) + 1] - 1 : k - 1;
  }
  int next_corner(int k) const { return next_corner(corner_face_[size_t(k)], k); }
  int lower_end(int k) const {
    return std::min(soup_.faces.verts[size_t(k)], soup_.faces.verts[size_t(next_corner(k))]);
  }

  // The corners sorted by their edge's (lower, higher) vertex, each edge's in corner order: two stable
  // counting passes (by the higher vertex, then the lower), linear whatever the valence.
  void group_corners_by_edge() {
    const PolygonTopology& t = soup_.faces;
    const size_t n_corners = t.verts.size();
    std::vector<int> low(n_corners), high(n_corners);
    for (size_t k = 0; k < n_corners; ++k) {
      const int a = t.verts[k], b = t.verts[size_t(next_corner(int(k)))];
      low[k] = std::min(a, b);
      high[k] = std::max(a, b);
    }
    std::vector<int> by_high(n_corners);
    edge_corners_.resize(n_corners);
    const auto counting_sort = [&](const std::vector<int>& digit, const auto& in, std::vector<int>& out) {
      std::vector<int> next(soup_.positions.size() + 1, 0);
      for (size_t i = 0; i < n_corners; ++i) ++next[size_t(digit[size_t(in(i))]) + 1];
      for (size_t v = 1; v < next.size(); ++v) next[v] += next[v - 1];
      for (size_t i = 0; i < n_corners; ++i) out[size_t(next[size_t(digit[size_t(in(i))])]++)] = in(i);
    };
    counting_sort(
        high, [](size_t i) { return int(i); }, by_high);
    counting_sort(
        low, [&](size_t i) { return by_high[i]; }, edge_corners_);
    edge_offsets_.assign(1, 0);
    for (size_t i = 1; i <= n_corners; ++i) {
      const int k = edge_corners_[i - 1];
      if (i == n_corners || low[size_t(edge_corners_[i])] != low[size_t(k)] ||
          high[size_t(edge_corners_[i])] != high[size_t(k)])
        edge_offsets_.push_back(int(i));
    }
  }

  // Two faces on an edge are paired, whichever way they run it (orient() flips one where both run it
  // the same way); these pairs join the faces into sheets, each face with its orientation relative to
  // its sheet. On a fin (more than two faces) the faces of one sheet are paired off, each with one that
  // runs the edge the other way once the sheet is oriented: a sheet closed across the fin stays closed
  // however its faces were flipped and wherever the extra faces come in the file. Where no sheet has
  // such two, the first face is paired with the first of another sheet that runs the edge the other
  // way (else the first of another sheet). Every pair keeps the sheets orientable: only a sheet of
  // two-face edges can be Möbius-like.
  void pair_edges() {
    const PolygonTopology& t = soup_.faces;
    pair_.assign(t.verts.size(), -1);
    ParitySets sheets(size_t(t.n_faces()));
    const auto join = [&](int k, int j) {
      pair_[size_t(k)] = j;
      pair_[size_t(j)] = k;
      sheets.unite(corner_face_[size_t(k)], corner_face_[size_t(j)], t.verts[size_t(k)] == t.verts[size_t(j)]);
    };
    const int n_edges = int(edge_offsets_.size()) - 1;
    for (int e = 0; e < n_edges; ++e)
      if (edge_offsets_[size_t(e) + 1] - edge_offsets_[size_t(e)] == 2)
        join(edge_corners_[size_t(edge_offsets_[size_t(e)])], edge_corners_[size_t(edge_offsets_[size_t(e)] + 1)]);
    struct Side {
      int sheet, side, index;  // side: which way the face runs the edge once its sheet is oriented
      bool operator<(const Side& o) const { return std::tie(sheet, side, index) < std::tie(o.sheet, o.side, o.index); }
    };
    std::vector<Side> sides;
    for (int e = 0; e < n_edges; ++e) {
      const int* c = edge_corners_.data() + edge_offsets_[size_t(e)];
      const int m = edge_offsets_[size_t(e) + 1] - edge_offsets_[size_t(e)];
      if (m <= 2) continue;
      fin_edges_.push_back(e);
      const int a = t.verts[size_t(c[0])], b = t.verts[size_t(next_corner(c[0]))];
      found(Defect::fin_edges, {std::min(a, b), std::max(a, b), m, joined(a) || joined(b)});
      sides.clear();
      for (int i = 0; i < m; ++i) {
        char parity = 0;
        const int sheet = sheets.find(corner_face_[size_t(c[i])], parity);
        sides.push_back({sheet, parity ^ (t.verts[size_t(c[i])] == a), i});
      }
      std::sort(sides.begin(), sides.end());
      bool paired = false;
      for (size_t i = 0, j = 0; i < sides.size(); i = j) {  // a sheet's faces: one side, then the other
        size_t other = i;
        for (j = i; j < sides.size() && sides[j].sheet == sides[i].sheet; ++j)
          if (sides[j].side == 0) other = j + 1;
        for (size_t q = i; q < other && other + (q - i) < j; ++q) {
          join(c[sides[q].index], c[sides[other + (q - i)].index]);
          paired = true;
        }
      }
      if (paired) continue;
      int partner = -1;
      const int sheet0 = sheets.find(corner_face_[size_t(c[0])]);
      for (int i = 1; i < m; ++i) {
        if (sheets.find(corner_face_[size_t(c[i])]) == sheet0) continue;
        if (partner < 0) partner = i;
        if (t.verts[size_t(c[i])] != a) {
          partner = i;
          break;
        }
      }
      if (partner > 0) join(c[0], c[partner]);
    }
  }

  // Joins the fans of paired corners k and j at both ends of their edge.
  void join_fans(LowestRootSets& fans, int k, int j) const {
    const int k_next = next_corner(k), j_next = next_corner(j);
    const bool same_direction = soup_.faces.verts[size_t(j)] == soup_.faces.verts[size_t(k)];
    fans.unite(k, same_direction ? j : j_next);
    fans.unite(k_next, same_direction ? j_next : j);
  }

  // The fans the file's faces make, every face on an edge joined across it (its pinches).
  LowestRootSets fans_joining_every_face() const {
    LowestRootSets fans(soup_.faces.verts.size());
    for (size_t e = 0; e + 1 < edge_offsets_.size(); ++e)
      for (int i = edge_offsets_[e] + 1; i < edge_offsets_[e + 1]; ++i)
        join_fans(fans, edge_corners_[size_t(edge_offsets_[e])], edge_corners_[size_t(i)]);
    return fans;
  }

  // The fans of the corners joined across paired edges.
  LowestRootSets fans_of_pairs() const {
    LowestRootSets fans(soup_.faces.verts.size());
    for (size_t k = 0; k < pair_.size(); ++k)
      if (pair_[k] > int(k)) join_fans(fans, int(k), pair_[k]);
    return fans;
  }

  // Per vertex: how many fans its corners make.
  std::vector<int> fans_per_vertex(LowestRootSets& fans) const {
    std::vector<int> count(soup_.positions.size(), 0);
    std::vector<char> counted(soup_.faces.verts.size(), 0);
    for (size_t k = 0; k < soup_.faces.verts.size(); ++k)
      if (char& seen = counted[size_t(fans.find(int(k)))]; !seen) {
        seen = 1;
        ++count[size_t(soup_.faces.verts[k])];
      }
    return count;
  }

  // Faces of a fin that are not paired with each other but still meet in the same fans at both of its
  // ends (an extra face joined to the kept ones through its other edges) would put more than two faces
  // on one edge again: all but one pair (else one face) of them are cut from the fan at their first
  // end, their pair on the edge and on the edge before that corner undone. Whether any was.
  bool cut_faces_meeting_again(LowestRootSets& fans) {
    const auto unpair = [&](int k) {
      if (pair_[size_t(k)] < 0) return false;
      pair_[size_t(pair_[size_t(k)])] = -1;
      pair_[size_t(k)] = -1;
      return true;
    };
    bool cut = false;
    std::vector<std::array<int, 3>> ends;  // per corner on the fin: its fans at the lower and higher end
    for (const int e : fin_edges_) {
      ends.clear();
      for (int i = edge_offsets_[size_t(e)]; i < edge_offsets_[size_t(e) + 1]; ++i) {
        const int k = edge_corners_[size_t(i)];
        const int at_k = fans.find(k), at_next = fans.find(next_corner(k));
        ends.push_back(soup_.faces.verts[size_t(k)] == lower_end(k) ? std::array{at_k, at_next, k}
                                                                    : std::array{at_next, at_k, k});
      }
      std::sort(ends.begin(), ends.end());
      for (size_t i = 0, j = 0; i < ends.size(); i = j) {
        int keep = ends[i][2];
        for (j = i; j < ends.size() && ends[j][0] == ends[i][0] && ends[j][1] == ends[i][1]; ++j)
          if (pair_[size_t(ends[j][2])] >= 0) keep = ends[j][2];
        for (size_t q = i; q < j; ++q) {
          const int k = ends[q][2];
          if (k == keep || k == pair_[size_t(keep)]) continue;
          cut |= unpair(k);
          cut |= unpair(previous_corner(corner_face_[size_t(k)], k));
        }
      }
    }
    return cut;
  }

  // Breadth-first over the paired edges, each face oriented as the face it was reached from; in each
  // part the orientation most of its faces have is kept. A paired edge that both faces run the same
  // way once both are oriented makes the part unorientable: it is left as it is.
  void orient() {
    PolygonTopology& t = faces();
    const int n_faces = t.n_faces();
    flip_.assign(size_t(n_faces), 0);
    std::vector<int> part(size_t(n_faces), -1);
    std::vector<int> queue;
    int unorientable = 0;
    for (int start = 0; start < n_faces; ++start) {
      if (part[size_t(start)] >= 0) continue;
      const int id = report_.parts++;
      bool orientable = true;
      queue.assign(1, start);
      part[size_t(start)] = id;
      for (size_t i = 0; i < queue.size(); ++i) {
        const int f = queue[i];
        for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) {
          const int j = pair_[size_t(k)];
          if (j < 0) continue;
          const int g = corner_face_[size_t(j)];
          const char flip = char(flip_[size_t(f)] ^ (t.verts[size_t(j)] == t.verts[size_t(k)]));
          if (part[size_t(g)] < 0) {
            part[size_t(g)] = id;
            flip_[size_t(g)] = flip;
            queue.push_back(g);
          } else if (flip_[size_t(g)] != flip) {
            orientable = false;
          }
        }
      }
      if (!orientable) {
        for (const int f : queue) flip_[size_t(f)] = 0;
        found(Defect::unorientable_parts, {file_face(start)});
        ++unorientable;
        continue;
      }
      size_t flipped = 0;
      for (const int f : queue) flipped += flip_[size_t(f)];
      if (2 * flipped > queue.size())
        for (const int f : queue) flip_[size_t(f)] ^= 1;
    }
    if (unorientable == 0) count_boundary_loops();
    for (int f = 0; f < n_faces; ++f) {
      if (!flip_[size_t(f)]) continue;
      found(Defect::flipped_faces, {file_face(f)});
      std::reverse(t.verts.begin() + t.offsets[size_t(f)] + 1, t.verts.begin() + t.offsets[size_t(f) + 1]);
    }
  }

  // Each boundary vertex of an oriented manifold has one boundary edge leaving it: the loops are the
  // cycles of that successor map. Read before the flipped faces are reversed (their edges run back).
  void count_boundary_loops() {
    const PolygonTopology& t = faces();
    std::vector<int> next(vertex_origin_.size(), -1);
    for (size_t k = 0; k < t.verts.size(); ++k) {
      if (pair_[k] >= 0) continue;
      const int f = corner_face_[k];
      int a = t.verts[k], b = t.verts[size_t(next_corner(f, int(k)))];
      if (flip_[size_t(f)]) std::swap(a, b);
      next[size_t(a)] = b;
    }
    report_.boundary_loops = 0;
    std::vector<char> seen(next.size(), 0);
    for (size_t v = 0; v < next.size(); ++v) {
      if (next[v] < 0 || seen[v]) continue;
      ++report_.boundary_loops;
      for (int w = int(v); w >= 0 && !seen[size_t(w)]; w = next[size_t(w)]) seen[size_t(w)] = 1;
    }
  }

  // Vertices no face uses are dropped, counted as isolated where no face of the file used them, else
  // as left without faces by the repair (welded ones are not counted again); the rest are compacted,
  // copies after the vertices of the file, each with its original's position and covariance.
  void drop_isolated_vertices() {
    const size_t n = vertex_origin_.size(), n_file = soup_.positions.size();
    std::vector<char> used(n, 0);
    for (const int v : soup_.faces.verts) used[size_t(v)] = 1;
    std::vector<int> index(n, -1), origin;
    std::vector<Vec3> positions;
    std::vector<Mat3> covariances;
    const bool has_covariances = !soup_.covariances.empty();
    for (size_t v = 0; v < n; ++v) {
      if (!used[v]) {
        if (v >= n_file || welded_away_[v]) continue;
        if (in_file_face_[v])
          ++report_.orphaned_vertices;
        else
          found(Defect::isolated_vertices, {int(v)});
        continue;
      }
      index[v] = int(positions.size());
      origin.push_back(vertex_origin_[v]);
      positions.push_back(soup_.positions[size_t(vertex_origin_[v])]);
      if (has_covariances) covariances.push_back(soup_.covariances[size_t(vertex_origin_[v])]);
    }
    for (int& v : soup_.faces.verts) v = index[size_t(v)];
    soup_.positions = std::move(positions);
    soup_.covariances = std::move(covariances);
    soup_.faces.n_vertices = int(soup_.positions.size());
    carry_sharpness(origin);
  }

  // The soup's sharpness (by vertex of the file) on the result, whose vertex v is a copy of, or is,
  // the welded vertex origin[v] of the file (see the header).
  void carry_sharpness(const std::vector<int>& origin) {
    const Sharpness& s = soup_.sharpness;
    if (s.empty()) return;
    const auto root = [&](int v) { return weld_root_.empty() ? v : weld_root_[size_t(v)]; };
    std::unordered_map<uint64_t, double> crease_of;  // by the welded ends' pair
    for (const EdgeCrease& c : s.creases) {
      double& sharpness = crease_of[edge_key(root(c.a), root(c.b))];
      sharpness = std::max(sharpness, c.sharpness);
    }
    Sharpness out;
    std::unordered_set<uint64_t> done, kept;  // edges of the result; the file's pairs found on them
    const PolygonTopology& t = soup_.faces;
    for (int f = 0; f < t.n_faces(); ++f)
      for (int k = t.offsets[size_t(f)]; k < t.offsets[size_t(f) + 1]; ++k) {
        const int u = t.verts[size_t(k)], w = t.verts[size_t(next_corner(f, k))];
        const uint64_t pair = edge_key(origin[size_t(u)], origin[size_t(w)]);
        const auto it = crease_of.find(pair);
        if (it == crease_of.end() || !done.insert(edge_key(u, w)).second) continue;
        kept.insert(pair);
        out.creases.push_back({std::min(u, w), std::max(u, w), it->second});
      }
    for (const EdgeCrease& c : s.creases) report_.dropped_creases += !kept.count(edge_key(root(c.a), root(c.b)));
    if (!s.corners.empty()) {
      std::vector<double> group_corner(s.corners.size(), 0.0);
      for (int v = 0; v < int(s.corners.size()); ++v)
        group_corner[size_t(root(v))] = std::max(group_corner[size_t(root(v))], s.corners[size_t(v)]);
      out.corners.resize(origin.size());
      for (size_t v = 0; v < origin.size(); ++v) out.corners[v] = group_corner[size_t(origin[v])];
    }
    out.normalise();
    soup_.sharpness = std::move(out);
  }
};

}  // namespace

RepairReport repair_polygon_soup(PolygonSoup& soup, const RepairOptions& options) {
  return Repair(soup, options).run();
}

RepairReport diagnose_polygon_soup(const PolygonSoup& soup, const RepairOptions& options) {
  PolygonSoup copy = soup;
  return repair_polygon_soup(copy, options);
}

}  // namespace gps
