#include "core/modelling/knife.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "core/modelling/edge_operations.h"
#include "core/modelling/extrude.h"
#include "core/modelling/face_pieces.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

namespace {

// A point this close to a face, relative to the mesh's bounding-box diagonal, is on it.
constexpr double kPointOnMesh = 1e-4;
// Vertices this close to a segment's plane, relative to the diagonal, lie on it (as bisect's).
constexpr double kVertexOnCutPlane = 1e-9;
// A crossing or a point this close to an edge's end, as a fraction of the edge, is at that end.
constexpr double kSnapToEnd = 1e-3;

// Where the cut passes: a vertex a, a point on the edge a–b (a < b) at fraction t from a, or a point
// inside face `face`.
struct Place {
  enum Kind { vertex, edge, inside } kind = vertex;
  int a = -1, b = -1;
  double t = 0;
  int face = -1;
  Vec3 at = Vec3::Zero();
};

// A step of the cut: across `face` to `to`.
struct Step {
  int face;
  Place to;
};

Place at_vertex(const MeshArrays& m, int v) { return {Place::vertex, v, -1, 0, -1, m.means[size_t(v)]}; }

// The place at fraction t from u on the edge u–w: its end where within kSnapToEnd of one.
Place on_edge(const MeshArrays& m, int u, int w, double t) {
  if (t <= kSnapToEnd) return at_vertex(m, u);
  if (t >= 1 - kSnapToEnd) return at_vertex(m, w);
  if (u > w) std::swap(u, w), t = 1 - t;
  return {Place::edge, u, w, t, -1, (1 - t) * m.means[size_t(u)] + t * m.means[size_t(w)]};
}

// Whether two places are on one element: the same vertex, edge or point inside a face.
bool same_element(const Place& x, const Place& y) {
  return x.kind == y.kind && (x.kind == Place::inside ? x.at == y.at : x.a == y.a && x.b == y.b);
}

Vec3 unit_normal(const MeshArrays& m, int f) { return newell_normal(m, f).normalized(); }

// How far p is from face f's plane where it lies over the face (seen along its normal) within
// `tolerance` of that plane, allowing for how far its corners are from flat; nullopt elsewhere.
std::optional<double> over_face(const MeshArrays& m, int f, const Vec3& p, double tolerance) {
  const std::vector<int>& face = m.faces[size_t(f)];
  const Vec3 n = unit_normal(m, f);
  if (!n.allFinite()) return std::nullopt;
  Vec3 centre = Vec3::Zero();
  for (int v : face) centre += m.means[size_t(v)];
  centre /= double(face.size());
  double flatness = 0;
  for (int v : face) flatness = std::max(flatness, std::abs(n.dot(m.means[size_t(v)] - centre)));
  const double height = std::abs(n.dot(p - centre));
  if (height > tolerance + flatness) return std::nullopt;
  // Crossing number of a ray in the face's plane.
  const Vec3 x = n.unitOrthogonal(), y = n.cross(x);
  bool in = false;
  for (size_t k = 0; k < face.size(); ++k) {
    const Vec3 u = m.means[size_t(face[k])] - p, w = m.means[size_t(face[(k + 1) % face.size()])] - p;
    const double uy = y.dot(u), wy = y.dot(w);
    if ((uy > 0) != (wy > 0) && x.dot(u) + (x.dot(w) - x.dot(u)) * uy / (uy - wy) > 0) in = !in;
  }
  return in ? std::optional<double>(height) : std::nullopt;
}

// Where p lies on the mesh: on the nearest vertex or edge within `tolerance`, else inside the face
// whose plane is nearest.
std::optional<Place> place_of(const MeshArrays& m, const Vec3& p, double tolerance) {
  std::optional<Place> on_boundary, inside;
  double nearest = tolerance, lowest = 0;
  for (int f = 0; f < m.n_faces(); ++f) {
    const std::vector<int>& face = m.faces[size_t(f)];
    // Passed over where p lies farther from the corners' box than an edge or over_face could take it:
    // the tolerance and twice the box's diagonal, past any corner's distance from the face's plane.
    Vec3 low = m.means[size_t(face[0])], high = low;
    for (const int v : face) low = low.cwiseMin(m.means[size_t(v)]), high = high.cwiseMax(m.means[size_t(v)]);
    const double margin = tolerance + 2 * (high - low).norm();
    if (((low - p).array() > margin).any() || ((p - high).array() > margin).any()) continue;
    for (size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], w = face[(k + 1) % face.size()];
      const Vec3 x = m.means[size_t(u)], e = m.means[size_t(w)] - x;
      const double t = std::clamp(e.dot(p - x) / e.squaredNorm(), 0.0, 1.0);
      if (const double d = (x + t * e - p).norm(); d <= nearest) {
        nearest = d;
        on_boundary = on_edge(m, u, w, t);
      }
    }
    if (const std::optional<double> height = over_face(m, f, p, tolerance); height && (!inside || *height < lowest)) {
      lowest = *height;
      inside = Place{Place::inside, -1, -1, 0, f, p};
    }
  }
  return on_boundary ? on_boundary : inside;
}

// Whether face f holds the place (as a corner, on an edge, or inside).
bool holds(const MeshArrays& m, int f, const Place& p) {
  const std::vector<int>& face = m.faces[size_t(f)];
  if (p.kind == Place::inside) return p.face == f;
  for (size_t k = 0; k < face.size(); ++k) {
    const int u = face[k], w = face[(k + 1) % face.size()];
    if (p.kind == Place::vertex ? u == p.a : std::min(u, w) == p.a && std::max(u, w) == p.b) return true;
  }
  return false;
}

// The plane a segment of the path cuts along: through `origin` with normal `normal`; `forward` is
// the segment's direction.
struct CutPlane {
  Vec3 origin, normal, forward;
};

// Where the plane crosses face f's boundary: its corners on the plane and its edges between corners
// on opposite sides.
std::vector<Place> plane_crossings(const MeshArrays& m, int f, const CutPlane& plane, double on_plane) {
  const std::vector<int>& face = m.faces[size_t(f)];
  std::vector<double> s;
  for (int v : face) s.push_back(plane.normal.dot(m.means[size_t(v)] - plane.origin));
  std::vector<Place> out;
  for (size_t k = 0; k < face.size(); ++k) {
    const size_t l = (k + 1) % face.size();
    if (std::abs(s[k]) <= on_plane) {
      out.push_back(at_vertex(m, face[k]));
    } else if (std::abs(s[l]) > on_plane && (s[k] > 0) != (s[l] > 0)) {
      // From the edge's lower-numbered end, as bisect does.
      const bool low_first = face[k] < face[l];
      const double su = low_first ? s[k] : s[l], sw = low_first ? s[l] : s[k];
      out.push_back(on_edge(m, std::min(face[k], face[l]), std::max(face[k], face[l]), su / (su - sw)));
    }
  }
  return out;
}

// How refusals name segment i of the path.
std::string segment_name(size_t i) {
  return "the cut from point " + std::to_string(i + 1) + " to point " + std::to_string(i + 2);
}

// Where the cut running from `before` to a place inside a face, straight on along the plane, leaves the
// face: the crossing of its boundary that goes on most nearly in that direction (segment i).
Place run_on(const MeshArrays& m, const Place& inside, const Vec3& before, const CutPlane& plane, double on_plane,
             size_t i) {
  const Vec3 heading = (inside.at - before).normalized();
  std::optional<Place> best;
  double straightest = 0;
  for (const Place& c : plane_crossings(m, inside.face, plane, on_plane))
    if (const double h = heading.dot((c.at - inside.at).normalized()); h > straightest) straightest = h, best = c;
  if (!best) throw Error(segment_name(i) + " does not leave face " + std::to_string(inside.face));
  return *best;
}

// The faces the cut may go on into from a place.
std::vector<int> faces_from(const Place& p, const MeshConnectivity& faces_at, const DirectedEdges& edges) {
  if (p.kind == Place::inside) return {p.face};
  if (p.kind == Place::vertex) {
    const std::span<const int> row = faces_at.faces_of_vertex(p.a);
    return {row.begin(), row.end()};
  }
  std::vector<int> out;
  for (const int f : {face_of_edge(edges, p.a, p.b).first, face_of_edge(edges, p.b, p.a).first})
    if (f >= 0) out.push_back(f);
  return out;
}

// The normal of the surface at a place: the sum of the unit normals of the faces holding it.
Vec3 normal_at(const MeshArrays& m, const Place& p, const MeshConnectivity& faces_at, const DirectedEdges& edges) {
  Vec3 n = Vec3::Zero();
  for (const int f : faces_from(p, faces_at, edges)) n += unit_normal(m, f);
  return n.normalized();
}

// The steps of the cut from one place to the next, face by face along the plane (segment i).
std::vector<Step> walk_segment(const MeshArrays& m, const MeshConnectivity& faces_at, const DirectedEdges& edges,
                               Place from, const Place& to, const CutPlane& plane, double on_plane, size_t i) {
  std::vector<Step> steps;
  int came_from = -1;
  Vec3 previous = from.at;
  for (size_t n = 0; n <= m.faces.size(); ++n) {
    std::vector<int> ahead = faces_from(from, faces_at, edges);
    ahead.erase(std::remove(ahead.begin(), ahead.end(), came_from), ahead.end());
    if (ahead.empty()) throw Error(segment_name(i) + " leaves the mesh at its boundary");
    for (const int f : ahead)
      if (holds(m, f, to)) {
        steps.push_back({f, to});
        return steps;
      }
    // On where the cut runs straightest: from the start along the segment, then on from the last step,
    // following the plane's trace wherever the surface bends it.
    const Vec3 heading = steps.empty() ? plane.forward : (from.at - previous).normalized();
    std::optional<Step> best;
    double straightest = steps.empty() ? 0 : -2;
    for (const int f : ahead)
      for (const Place& c : plane_crossings(m, f, plane, on_plane))
        if (const double h = heading.dot((c.at - from.at).normalized()); !same_element(c, from) && h > straightest)
          straightest = h, best = Step{f, c};
    if (!best) break;
    steps.push_back(*best);
    came_from = best->face;
    previous = from.at;
    from = best->to;
  }
  throw Error(segment_name(i) + " does not reach it across the faces");
}

// The Gaussian at x inside face f: the 9D blend of its corners by mean value coordinates (Floater,
// "Mean value coordinates", 2003, Eq. 3.1): w_k ∝ (tan(α_{k−1}/2) + tan(α_k/2)) / |v_k − x|, α_k the
// angle at x from corner k to corner k + 1.
Gaussian inside_blend(const MeshArrays& m, int f, const Vec3& x) {
  const std::vector<int>& face = m.faces[size_t(f)];
  const Vec3 n = unit_normal(m, f);
  const size_t c = face.size();
  std::vector<double> tan_half(c), weight(c);
  for (size_t k = 0; k < c; ++k) {
    const Vec3 e = m.means[size_t(face[k])] - x, g = m.means[size_t(face[(k + 1) % c])] - x;
    tan_half[k] = e.cross(g).dot(n) / (e.norm() * g.norm() + e.dot(g));
  }
  double total = 0;
  for (size_t k = 0; k < c; ++k)
    total += weight[k] = (tan_half[(k + c - 1) % c] + tan_half[k]) / (m.means[size_t(face[k])] - x).norm();
  std::vector<std::pair<int, double>> weights;
  for (size_t k = 0; k < c; ++k) weights.emplace_back(face[k], weight[k] / total);
  return blend_gaussians(m, weights);
}

// Whether x and y are neighbours in one of the pieces.
bool neighbours(const std::vector<std::vector<int>>& pieces, int x, int y) {
  for (const std::vector<int>& piece : pieces)
    for (size_t k = 0; k < piece.size(); ++k) {
      const int u = piece[k], w = piece[(k + 1) % piece.size()];
      if ((u == x && w == y) || (u == y && w == x)) return true;
    }
  return false;
}

// Whether two of the chords of face f cross (or one crosses itself) between their vertices, seen
// along the face's normal: a cut so drawn would make pieces whose edges cross, which the split
// along the chords' vertices alone does not see. Segments that share a vertex do not count.
bool chords_cross(const MeshArrays& a, int f, const std::vector<std::vector<int>>& chords) {
  const Vec3 n = newell_normal(a, f), x = n.unitOrthogonal(), y = n.cross(x);
  struct Segment {
    int u, w;
    Eigen::Vector2d p, q;
  };
  std::vector<Segment> segments;
  for (const std::vector<int>& chord : chords)
    for (size_t k = 0; k + 1 < chord.size(); ++k) {
      const Vec3 &p = a.means[size_t(chord[k])], &q = a.means[size_t(chord[k + 1])];
      segments.push_back({chord[k], chord[k + 1], {p.dot(x), p.dot(y)}, {q.dot(x), q.dot(y)}});
    }
  const auto side = [](const Eigen::Vector2d& o, const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    const double d = (p - o).x() * (q - o).y() - (p - o).y() * (q - o).x();
    return (d > 0) - (d < 0);
  };
  for (size_t i = 0; i < segments.size(); ++i)
    for (size_t j = i + 1; j < segments.size(); ++j) {
      const Segment &s = segments[i], &t = segments[j];
      if (s.u == t.u || s.u == t.w || s.w == t.u || s.w == t.w) continue;
      if (side(s.p, s.q, t.p) * side(s.p, s.q, t.q) < 0 && side(t.p, t.q, s.p) * side(t.p, t.q, s.q) < 0) return true;
    }
  return false;
}

}  // namespace

Modelled knife(const CovarianceMesh& mesh, const std::vector<Vec3>& points) {
  if (points.size() < 2) throw Error("the knife needs at least 2 points, got " + std::to_string(points.size()));
  MeshArrays a = arrays_of(mesh);
  const double diagonal = bounding_box_diagonal(mesh);
  const double tolerance = kPointOnMesh * diagonal, on_plane = kVertexOnCutPlane * diagonal;
  std::vector<Place> places;
  for (size_t i = 0; i < points.size(); ++i) {
    const std::string name = "point " + std::to_string(i + 1);
    if (!points[i].allFinite()) throw Error(name + " has a number that is not finite");
    const std::optional<Place> p = place_of(a, points[i], tolerance);
    if (!p) throw Error(name + " is not on the mesh");
    if (!places.empty() && (p->at - places.back().at).norm() <= tolerance)
      throw Error(name + " is at point " + std::to_string(i));
    places.push_back(*p);
  }
  // A path that ends where it began cuts a loop (as Blender's knife closes one on its first point),
  // round at least three points: its ends are one place.
  const bool closed = places.size() > 2 && (places.back().at - places.front().at).norm() <= tolerance;
  if (closed && places.size() < 4)
    throw Error("point " + std::to_string(places.size()) +
                " closes the path on point 1 after one other point; a loop needs three points or more");
  if (closed) places.back() = places.front();

  // The cut as a start and steps, each segment along its own plane.
  // The faces at each vertex, in face order: the mesh's own rows (the arrays are still the mesh's).
  const MeshConnectivity& faces_at = mesh.connectivity();
  const DirectedEdges edges(mesh);
  Place start = places[0];
  std::vector<Step> steps;
  for (size_t i = 0; i + 1 < places.size(); ++i) {
    const Place &from = places[i], &to = places[i + 1];
    const Vec3 forward = (to.at - from.at).normalized();
    Vec3 normals = normal_at(a, from, faces_at, edges) + normal_at(a, to, faces_at, edges);
    if (!(normals.norm() > 1e-6)) normals = normal_at(a, from, faces_at, edges);
    const CutPlane plane{from.at, forward.cross(normals).normalized(), forward};
    if (!plane.normal.allFinite() || !(plane.normal.norm() > 0))
      throw Error(segment_name(i) + " runs along the surface's normal");
    const std::vector<Step> more = walk_segment(a, faces_at, edges, from, to, plane, on_plane, i);
    steps.insert(steps.end(), more.begin(), more.end());
    // A path end inside a face is moved on along the cut, away from the rest of it, to the face's edge.
    if (i + 2 == places.size() && to.kind == Place::inside && !closed)
      steps.back().to = run_on(a, to, steps.size() > 1 ? steps[steps.size() - 2].to.at : from.at, plane, on_plane, i);
    if (i == 0 && start.kind == Place::inside && !closed)
      start = run_on(a, start, steps.front().to.at, plane, on_plane, i);
  }

  // Vertices along the cut, in its order: new ones on edges (one per crossing place) and inside faces.
  const int n_faces = a.n_faces(), n_vertices = a.n_vertices();
  std::map<uint64_t, std::vector<std::pair<double, int>>> on_edges;  // by edge: (t from its lower end, vertex)
  const auto vertex_of = [&](const Place& p) {
    if (p.kind == Place::vertex) return p.a;
    if (p.kind == Place::inside) return a.add_vertex(inside_blend(a, p.face, p.at));
    std::vector<std::pair<double, int>>& cut = on_edges[edge_key(p.a, p.b)];
    for (const auto& [t, v] : cut)
      if (std::abs(t - p.t) <= 1e-12) return v;
    cut.emplace_back(p.t, add_edge_vertex(a, p.a, p.b, p.t));
    return cut.back().second;
  };
  // The cut's chords by face: from a vertex or edge place through places inside the face to the next.
  std::map<int, std::vector<std::vector<int>>> chords;
  std::vector<int> on_cut = {vertex_of(start)}, chord = on_cut;
  std::pair<int, size_t> first_chord{-1, 0};  // (face, index in chords[face]) of the cut's first chord
  for (size_t k = 0; k < steps.size(); ++k) {
    const Step& s = steps[k];
    on_cut.push_back(closed && k + 1 == steps.size() ? on_cut.front() : vertex_of(s.to));
    chord.push_back(on_cut.back());
    if (s.to.kind == Place::inside) continue;
    if (first_chord.first < 0) first_chord = {s.face, chords[s.face].size()};
    chords[s.face].push_back(chord);
    chord = {on_cut.back()};
  }
  // A loop that meets no edge would cut a hole in its face, which the knife does not.
  if (closed && first_chord.first < 0 && !steps.empty())
    throw Error("the closed path lies inside face " + std::to_string(steps.front().face) +
                " and would cut a hole in it; a loop must cross the face's edges");
  // A loop that closes inside a face: its last chord and its first are one, through the start.
  if (closed && start.kind == Place::inside && chord.size() > 1 && first_chord.first >= 0) {
    std::vector<int>& first = chords[first_chord.first][first_chord.second];
    chord.insert(chord.end(), first.begin() + 1, first.end());
    first = chord;
  }
  if (closed) on_cut.pop_back();
  for (auto& [key, cut] : on_edges) std::sort(cut.begin(), cut.end());

  // The faces the cut reaches, in order: those it has chords in and those beside the edges it splits.
  std::vector<int> reached;
  for (const auto& [f, face_chords] : chords) reached.push_back(f);
  for (const auto& [key, cut] : on_edges) {
    const int low = int(uint32_t(key >> 32)), high = int(uint32_t(key));
    for (const int f : {face_of_edge(edges, low, high).first, face_of_edge(edges, high, low).first})
      if (f >= 0) reached.push_back(f);
  }
  std::sort(reached.begin(), reached.end());
  reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  const bool triangles = all_triangles(a);
  size_t split_faces = 0;
  const std::vector<std::vector<int>> no_chords;
  for (const int f : reached) {
    const std::vector<int>& face = a.faces[size_t(f)];
    const auto found = chords.find(f);
    const std::vector<std::vector<int>>& face_chords = found == chords.end() ? no_chords : found->second;
    // The face with its edges' new vertices in order from each edge's start.
    std::vector<int> cycle;
    for (size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], w = face[(k + 1) % face.size()];
      cycle.push_back(u);
      if (const auto cut = on_edges.find(edge_key(u, w)); cut != on_edges.end()) {
        std::vector<int> between;
        for (const auto& [t, v] : cut->second) between.push_back(v);
        if (u > w) std::reverse(between.begin(), between.end());
        cycle.insert(cycle.end(), between.begin(), between.end());
      }
    }
    std::vector<std::vector<int>> pieces = {cycle};
    if (chords_cross(a, f, face_chords)) throw Error("the cut crosses itself in face " + std::to_string(f));
    for (const std::vector<int>& c : face_chords) {
      if (c.size() == 2 && neighbours(pieces, c[0], c[1])) continue;  // along an edge already there
      if (!split_along(pieces, c)) throw Error("the cut crosses itself in face " + std::to_string(f));
    }
    if (pieces.size() == 1 && cycle.size() == face.size()) continue;
    split_faces += pieces.size() > 1;
    if (triangles) triangulate_pieces(pieces, a.means, newell_normal(a, f));
    a.faces[size_t(f)] = pieces[0];
    a.faces.insert(a.faces.end(), pieces.begin() + 1, pieces.end());
  }
  if (split_faces == 0) throw Error("the cut runs along edges already there: no face is split");

  std::sort(on_cut.begin(), on_cut.end());
  on_cut.erase(std::unique(on_cut.begin(), on_cut.end()), on_cut.end());
  const std::string added = count_of(size_t(a.n_vertices() - n_vertices), "vertex", "vertices") + ", " +
                            count_of(size_t(a.n_faces() - n_faces), "face", "faces") + " added";
  Modelled out = modelled(mesh, std::move(a), on_cut);
  out.summary = "cut " + count_of(split_faces, "face", "faces") + " along " +
                count_of(points.size(), "point", "points") + ": " + added;
  return out;
}

}  // namespace gps
