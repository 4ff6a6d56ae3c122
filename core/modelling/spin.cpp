#include "core/modelling/spin.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/modelling/affine_transform.h"
#include "core/modelling/extrude.h"
#include "core/modelling/operation_words.h"
#include "core/plans/plan_builder.h"
#include "core/support/error.h"

namespace gps {

namespace {

// Vertices this close to the axis, relative to the mesh's bounding-box diagonal, lie on it.
constexpr double kOnAxis = 1e-9;
constexpr int kMostSteps = 1000;

}  // namespace

Modelled spin(const CovarianceMesh& mesh, const std::vector<int>& vertices, const Vec3& axis, const Vec3& center,
              double degrees, int steps) {
  if (!axis.allFinite() || !center.allFinite() || !std::isfinite(degrees))
    throw Error("the spin has a number that is not finite");
  if (!(axis.norm() > 0)) throw Error("the spin's axis is zero");
  if (degrees == 0 || std::abs(degrees) > 360)
    throw Error("the angle must be from -360 to 360 degrees and not 0, got " + short_number(degrees));
  const bool full_turn = std::abs(degrees) == 360;
  if (steps < (full_turn ? 3 : 1) || steps > kMostSteps)
    throw Error("the steps must be from " + std::string(full_turn ? "3 (a full turn)" : "1") + " to " +
                std::to_string(kMostSteps) + ", got " + std::to_string(steps));
  MeshArrays a = arrays_of(mesh);
  for (const int v : vertices) check_vertex(a, v);
  if (vertices.size() < 2)
    throw Error("the profile has " + count_of(vertices.size(), "vertex", "vertices") + " (2 needed)");
  const bool loop = vertices.size() > 2 && vertices.front() == vertices.back();
  const std::vector<int> profile(vertices.begin(), vertices.end() - (loop ? 1 : 0));
  if (loop && profile.size() < 3) throw Error("a loop needs 3 vertices");
  std::vector<int> sorted = profile;
  std::sort(sorted.begin(), sorted.end());
  if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
    throw Error("vertex " + std::to_string(*twice) + " is twice in the profile");

  // The profile's edges (positions in it), and which way the quads run: against the faces of its edges.
  std::vector<std::array<size_t, 2>> edges;
  for (size_t i = 0; i + 1 < profile.size(); ++i) edges.push_back({i, i + 1});
  if (loop) edges.push_back({profile.size() - 1, 0});
  const DirectedEdges directed(mesh);
  int direction = 0;  // 1: (u_k, v_k, v_k+1, u_k+1) for profile edge u → v; −1: reversed; 0: not yet known
  for (const auto& [i, j] : edges) {
    const int u = profile[i], v = profile[j];
    const bool forward = directed.count(directed_key(u, v)) != 0, backward = directed.count(directed_key(v, u)) != 0;
    if (forward && backward)
      throw Error(edge_name(u, v) + " has faces on both sides (a spin from it would join three)");
    if ((forward || backward) && full_turn)
      throw Error(edge_name(u, v) + " is an edge of the mesh (a full turn would close on it beside its face)");
    const int wanted = forward ? -1 : backward ? 1 : 0;
    if (wanted != 0 && direction != 0 && wanted != direction)
      throw Error("the profile runs along boundary edges of opposite directions (" + edge_name(u, v) + ")");
    if (wanted != 0) direction = wanted;
  }

  const Vec3 unit = axis.normalized();
  const double tolerance = kOnAxis * bounding_box_diagonal(mesh);
  const auto from_axis = [&](const Vec3& x) {
    const Vec3 r = x - center;
    return Vec3(r - unit * unit.dot(r));
  };
  std::vector<char> on_axis;
  for (const int v : profile) on_axis.push_back(from_axis(a.means[size_t(v)]).norm() <= tolerance);

  // A vertex on the axis gets a triangle per step from each profile edge at it that leaves the axis.
  for (size_t i = 0; i < profile.size(); ++i) {
    if (!on_axis[i]) continue;
    int leaving = 0;
    for (const auto& [p, q] : edges) leaving += (p == i || q == i) && !(on_axis[p] && on_axis[q]);
    if (leaving == 0) continue;
    const int faces = mesh.connectivity().n_vertex_faces(profile[i]);
    if (faces + leaving * steps > kMaxPlanValence)
      throw Error("vertex " + std::to_string(profile[i]) + " lies on the axis, so " + std::to_string(steps) +
                  " steps would give it " + std::to_string(faces + leaving * steps) +
                  " faces; a surface's patch plans take up to " + std::to_string(kMaxPlanValence) + " (at most " +
                  std::to_string(std::max(0, (kMaxPlanValence - faces) / leaving)) + " steps here)");
  }

  // at[k][i]: profile vertex i after k steps; the last step of a full turn is the profile itself.
  const int last_copy = full_turn ? steps - 1 : steps;
  std::vector<std::vector<int>> at(size_t(steps) + 1, profile);
  for (int k = 1; k <= last_copy; ++k) {
    const double angle = degrees * M_PI / 180.0 * k / steps;
    const AffineMap rotation = AffineMap::about(center, Eigen::AngleAxisd(angle, unit).toRotationMatrix());
    for (size_t i = 0; i < profile.size(); ++i)
      if (!on_axis[i]) at[size_t(k)][i] = a.add_vertex(rotation.apply(a.gaussian(profile[i])));
  }

  const size_t first_face = a.faces.size();
  for (const auto& [i, j] : edges) {
    if (on_axis[i] && on_axis[j]) continue;
    for (size_t k = 0; k < size_t(steps); ++k) {
      std::vector<int> face = {at[k][i], at[k][j], at[k + 1][j], at[k + 1][i]};
      face.erase(std::unique(face.begin(), face.end()), face.end());
      if (face.front() == face.back()) face.pop_back();
      a.faces.push_back(std::move(face));
    }
  }
  if (a.faces.size() == first_face) throw Error("the profile lies on the axis (nothing to spin)");
  if (direction == 0) {
    // Facing away from the axis: the flux of the unit radial field through the band, positive for a
    // closed surface of revolution oriented outward (its divergence 1/r is positive).
    double flux = 0;
    for (size_t f = first_face; f < a.faces.size(); ++f) {
      Vec3 centroid = Vec3::Zero();
      for (const int v : a.faces[f]) centroid += a.means[size_t(v)] / double(a.faces[f].size());
      const Vec3 radial = from_axis(centroid);
      if (radial.norm() > 0) flux += newell_normal(a, int(f)).dot(radial.normalized());
    }
    direction = flux < 0 ? -1 : 1;
  }
  if (direction < 0)
    for (size_t f = first_face; f < a.faces.size(); ++f) std::reverse(a.faces[f].begin() + 1, a.faces[f].end());

  const Sharpness before = a.sharpness;
  for (int k = 1; k <= last_copy; ++k) {
    for (const auto& [i, j] : edges)
      if (const double crease = before.crease(profile[i], profile[j]); crease > 0 && !(on_axis[i] && on_axis[j]))
        a.sharpness.set_crease(at[size_t(k)][i], at[size_t(k)][j], crease);
    for (size_t i = 0; i < profile.size(); ++i)
      if (const double corner = before.corner(profile[i]); corner > 0 && !on_axis[i])
        a.sharpness.set_corner(at[size_t(k)][i], corner, a.n_vertices());
  }

  std::vector<int> selection = at[size_t(steps)];
  std::sort(selection.begin(), selection.end());
  const size_t added_vertices = size_t(a.n_vertices()) - mesh.n_vertices();
  Modelled out = modelled(mesh, std::move(a), selection);
  out.summary = "spun " + count_of(profile.size(), "vertex", "vertices") + " by " + short_number(degrees) + "° in " +
                count_of(size_t(steps), "step", "steps") + ": " + count_of(added_vertices, "vertex", "vertices") +
                ", " + count_of(a.faces.size() - first_face, "face", "faces") + " added";
  return out;
}

}  // namespace gps
