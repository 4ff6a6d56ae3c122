#include "core/modelling/bevel.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/io/mesh_repair.h"
#include "core/support/error.h"
#include "core/modelling/bevel_fan.h"
#include "core/modelling/extrude.h"
#include "core/modelling/face_pieces.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/operation_words.h"

namespace gps {

namespace {

std::string vertex_name(int v) { return "vertex " + std::to_string(v); }

/// A new vertex before the width is known: its displacement from `v` per unit of width, moving along
/// the edge to `along`, or else lying in the face whose corner at v is `in` → v → `out`.
struct Spot {
  int v = -1;
  Vec3 unit_shift = Vec3::Zero();
  int along = -1, in = -1, out = -1;
  bool keep = false;  // v itself: the outer corner of a band along a boundary edge
  int vertex = -1;    // once made
};

/// The superellipse exponent of a Blender profile value (0.5 → 2, a circle; 1 → ∞, the sharp corner).
double superellipse_exponent(double profile) {
  return profile >= 1 ? std::numeric_limits<double>::infinity() : -2 * std::log(2.0) / std::log(profile);
}

class Bevel {
public:
  Bevel(const CovarianceMesh& mesh, const BevelOptions& options) : mesh_(mesh), a_(arrays_of(mesh)), o_(options) {
    if (!(std::isfinite(o_.width) && o_.width > 0))
      throw Error("width " + short_number(o_.width) + " is not a positive number");
    if (o_.segments < 1 || o_.segments > kMaxBevelSegments)
      throw Error("segments " + std::to_string(o_.segments) + " is not from 1 to " + std::to_string(kMaxBevelSegments));
    if (!(o_.profile > 0 && o_.profile <= 1)) throw Error("profile " + short_number(o_.profile) + " is not in (0, 1]");
    if (!(std::isfinite(o_.crease) && o_.crease >= 0))
      throw Error("crease " + short_number(o_.crease) + " is not a sharpness (a number ≥ 0)");
    edges_ = DirectedEdges(mesh_);
    n_vertices_ = a_.n_vertices();
    n_faces_ = a_.n_faces();
    triangles_ = std::all_of(a_.faces.begin(), a_.faces.end(), [](const auto& f) { return f.size() == 3; });
    first_corner_.assign(size_t(n_vertices_), {-1, -1});
    corner_count_.assign(size_t(n_vertices_), 0);
    for (int f = 0; f < n_faces_; ++f)
      for (int k = 0; k < int(a_.faces[size_t(f)].size()); ++k) {
        const int v = a_.faces[size_t(f)][size_t(k)];
        if (corner_count_[size_t(v)]++ == 0) first_corner_[size_t(v)] = {f, k};
      }
  }

  Modelled edges(const std::vector<std::array<int, 2>>& list) {
    if (list.empty()) throw Error("no edges are selected");
    std::set<int> ends;
    for (const auto& [x, y] : list) {
      if (!has_edge(edges_, x, y)) throw Error(edge_name(x, y) + " is not in the mesh");
      if (chosen_.insert(edge_key(x, y)).second) strips_.push_back({x, y});
      ends.insert(x), ends.insert(y);
    }
    std::vector<VertexPlan> plans;
    for (int v : ends) plans.push_back(plan_edge_ends(v));
    decide_width();
    for (Spot& s : spots_) make_spot(s);
    for (const VertexPlan& p : plans) replace_edge_ends(p);
    for (const auto& [x, y] : strips_) add_strip(x, y);
    return finish("bevelled " + count_of(strips_.size(), "edge", "edges"));
  }

  Modelled vertices(const std::vector<int>& list) {
    if (o_.width_type == BevelWidth::width || o_.width_type == BevelWidth::depth)
      throw Error(std::string("the width type \"") + (o_.width_type == BevelWidth::width ? "width" : "depth") +
                  "\" is for edges; a vertex bevel takes \"offset\" or \"percent\"");
    if (o_.crease > 0) throw Error("a crease is for edge bevels; a vertex bevel has no rims");
    if (list.empty()) throw Error("no vertices are selected");
    std::vector<VertexPlan> plans;
    for (int v : sorted_vertices(a_, list)) plans.push_back(plan_vertex(v));
    decide_width();
    for (Spot& s : spots_) make_spot(s);
    for (const VertexPlan& p : plans) replace_vertex(p);
    return finish("bevelled " + count_of(plans.size(), "vertex", "vertices"));
  }

private:
  /// A vertex the bevel replaces: its fan, and by fan edge the spots where the bevel meets it (edge
  /// bevel: left and right of a bevelled edge, the left one in the face before it; vertex bevel: on it).
  struct VertexPlan {
    Fan fan;
    std::vector<char> bevelled;
    std::vector<int> left, right;
    /// The end of a single bevelled edge at a vertex of four or more edges inside the mesh: by fan
    /// edge, the spot on each edge not beside it (−1 elsewhere).
    std::vector<int> across;
  };

  Fan fan_of(int v) const {
    if (corner_count_[size_t(v)] == 0) throw Error(vertex_name(v) + " is on no face");
    const int count = corner_count_[size_t(v)];
    // At a boundary vertex, start at the face after its incoming boundary edge.
    auto [f, k] = first_corner_[size_t(v)];
    for (int step = 0; step < count; ++step) {
      const auto& face = a_.faces[size_t(f)];
      const auto twin = edges_.place(directed_key(v, face[(size_t(k) + face.size() - 1) % face.size()]));
      if (twin.first < 0) break;
      f = twin.first;
      k = twin.second;
    }
    const int f0 = f, k0 = k;
    Fan fan;
    fan.v = v;
    do {
      const auto& face = a_.faces[size_t(f)];
      const size_t n = face.size();
      fan.faces.push_back(f);
      fan.corners.push_back(k);
      fan.around.push_back(face[(size_t(k) + n - 1) % n]);
      const auto twin = edges_.place(directed_key(face[(size_t(k) + 1) % n], v));
      if (twin.first < 0) {  // the outgoing boundary edge: the gap follows
        fan.around.push_back(face[(size_t(k) + 1) % n]);
        fan.faces.push_back(-1);
        fan.corners.push_back(-1);
        break;
      }
      f = twin.first;
      k = int((size_t(twin.second) + 1) % a_.faces[size_t(f)].size());
      if (fan.size() > count) break;
    } while (f != f0 || k != k0);
    if (fan.size() - (fan.open() ? 1 : 0) != count)
      throw Error(vertex_name(v) + " joins faces that meet only there (the mesh is not manifold at it)");
    if (!fan.open() && fan.size() < 3) throw Error(vertex_name(v) + " has fewer than three edges");
    return fan;
  }

  Vec3 mean(int v) const { return a_.means[size_t(v)]; }
  Vec3 direction(int v, int x) const { return (mean(x) - mean(v)).normalized(); }
  Vec3 face_normal(int f) const { return newell_normal(a_, f).normalized(); }

  /// The distance per unit width of the new edge beside fan edge b from it, in fan face `face` (b − 1
  /// or b): the offset as the width type gives it (Blender's offset, width, depth and percent).
  double rail_offset(const Fan& fan, int b, int face) const {
    const int v = fan.v, x = fan.neighbour(b);
    switch (o_.width_type) {
      case BevelWidth::offset:
        return 1;
      case BevelWidth::percent: {
        const int other = face == fan.at(b) ? fan.neighbour(b + 1) : fan.neighbour(b - 1);
        return direction(v, x).cross(mean(other) - mean(v)).norm() / 100;
      }
      case BevelWidth::width:
      case BevelWidth::depth: {
        // A boundary edge's band lies in its one face, from the edge to the new edge: both are the offset.
        if (fan.on_boundary(b)) return 1;
        // φ, the angle between the two faces at the edge, from their directions away from it: a band
        // across offsets o has the width 2 o sin(φ/2) and lies o cos(φ/2) from the edge.
        const Vec3 d = direction(v, x);
        const Vec3 into_before = face_normal(fan.faces[size_t(fan.at(b - 1))]).cross(d).normalized();
        const Vec3 into_after = face_normal(fan.faces[size_t(fan.at(b))]).cross(-d).normalized();
        const double phi = std::acos(std::clamp(into_before.dot(into_after), -1.0, 1.0));
        const double factor = o_.width_type == BevelWidth::width ? 2 * std::sin(phi / 2) : std::cos(phi / 2);
        if (!(factor > 1e-6))
          throw Error("the faces at " + edge_name(v, x) +
                      (o_.width_type == BevelWidth::width ? " fold onto each other" : " are flat") + ", so a " +
                      (o_.width_type == BevelWidth::width ? "width" : "depth") + " does not give an offset");
        return 1 / factor;
      }
    }
    return 1;
  }

  /// Records that spot `s` moves towards x along edge v–x by `reach` per unit width, for the clamp.
  void reaches(int s, int x) {
    const Spot& spot = spots_[size_t(s)];
    const double along = std::max(0.0, spot.unit_shift.dot(direction(spot.v, x)));
    auto [it, added] = reach_.emplace(edge_key(spot.v, x), std::array<double, 2>{0, 0});
    double& r = it->second[spot.v < x ? 0 : 1];
    r = std::max(r, along);
  }

  int add_spot(const Spot& s) {
    if (!s.unit_shift.allFinite())
      throw Error("the bevel at " + vertex_name(s.v) + " has no position (degenerate faces)");
    spots_.push_back(s);
    return int(spots_.size()) - 1;
  }

  /// How far along fan edge e, per unit width, the new edge at `offset` beside fan edge b meets it.
  double meeting_length(const Fan& fan, int b, double offset, int e) const {
    const double sine = direction(fan.v, fan.neighbour(b)).cross(direction(fan.v, fan.neighbour(e))).norm();
    if (!(sine > 1e-9))
      throw Error(edge_name(fan.v, fan.neighbour(e)) + " is in line with " + edge_name(fan.v, fan.neighbour(b)) +
                  ", so the bevel cannot meet it");
    return offset / sine;
  }

  int kept_spot(int v) {
    Spot s;
    s.v = v;
    s.keep = true;
    return add_spot(s);
  }

  int slide_spot(const Fan& fan, int e, double length) {
    Spot s;
    s.v = fan.v;
    s.along = fan.neighbour(e);
    s.unit_shift = length * direction(fan.v, s.along);
    return add_spot(s);
  }

  /// The spot in fan face i at offset w_in from its incoming edge and w_out from its outgoing one.
  int face_spot(const Fan& fan, int i, double w_in, double w_out) {
    Spot s;
    s.v = fan.v;
    s.in = fan.neighbour(i);
    s.out = fan.neighbour(i + 1);
    const Vec3 n = face_normal(fan.faces[size_t(fan.at(i))]);
    // A face's inside lies to the left of its edges: normal × edge direction.
    const Vec3 left_in = n.cross(mean(s.v) - mean(s.in)).normalized();
    const Vec3 left_out = n.cross(mean(s.out) - mean(s.v)).normalized();
    const double c = left_in.dot(left_out);
    if (1 - c * c < 1e-12) {
      if (c < 0)
        throw Error("the corner of face " + std::to_string(fan.faces[size_t(fan.at(i))]) + " at " + vertex_name(s.v) +
                    " folds back on itself");
      s.unit_shift = left_in * (w_in + w_out) / 2;
    } else {
      s.unit_shift = (w_in - c * w_out) / (1 - c * c) * left_in + (w_out - c * w_in) / (1 - c * c) * left_out;
    }
    return add_spot(s);
  }

  /// The number of fan faces from bevelled edge bevelled[j] to the next one (all of them for one).
  static int faces_to_next(const Fan& fan, const std::vector<int>& bevelled, size_t j) {
    const int m = fan.at(bevelled[(j + 1) % bevelled.size()] - bevelled[j]);
    return m == 0 ? fan.size() : m;
  }
  static std::vector<int> bevelled_edges(const VertexPlan& p) {
    std::vector<int> out;
    for (int i = 0; i < p.fan.size(); ++i)
      if (p.bevelled[size_t(i)]) out.push_back(i);
    return out;
  }

  VertexPlan plan_edge_ends(int v) {
    VertexPlan p;
    p.fan = fan_of(v);
    const Fan& fan = p.fan;
    const int n = fan.size();
    p.bevelled.assign(size_t(n), 0);
    p.left.assign(size_t(n), -1);
    p.right.assign(size_t(n), -1);
    for (int i = 0; i < n; ++i) p.bevelled[size_t(i)] = chosen_.count(edge_key(v, fan.neighbour(i))) ? 1 : 0;
    const std::vector<int> b = bevelled_edges(p);
    for (size_t j = 0; j < b.size(); ++j) {
      const int s = b[j], t = b[(j + 1) % b.size()], m = faces_to_next(fan, b, j);
      const double w_s = rail_offset(fan, s, fan.at(s)), w_t = rail_offset(fan, t, fan.at(t - 1));
      int& right = p.right[size_t(s)];
      int& left = p.left[size_t(t)];
      if (const GapInRange gap = gap_in_range(fan, s, m); gap.in) {
        // Across the gap outside a boundary: a side with faces slides along its edge next to the bevelled
        // one; a side without keeps v as the band's outer corner, one spot for both where both do.
        if (gap.after_s == 0 && gap.before_t == 0) {
          right = left = kept_spot(v);
          continue;
        }
        right = gap.after_s == 0 ? kept_spot(v) : slide_spot(fan, s + 1, meeting_length(fan, s, w_s, s + 1));
        left = gap.before_t == 0 ? kept_spot(v) : slide_spot(fan, t - 1, meeting_length(fan, t, w_t, t - 1));
        if (gap.after_s > 0) reaches(right, fan.neighbour(s + 1)), reaches(right, fan.neighbour(s));
        if (gap.before_t > 0) reaches(left, fan.neighbour(t - 1)), reaches(left, fan.neighbour(t));
        continue;
      }
      if (m == 1) {
        right = left = face_spot(fan, s, w_s, w_t);
      } else if (m == 2) {
        const double length = (meeting_length(fan, s, w_s, s + 1) + meeting_length(fan, t, w_t, s + 1)) / 2;
        right = left = slide_spot(fan, s + 1, length);
        reaches(right, fan.neighbour(s + 1));
      } else {
        right = slide_spot(fan, s + 1, meeting_length(fan, s, w_s, s + 1));
        left = slide_spot(fan, t - 1, meeting_length(fan, t, w_t, t - 1));
        reaches(right, fan.neighbour(s + 1));
        reaches(left, fan.neighbour(t - 1));
        // The end of a single bevelled edge among four or more: as Blender's, v goes, and each edge
        // not beside the bevelled one gets a vertex at the width along it (otherwise the corner
        // polygon would be v and the two spots beside it, flat where the edges across run straight on).
        if (b.size() == 1 && m >= 4) {
          p.across.assign(size_t(n), -1);
          for (int e = s + 2; e <= s + m - 2; ++e) {
            p.across[size_t(fan.at(e))] = slide_spot(fan, e, w_s);
            reaches(p.across[size_t(fan.at(e))], fan.neighbour(e));
          }
        }
      }
      reaches(right, fan.neighbour(s));
      reaches(left, fan.neighbour(t));
    }
    return p;
  }

  VertexPlan plan_vertex(int v) {
    VertexPlan p;
    p.fan = fan_of(v);
    for (int i = 0; i < p.fan.size(); ++i) {
      const int x = p.fan.neighbour(i);
      const double length = o_.width_type == BevelWidth::percent ? (mean(x) - mean(v)).norm() / 100 : 1;
      p.left.push_back(slide_spot(p.fan, i, length));
      reaches(p.left.back(), x);
    }
    return p;
  }

  /// The width the options give, reduced (or refused) where new vertices along an edge would pass
  /// each other or its end.
  void decide_width() {
    width_ = o_.width;
    double limit = std::numeric_limits<double>::infinity();
    uint64_t limiting = 0;
    for (const auto& [key, r] : reach_) {
      const int x = int(key >> 32), y = int(key & 0xffffffffu);
      if (const double sum = r[0] + r[1]; sum > 0 && (mean(y) - mean(x)).norm() / sum < limit)
        limit = (mean(y) - mean(x)).norm() / sum, limiting = key;
    }
    if (width_ > limit) {
      if (!o_.clamp)
        throw Error("a width of " + short_number(width_) + " would carry new vertices past each other on " +
                    edge_name(int(limiting >> 32), int(limiting & 0xffffffffu)) + " (at most " + short_number(limit) +
                    "; clamp limits it)");
      width_ = limit;
      clamped_ = limit < o_.width * (1 - 1e-9);  // a width at its limit but for rounding is not reported
    }
    // Vertices closer than the repair's weld tolerance coincide (core/io/mesh_repair.h), so that a
    // bevel leaves nothing the repair would weld: new vertices that near each other, or the vertex
    // their edge ends at, meet.
    met_ = RepairOptions().weld_tolerance * bounding_box_diagonal(mesh_);
    for (const auto& [key, r] : reach_) {
      const int x = int(key >> 32), y = int(key & 0xffffffffu);
      if ((mean(y) - mean(x)).norm() - width_ * (r[0] + r[1]) < met_) meet_ = true;
    }
    // A width so small that new vertices stay that near where they start is refused.
    for (const Spot& spot : spots_)
      if (!spot.keep && width_ * spot.unit_shift.norm() < met_)
        throw Error("a width of " + short_number(width_) + " would leave new vertices at " + vertex_name(spot.v) +
                    " (closer than " + short_number(met_) + ", a millionth of the mesh's size)");
  }

  void make_spot(Spot& s) {
    if (s.keep) {
      s.vertex = s.v;
      return;
    }
    const Vec3 at = mean(s.v) + width_ * s.unit_shift;
    std::vector<std::pair<int, double>> weights;
    if (s.along >= 0) {
      const double t = std::min(1.0, (at - mean(s.v)).norm() / (mean(s.along) - mean(s.v)).norm());
      weights = {{s.v, 1 - t}, {s.along, t}};
    } else {
      // Barycentric weights of the position in the corner's triangle (v, in, out), clipped to it.
      const Vec3 e1 = mean(s.in) - mean(s.v), e2 = mean(s.out) - mean(s.v), d = at - mean(s.v);
      Eigen::Matrix2d g;
      g << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
      Eigen::Vector2d w = g.ldlt().solve(Eigen::Vector2d(e1.dot(d), e2.dot(d))).cwiseMax(0.0);
      if (!w.allFinite()) w.setZero();
      if (w.sum() > 1) w /= w.sum();
      weights = {{s.v, 1 - w.sum()}, {s.in, w[0]}, {s.out, w[1]}};
    }
    s.vertex = a_.add_vertex({at, blend_gaussians(a_, weights).covariance});
  }

  /// The profile from vertex `left` to vertex `right` around the corner point: left, the
  /// segments − 1 new vertices, right.
  std::vector<int> profile(int left, int right, const Vec3& corner) {
    std::vector<int> out{left};
    const Vec3 l = mean(left), r = mean(right), origin = l + r - corner;
    const double exponent = superellipse_exponent(o_.profile);
    const int n = o_.segments;
    for (int i = 1; i < n; ++i) {
      const double theta = M_PI / 2 * double(i) / n, x = std::sin(theta), y = std::cos(theta);
      const double big = std::max(x, y);
      const double norm = std::isinf(exponent)
                              ? big
                              : big * std::pow(std::pow(x / big, exponent) + std::pow(y / big, exponent), 1 / exponent);
      const Vec3 at = origin + x / norm * (r - origin) + y / norm * (l - origin);
      const double t = double(i) / n;
      out.push_back(a_.add_vertex({at, blend_gaussians(a_, {{left, 1 - t}, {right, t}}).covariance}));
    }
    out.push_back(right);
    return out;
  }

  /// The straight profile from `left` to `right` (a band along a boundary edge ends on an edge or a
  /// face beside it, not round a corner): vertex i of n at i/n of the way, with the profile's blend.
  std::vector<int> chord(int left, int right) {
    std::vector<int> out{left};
    for (int i = 1; i < o_.segments; ++i) {
      const double t = double(i) / o_.segments;
      out.push_back(a_.add_vertex(
          {(1 - t) * mean(left) + t * mean(right), blend_gaussians(a_, {{left, 1 - t}, {right, t}}).covariance}));
    }
    out.push_back(right);
    return out;
  }

  /// Puts `by` in place of v in fan face i (nothing in the gap outside a boundary).
  void replace(const Fan& fan, int i, std::vector<int> by) {
    if (!fan.real(i)) return;
    replaced_[{fan.faces[size_t(fan.at(i))], fan.corners[size_t(fan.at(i))]}] = std::move(by);
  }

  void replace_edge_ends(const VertexPlan& p) {
    const Fan& fan = p.fan;
    const int v = fan.v;
    const std::vector<int> b = bevelled_edges(p);
    const size_t k = b.size();
    const auto vertex = [&](int spot) { return spots_[size_t(spot)].vertex; };
    // Two bevelled edges whose ranges of faces each hold one spot share their profile.
    bool shared = k == 2;
    for (size_t j = 0; j < k; ++j) shared = shared && p.right[size_t(b[j])] == p.left[size_t(b[(j + 1) % k])];

    std::map<int, std::vector<int>> profiles;
    for (size_t j = 0; j < k; ++j) {
      const int e = b[j], left = vertex(p.left[size_t(e)]), right = vertex(p.right[size_t(e)]);
      if (shared && j == 1) {
        profiles[e].assign(profiles[b[0]].rbegin(), profiles[b[0]].rend());
        continue;
      }
      // The corner the profile cuts: v where two bevelled edges meet (a mitre), else the point of the
      // edge's line across from the profile's ends; a boundary edge's band has no corner to round.
      const Vec3 d = direction(v, fan.neighbour(e));
      const Vec3 corner = shared ? mean(v) : mean(v) + ((mean(left) + mean(right)) / 2 - mean(v)).dot(d) * d;
      profiles[e] = fan.on_boundary(e) ? chord(left, right) : profile(left, right, corner);
      profile_of_[directed_key(v, fan.neighbour(e))] = profiles[e];
    }
    if (shared) profile_of_[directed_key(v, fan.neighbour(b[1]))] = profiles[b[1]];

    // The face beyond the first face after bevelled edge s keeps v; where s is a boundary edge its
    // profile runs along the edge between them, and that face takes it.
    const auto split_after = [&](int s, int right) {
      if (fan.on_boundary(s)) {
        const auto& pr = profiles[s];
        replace(fan, s + 1, std::vector<int>(pr.rbegin(), pr.rend()));
      } else {
        replace(fan, s + 1, {right, v});
      }
    };
    const auto split_before = [&](int t, int left) {
      if (fan.on_boundary(t)) {
        const auto& pr = profiles[t];
        replace(fan, t - 2, std::vector<int>(pr.rbegin(), pr.rend()));
      } else {
        replace(fan, t - 2, {v, left});
      }
    };
    for (size_t j = 0; j < k; ++j) {
      const int s = b[j], t = b[(j + 1) % k], m = faces_to_next(fan, b, j);
      const int right = vertex(p.right[size_t(s)]), left = vertex(p.left[size_t(t)]);
      replace(fan, s, {right});
      replace(fan, t - 1, {left});
      if (right != v) end_of_[directed_key(v, fan.neighbour(s + 1))] = right;
      if (left != v) end_of_[directed_key(v, fan.neighbour(t - 1))] = left;
      if (const GapInRange gap = gap_in_range(fan, s, m); gap.in) {
        if (gap.after_s >= 2) split_after(s, right);
        if (gap.before_t >= 2) split_before(t, left);
      } else if (m == 3 && k == 1) {
        const auto& pr = profiles[s];
        replace(fan, s + 1, std::vector<int>(pr.rbegin(), pr.rend()));
      } else if (m == 3) {
        replace(fan, s + 1, {right, left});
      } else if (!p.across.empty()) {
        // Faces s + 1 … t − 2 each take the spots on their two edges in place of v.
        const auto at = [&](int e) {
          return e == s + 1 ? right : e == s + m - 1 ? left : vertex(p.across[size_t(fan.at(e))]);
        };
        for (int i = s + 1; i <= s + m - 2; ++i) replace(fan, i, {at(i), at(i + 1)});
        for (int e = s + 2; e <= s + m - 2; ++e) end_of_[directed_key(v, fan.neighbour(e))] = at(e);
      } else if (m >= 4) {
        split_after(s, right);
        split_before(t, left);
      }
    }
    if (shared || (!fan.open() && k == 1 && faces_to_next(fan, b, 0) == 3)) return;
    // The polygon closing the corner: the profiles backwards, with what lies between them. Across the
    // gap outside a boundary it runs through v where a face keeps v, and else stays open (no polygon).
    std::vector<int> polygon;
    for (size_t j = k; j-- > 0;) {
      const auto& pr = profiles[b[j]];
      polygon.insert(polygon.end(), pr.rbegin(), pr.rend() - 1);
      const size_t before = (j + k - 1) % k;
      const int m = faces_to_next(fan, b, before);
      if (const GapInRange gap = gap_in_range(fan, b[before], m); gap.in) {
        if (gap.before_t == 1 && gap.after_s == 1) return;
        if (gap.before_t >= 1) polygon.push_back(pr.front());
        if (gap.after_s >= 1) polygon.push_back(v);
      } else if (!p.across.empty()) {
        polygon.push_back(pr.front());
        for (int e = b[before] + m - 2; e >= b[before] + 2; --e) polygon.push_back(vertex(p.across[size_t(fan.at(e))]));
      } else if (m >= 3) {
        polygon.push_back(pr.front());
        if (m >= 4) polygon.push_back(v);
      }
    }
    add_corner_polygon(fan, b, profiles, polygon);
  }

  /// Adds the corner's polygon less the loops through v that only follow a boundary edge's straight
  /// profile (they lie along an edge: the face beyond took them, or they are on the boundary).
  void add_corner_polygon(const Fan& fan, const std::vector<int>& b, std::map<int, std::vector<int>>& profiles,
                          std::vector<int> polygon) {
    const int v = fan.v;
    const auto first_v = std::find(polygon.begin(), polygon.end(), v);
    if (first_v != polygon.end()) {
      std::rotate(polygon.begin(), first_v, polygon.end());
      std::vector<int> kept;
      for (size_t from = 0; from < polygon.size();) {
        size_t to = from + 1;
        while (to < polygon.size() && polygon[to] != v) ++to;
        const std::vector<int> loop(polygon.begin() + long(from), polygon.begin() + long(to));
        bool straight = false;
        for (int e : b)
          if (fan.on_boundary(e))
            straight = straight || std::all_of(loop.begin(), loop.end(), [&](int x) {
                         return std::find(profiles[e].begin(), profiles[e].end(), x) != profiles[e].end();
                       });
        if (!straight) kept.insert(kept.end(), loop.begin(), loop.end());
        from = to;
      }
      polygon = kept;
    }
    if (polygon.size() >= 3) a_.faces.push_back(polygon);
  }

  void replace_vertex(const VertexPlan& p) {
    const Fan& fan = p.fan;
    const int n = fan.size();
    // At a corner of one face (valence 2) its profile is the new boundary; elsewhere the gap outside a
    // boundary gets a profile round v as a face would, the polygon's side on the boundary.
    const bool closed_by_polygon = !fan.open() || n > 2;
    std::vector<std::vector<int>> profiles;
    for (int i = 0; i < n; ++i) {
      const int from = spots_[size_t(p.left[size_t(i)])].vertex,
                to = spots_[size_t(p.left[size_t(fan.at(i + 1))])].vertex;
      end_of_[directed_key(fan.v, fan.neighbour(i))] = from;
      if (!fan.real(i) && !closed_by_polygon) continue;
      profiles.push_back(profile(from, to, mean(fan.v)));
      replace(fan, i, profiles.back());
    }
    if (!closed_by_polygon) return;
    std::vector<int> closing;
    for (size_t i = profiles.size(); i-- > 0;)
      closing.insert(closing.end(), profiles[i].rbegin(), profiles[i].rend() - 1);
    a_.faces.push_back(closing);
  }

  /// The band of quads along bevelled edge x–y, between the profiles at its ends.
  void add_strip(int x, int y) {
    // Profiles run from the face before the edge in the fan to the face after it: at x from the
    // face with x → y, at y from the face with y → x.
    const std::vector<int>& at_x = profile_of_.at(directed_key(x, y));
    const std::vector<int>& at_y_reversed = profile_of_.at(directed_key(y, x));
    const std::vector<int> at_y(at_y_reversed.rbegin(), at_y_reversed.rend());
    const size_t n = at_x.size() - 1;
    for (size_t i = 0; i < n; ++i) a_.faces.push_back({at_y[i], at_x[i], at_x[i + 1], at_y[i + 1]});
    if (o_.crease > 0) {
      a_.sharpness.set_crease(at_x[0], at_y[0], o_.crease);
      a_.sharpness.set_crease(at_x[n], at_y[n], o_.crease);
    }
  }

  Modelled finish(std::string summary) {
    // The changed faces, which must keep their orientation.
    std::map<int, Vec3> normals;
    for (const auto& [corner, by] : replaced_) normals.emplace(corner.first, newell_normal(a_, corner.first));
    for (int f = 0; f < n_faces_; ++f) {
      if (!normals.count(f)) continue;
      const auto& face = a_.faces[size_t(f)];
      std::vector<int> now;
      for (int k = 0; k < int(face.size()); ++k) {
        const auto it = replaced_.find({f, k});
        if (it == replaced_.end())
          now.push_back(face[size_t(k)]);
        else
          now.insert(now.end(), it->second.begin(), it->second.end());
      }
      a_.faces[size_t(f)] = now;
    }
    for (const auto& [f, before] : normals)
      if (newell_normal(a_, f).dot(before) < 0)
        throw Error("a width of " + short_number(width_) + " would turn face " + std::to_string(f) + " inside out");

    // Creases of the edges that remain follow their ends to the vertices that replace them.
    const auto end_of = [&](int v, int x) {
      const auto it = end_of_.find(directed_key(v, x));
      return it == end_of_.end() ? v : it->second;
    };
    for (const EdgeCrease c : std::vector<EdgeCrease>(a_.sharpness.creases)) {
      if (c.a >= n_vertices_ || c.b >= n_vertices_ || chosen_.count(edge_key(c.a, c.b))) continue;
      if (const int x = end_of(c.a, c.b), y = end_of(c.b, c.a); x != c.a || y != c.b)
        a_.sharpness.set_crease(x, y, c.sharpness);
    }

    if (triangles_)
      for (int f = 0, n = a_.n_faces(); f < n; ++f) {
        if (a_.faces[size_t(f)].size() <= 3) continue;
        std::vector<std::vector<int>> pieces{a_.faces[size_t(f)]};
        triangulate_pieces(pieces, a_.means, newell_normal(a_, f));
        a_.faces[size_t(f)] = pieces[0];
        a_.faces.insert(a_.faces.end(), pieces.begin() + 1, pieces.end());
      }

    const int n_before = a_.n_vertices();
    const std::vector<int> new_index = drop_unused_vertices(a_);
    Modelled out;
    for (int v = n_vertices_; v < n_before; ++v)
      if (new_index[size_t(v)] >= 0) out.selection.push_back(new_index[size_t(v)]);
    const size_t removed = size_t(n_vertices_ - (a_.n_vertices() - int(out.selection.size())));
    out = modelled(mesh_, a_, std::move(out.selection));
    // The band and the corners' polygons, appended after the faces the mesh had (as Blender selects them).
    for (int f = n_faces_; f < a_.n_faces(); ++f) out.selected_faces.push_back(f);
    out.summary = summary + (o_.segments > 1 ? " (" + std::to_string(o_.segments) + " segments)" : "") + ": " +
                  count_of(out.selection.size(), "vertex", "vertices") + " in place of " + std::to_string(removed) +
                  ", " + count_of(size_t(a_.n_faces() - n_faces_), "face", "faces") + " added";
    if (clamped_)
      out.summary += "; width clamped to " + short_number(width_) + " so that new vertices do not pass each other";
    // At the largest width new vertices meet one another or the vertex at the end of their edge
    // (every face of a cube bevelled on all its edges shrinks to a point): merged.
    if (meet_) {
      try {
        out = merge_met_vertices(std::move(out), met_);
      } catch (const Error& e) {
        throw Error("at a width of " + short_number(width_) + " new vertices meet, and merging them fails (" +
                    e.what() + "); give a smaller width");
      }
    }
    return out;
  }

  const CovarianceMesh& mesh_;  // the mesh the arrays were made from
  MeshArrays a_;
  const BevelOptions& o_;
  DirectedEdges edges_;
  int n_vertices_ = 0, n_faces_ = 0;
  bool triangles_ = false;
  std::vector<std::pair<int, int>> first_corner_;
  std::vector<int> corner_count_;

  std::set<uint64_t> chosen_;               // bevelled edges
  std::vector<std::array<int, 2>> strips_;  // bevelled edges, as first given
  std::vector<Spot> spots_;
  std::map<uint64_t, std::array<double, 2>> reach_;  // by edge: reach per unit width from its lower, higher end
  double width_ = 0;
  bool clamped_ = false;
  bool meet_ = false;                                         // new vertices meet at the width: merged once made
  double met_ = 0;                                            // how near vertices that meet are
  std::map<std::pair<int, int>, std::vector<int>> replaced_;  // (face, corner) → the vertices in its place
  std::map<uint64_t, std::vector<int>> profile_of_;           // directed_key(v, x): bevelled edge's profile at v
  std::map<uint64_t, int> end_of_;                            // directed_key(v, x): what replaces v on edge v–x
};

}  // namespace

bool bevel_width_named(const std::string& name, BevelWidth& type) {
  static const std::map<std::string, BevelWidth> names{{"offset", BevelWidth::offset},
                                                       {"width", BevelWidth::width},
                                                       {"depth", BevelWidth::depth},
                                                       {"percent", BevelWidth::percent}};
  const auto it = names.find(name);
  if (it == names.end()) return false;
  type = it->second;
  return true;
}

Modelled bevel_edges(const CovarianceMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                     const BevelOptions& options) {
  return Bevel(mesh, options).edges(edges);
}

Modelled bevel_vertices(const CovarianceMesh& mesh, const std::vector<int>& vertices, const BevelOptions& options) {
  return Bevel(mesh, options).vertices(vertices);
}

}  // namespace gps
