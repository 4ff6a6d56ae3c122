#include "core/modelling/inset.h"

#include <Eigen/Geometry>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>

#include "core/mesh/dual_map.h"
#include "core/support/error.h"
#include "core/modelling/extrude.h"
#include "core/modelling/operation_words.h"

namespace gps {

namespace {

// Per face of the region, read once: its Newell normal and the 9D average of its corners (its face
// point's q). Every sector of a face reads them, so a face of n corners costs O(n), not O(n²).
class FaceSums {
public:
  explicit FaceSums(const MeshArrays& a) : a_(a) {}
  const std::pair<Vec3, Dual>& of(int f) {
    const auto [it, added] = sums_.try_emplace(f);
    if (added) {
      const auto& face = a_.faces[size_t(f)];
      Dual q = Dual::Zero();
      for (int v : face) q += to_dual(a_.means[size_t(v)], a_.covariances[size_t(v)]);
      it->second = {newell_normal(a_, f), q / double(face.size())};
    }
    return it->second;
  }

private:
  const MeshArrays& a_;
  std::unordered_map<int, std::pair<Vec3, Dual>> sums_;
};

/// The inner copy of a sector's vertex: moved along the bisector of its boundary edges so that the
/// inner edges lie `thickness` inside, with the covariance of the 9D blend towards the fan's face points.
Gaussian inner_copy(const MeshArrays& a, FaceSums& sums, const FaceRegion::Sector& s, double thickness) {
  const std::string vertex = "vertex " + std::to_string(s.vertex);
  std::set<int> fan;
  for (const auto& [f, k] : s.corners) fan.insert(f);
  Vec3 normal = Vec3::Zero();
  for (int f : fan) normal += sums.of(f).first;
  if (!(normal.norm() > 0)) throw Error("the faces at " + vertex + " have no normal to inset along");
  normal.normalize();

  const auto& in_face = a.faces[size_t(s.incoming.first)];
  const auto& out_face = a.faces[size_t(s.outgoing.first)];
  const Vec3& p = a.means[size_t(s.vertex)];
  const Vec3& u = a.means[size_t(in_face[size_t(s.incoming.second)])];
  const Vec3& w = a.means[(size_t(out_face[(size_t(s.outgoing.second) + 1) % out_face.size()]))];
  // A face's inside lies to the left of its edges: normal × edge direction.
  const Vec3 left_in = normal.cross(p - u).normalized(), left_out = normal.cross(w - p).normalized();
  const Vec3 bisector = (left_in + left_out).normalized();
  const double cos_half = bisector.dot(left_in);
  if (!left_in.allFinite() || !left_out.allFinite() || !bisector.allFinite() || !(cos_half > 1e-6))
    throw Error("the corner at " + vertex + " is too sharp to inset");
  const Vec3 moved = p + bisector * (thickness / cos_half);

  // The 9D average of the fan's face points, and the fraction of the way to it the vertex moved.
  Dual centre = Dual::Zero();
  for (int f : fan) centre += sums.of(f).second;
  centre /= double(fan.size());
  const std::optional<Vec3> centre_mean = mean_from_dual(centre);
  if (!centre_mean) throw Error("a new vertex would get a covariance that is not positive definite");
  const double t = (moved - p).norm() / (*centre_mean - p).norm();
  if (!(t < 1))
    throw Error("a thickness of " + short_number(thickness) + " would carry " + vertex + " past the centre of face " +
                std::to_string(*fan.begin()));
  const std::optional<Gaussian> blend = from_dual(t * centre + (1 - t) * to_dual(p, a.covariances[size_t(s.vertex)]));
  if (!blend) throw Error("a new vertex would get a covariance that is not positive definite");
  return {moved, blend->covariance};
}

}  // namespace

std::vector<int> inset_faces_in(MeshArrays& a, const std::vector<int>& faces, double thickness, std::string& summary) {
  if (!(std::isfinite(thickness) && thickness > 0))
    throw Error("thickness " + short_number(thickness) + " is not a positive number");
  const FaceRegion r = face_region(a, faces);
  if (r.has_closed_part) throw Error("insetting every face of a closed part would leave no border to inset from");

  std::vector<Gaussian> copies;
  FaceSums sums(a);
  for (const auto& s : r.sectors) copies.push_back(inner_copy(a, sums, s, thickness));

  // Every region face must keep its orientation and the direction of each of its edges.
  // (Detaching only adds vertices: the old corners' means stay where they are.)
  std::vector<Vec3> old_normals;
  std::vector<std::vector<int>> old_faces;
  for (int f : r.faces) {
    old_normals.push_back(sums.of(f).first);
    old_faces.push_back(a.faces[size_t(f)]);
  }
  const int n_faces = a.n_faces();
  std::vector<int> selection = detach_region(a, r, copies);
  for (size_t i = 0; i < r.faces.size(); ++i) {
    const int f = r.faces[i];
    const auto& old_face = old_faces[i];
    const auto& face = a.faces[size_t(f)];
    bool kept = newell_normal(a, f).dot(old_normals[i]) > 0;
    for (size_t k = 0; k < face.size() && kept; ++k) {
      const size_t l = (k + 1) % face.size();
      const Vec3 now = a.means[size_t(face[l])] - a.means[size_t(face[k])];
      const Vec3 was = a.means[size_t(old_face[l])] - a.means[size_t(old_face[k])];
      kept = now.dot(was) > 0;
    }
    if (!kept)
      throw Error("a thickness of " + short_number(thickness) + " would turn face " + std::to_string(f) +
                  " inside out");
  }
  check_gaussians(a, selection);  // the inner copies: the others were checked before
  summary = "inset " + count_of(r.faces.size(), "face", "faces") + ": " +
            count_of(selection.size(), "vertex", "vertices") + ", " +
            count_of(size_t(a.n_faces() - n_faces), "face", "faces") + " added";
  return selection;
}

Modelled inset_faces(const CovarianceMesh& mesh, const std::vector<int>& faces, double thickness) {
  return modelled_by(mesh,
                     [&](MeshArrays& a, std::string& summary) { return inset_faces_in(a, faces, thickness, summary); });
}

}  // namespace gps
