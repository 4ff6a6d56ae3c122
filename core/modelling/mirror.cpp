#include "core/modelling/mirror.h"

#include <algorithm>
#include <cmath>

#include "core/modelling/affine_transform.h"
#include "core/modelling/operation_words.h"
#include "core/support/error.h"

namespace gps {

namespace {

// Vertices this close to the plane, relative to the mesh's bounding-box diagonal, are merged.
constexpr double kOnPlane = 1e-5;

// The map of the mirror image about the plane through `center` perpendicular to `axis`.
AffineMap mirror_map(int axis, const Vec3& center) {
  Mat3 flip = Mat3::Identity();
  flip(axis, axis) = -1;
  return AffineMap::about(center, flip);
}

// A merged vertex's Gaussian: the 9D average of it and its image, which is its own image, so that the
// seam stays symmetric.
Gaussian seam_gaussian(const Gaussian& g, const AffineMap& image, int vertex) {
  const std::optional<Gaussian> symmetric = from_dual(0.5 * (to_dual(g) + to_dual(image.apply(g))));
  if (!symmetric)
    throw Error("vertex " + std::to_string(vertex) +
                " on the mirror plane would get a covariance that is not positive definite");
  return *symmetric;
}

void check_mirror_plane(int axis, const Vec3& center) {
  if (axis < 0 || axis > 2) throw Error("the mirror axis must be x, y or z");
  if (!center.allFinite()) throw Error("the mirror's center has a number that is not finite");
}

}  // namespace

double mirror_merge_distance(const CovarianceMesh& mesh) { return kOnPlane * bounding_box_diagonal(mesh); }

std::vector<int> mirror_images(const CovarianceMesh& mesh, int axis, const Vec3& center, bool merge) {
  check_mirror_plane(axis, center);
  const double tolerance = mirror_merge_distance(mesh);
  const int n_vertices = int(mesh.n_vertices());
  std::vector<int> images(static_cast<size_t>(n_vertices));
  int next = n_vertices;
  for (int v = 0; v < n_vertices; ++v)
    images[size_t(v)] = merge && std::abs(mesh.mean(size_t(v))[axis] - center[axis]) <= tolerance ? v : next++;
  return images;
}

std::vector<int> update_mirrored(const CovarianceMesh& mesh, const std::vector<int>& vertices, int axis,
                                 const Vec3& center, const std::vector<int>& images, CovarianceMesh& mirrored) {
  check_mirror_plane(axis, center);
  const AffineMap image = mirror_map(axis, center);
  std::vector<int> set;
  for (const int v : vertices) {
    const Gaussian g{mesh.mean(size_t(v)), mesh.covariance(size_t(v))};
    const int copy = images[size_t(v)];
    const Gaussian own = copy == v ? seam_gaussian(g, image, v) : g;
    mirrored.set_mean(size_t(v), own.mean);
    mirrored.set_covariance(size_t(v), own.covariance);
    set.push_back(v);
    if (copy == v) continue;
    const Gaussian mirrored_g = image.apply(g);
    mirrored.set_mean(size_t(copy), mirrored_g.mean);
    mirrored.set_covariance(size_t(copy), mirrored_g.covariance);
    set.push_back(copy);
  }
  std::sort(set.begin(), set.end());
  set.erase(std::unique(set.begin(), set.end()), set.end());
  return set;
}

Modelled mirror(const CovarianceMesh& mesh, int axis, const Vec3& center, bool merge) {
  const std::vector<int> images = mirror_images(mesh, axis, center, merge);
  MeshArrays a = arrays_of(mesh);
  const int n_vertices = a.n_vertices(), n_faces = a.n_faces();
  const char* const axis_name[] = {"x", "y", "z"};
  const AffineMap image = mirror_map(axis, center);

  std::vector<char> merged(size_t(n_vertices), 0);
  for (int v = 0; v < n_vertices; ++v) merged[size_t(v)] = images[size_t(v)] == v;
  // The seam: merged vertices must be joined by boundary edges along the plane, each with one face.
  const DirectedEdges edges(mesh);
  std::vector<char> on_seam(size_t(n_vertices), 0), used(size_t(n_vertices), 0);
  for (int f = 0; f < n_faces; ++f) {
    const std::vector<int>& face = a.faces[size_t(f)];
    if (std::all_of(face.begin(), face.end(), [&](int v) { return merged[size_t(v)] != 0; }))
      throw Error("face " + std::to_string(f) + " lies on the mirror plane (it would meet its own image)");
  }
  for (const std::vector<int>& face : a.faces)
    for (size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], v = face[(k + 1) % face.size()];
      used[size_t(u)] = 1;
      if (!merged[size_t(u)] || !merged[size_t(v)]) continue;
      if (!is_boundary_edge(edges, u, v))
        throw Error(edge_name(std::min(u, v), std::max(u, v)) +
                    " lies on the mirror plane with faces on both sides (the seam would join four)");
      on_seam[size_t(u)] = on_seam[size_t(v)] = 1;
    }
  for (int v = 0; v < n_vertices; ++v)
    if (merged[size_t(v)] && used[size_t(v)] && !on_seam[size_t(v)])
      throw Error("vertex " + std::to_string(v) +
                  " lies on the mirror plane beside no boundary edge along it (the halves would meet at a point)");

  const std::vector<int>& copy_of = images;
  std::vector<int> copies;
  for (int v = 0; v < n_vertices; ++v) {
    if (!merged[size_t(v)]) {
      copies.push_back(a.add_vertex(image.apply(a.gaussian(v))));
      continue;
    }
    const Gaussian symmetric = seam_gaussian(a.gaussian(v), image, v);
    a.means[size_t(v)] = symmetric.mean;
    a.covariances[size_t(v)] = symmetric.covariance;
  }
  for (int f = 0; f < n_faces; ++f) {
    std::vector<int> face = a.faces[size_t(f)];
    for (int& v : face) v = copy_of[size_t(v)];
    std::reverse(face.begin() + 1, face.end());
    a.faces.push_back(std::move(face));
  }
  const Sharpness before = a.sharpness;
  for (const EdgeCrease& c : before.creases)
    a.sharpness.set_crease(copy_of[size_t(c.a)], copy_of[size_t(c.b)], c.sharpness);
  for (int v = 0; v < n_vertices; ++v)
    if (const double corner = before.corner(v); corner > 0 && !merged[size_t(v)])
      a.sharpness.set_corner(copy_of[size_t(v)], corner, a.n_vertices());

  const size_t n_merged = size_t(std::count(merged.begin(), merged.end(), 1));
  Modelled out = modelled(mesh, std::move(a), copies);
  out.summary = "mirrored " + count_of(size_t(n_vertices), "vertex", "vertices") + " and " +
                count_of(size_t(n_faces), "face", "faces") + " in " + axis_name[axis] +
                (merge ? ", " + count_of(n_merged, "vertex", "vertices") + " merged on the plane" : "");
  return out;
}

}  // namespace gps
