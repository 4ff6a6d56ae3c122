#include "core/modelling/select_similar.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <set>
#include <span>

#include "core/modelling/mesh_arrays.h"
#include "core/support/error.h"

namespace gps {

namespace {

// Whether `value` is within `tolerance` of one of `wanted` (sorted): |value − w| ≤ tolerance · scale(w).
template <typename Scale>
bool near_one(double value, const std::vector<double>& wanted, double tolerance, Scale scale) {
  return std::any_of(wanted.begin(), wanted.end(),
                     [&](double w) { return std::abs(value - w) <= tolerance * scale(w) + 1e-12 * std::abs(w); });
}

// A face's area vector: half the sum of its corners' cross products (Newell).
Vec3 face_area_vector(const CovarianceMesh& mesh, int f) {
  Vec3 sum = Vec3::Zero();
  const std::span<const int> corners = mesh.face(size_t(f));
  for (size_t k = 0; k < corners.size(); ++k)
    sum += mesh.mean(size_t(corners[k])).cross(mesh.mean(size_t(corners[(k + 1) % corners.size()])));
  return 0.5 * sum;
}

}  // namespace

const char* similarity_name(Similarity similarity) {
  switch (similarity) {
    case Similarity::edge_length:
      return "length";
    case Similarity::edge_crease:
      return "crease";
    case Similarity::face_area:
      return "area";
    case Similarity::face_sides:
      return "sides";
    case Similarity::face_normal:
      return "normal";
    case Similarity::vertex_edges:
      return "number of edges";
  }
  return "";
}

std::vector<std::array<int, 2>> similar_edges(const CovarianceMesh& mesh,
                                              const std::vector<std::array<int, 2>>& selected, Similarity similarity,
                                              double tolerance) {
  if (similarity != Similarity::edge_length && similarity != Similarity::edge_crease)
    throw Error(std::string("edges have no ") + similarity_name(similarity) + " to compare");
  const auto value = [&](int a, int b) {
    return similarity == Similarity::edge_length ? (mesh.mean(size_t(a)) - mesh.mean(size_t(b))).norm()
                                                 : mesh.sharpness.crease(a, b);
  };
  std::vector<double> wanted;
  for (const auto& [a, b] : selected) wanted.push_back(value(a, b));
  std::vector<std::array<int, 2>> similar;
  for (size_t e = 0; e < mesh.n_edges(); ++e) {
    const auto [a, b] = mesh.edge(e);
    const bool like = similarity == Similarity::edge_length
                          ? near_one(value(a, b), wanted, tolerance, [](double w) { return w; })
                          : near_one(value(a, b), wanted, tolerance, [](double) { return 1.0; });
    if (like) similar.push_back({a, b});
  }
  std::sort(similar.begin(), similar.end());
  return similar;
}

std::vector<int> similar_faces(const CovarianceMesh& mesh, const std::vector<int>& selected, Similarity similarity,
                               double tolerance) {
  const int n_faces = int(mesh.n_faces());
  std::vector<int> similar;
  if (similarity == Similarity::face_sides) {
    std::set<int> sides;
    for (const int f : selected) sides.insert(mesh.face_size(size_t(f)));
    for (int f = 0; f < n_faces; ++f)
      if (sides.count(mesh.face_size(size_t(f)))) similar.push_back(f);
    return similar;
  }
  if (similarity == Similarity::face_area) {
    std::vector<double> wanted;
    for (const int f : selected) wanted.push_back(face_area_vector(mesh, f).norm());
    for (int f = 0; f < n_faces; ++f)
      if (near_one(face_area_vector(mesh, f).norm(), wanted, tolerance, [](double w) { return w; }))
        similar.push_back(f);
    return similar;
  }
  if (similarity != Similarity::face_normal)
    throw Error(std::string("faces have no ") + similarity_name(similarity) + " to compare");
  std::vector<Vec3> normals;
  for (const int f : selected) normals.push_back(face_area_vector(mesh, f).normalized());
  const double cosine = std::cos(std::clamp(tolerance, 0.0, 1.0) * M_PI);
  for (int f = 0; f < n_faces; ++f) {
    const Vec3 n = face_area_vector(mesh, f).normalized();
    if (std::any_of(normals.begin(), normals.end(), [&](const Vec3& w) { return n.dot(w) >= cosine - 1e-12; }))
      similar.push_back(f);
  }
  return similar;
}

std::vector<int> similar_vertices(const CovarianceMesh& mesh, const std::vector<int>& selected, Similarity similarity) {
  if (similarity != Similarity::vertex_edges)
    throw Error(std::string("vertices have no ") + similarity_name(similarity) + " to compare");
  std::set<int> valences;
  for (const int v : selected) valences.insert(mesh.valence(size_t(v)));
  std::vector<int> similar;
  for (int v = 0; v < int(mesh.n_vertices()); ++v)
    if (valences.count(mesh.valence(size_t(v)))) similar.push_back(v);
  return similar;
}

}  // namespace gps
