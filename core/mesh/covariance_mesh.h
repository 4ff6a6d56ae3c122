#pragma once
// A covariance mesh: a polygon mesh whose vertex i carries a Gaussian (μ_i, Σ_i) (docs/design.md §1).
#include <string>
#include <vector>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "core/mesh/element_names.h"
#include "core/mesh/linalg.h"
#include "core/mesh/sharpness.h"

namespace gps {

struct PolygonTopology;  // core/mesh/mesh_connectivity.h

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
/// Topology and means: OpenMesh's polygon mesh with double-precision points.
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;

/// A polygon mesh whose points are the means μ_i, with one covariance Σ_i per vertex (by vertex index).
struct CovarianceMesh {
  PolyMesh mesh;
  std::vector<Mat3> covariances;
  /// Edge creases and vertex corners by vertex index; empty for a smooth mesh.
  Sharpness sharpness;

  size_t n_vertices() const { return mesh.n_vertices(); }
  size_t n_faces() const { return mesh.n_faces(); }
  Vec3 mean(size_t i) const;
  void set_mean(size_t i, const Vec3& mean);
  const Mat3& covariance(size_t i) const { return covariances[i]; }
  void set_covariance(size_t i, const Mat3& covariance) { covariances[i] = covariance; }
};

/// Builds a covariance mesh from plain arrays; faces are vertex-index lists.
/// Throws gps::Error naming `source` and the face if the topology is non-manifold or a face is degenerate.
CovarianceMesh make_covariance_mesh(const std::vector<Vec3>& means, const std::vector<Mat3>& covariances,
                                    const std::vector<std::vector<int>>& faces, const std::string& source = "mesh");
/// The same with the faces in compressed form, taking its arrays over: nothing is copied, so a
/// reader's memory is that of the arrays it filled. Empty `covariances` stand for the identity at
/// every vertex, made after the faces are built (a plain mesh's placeholders, not held meanwhile).
/// `names`: how its messages name the vertices and faces (as the file read numbers them).
CovarianceMesh make_covariance_mesh(std::vector<Vec3>&& means, std::vector<Mat3>&& covariances, PolygonTopology&& faces,
                                    const std::string& source = "mesh", const ElementNames& names = {});

/// Largest position coordinate magnitude accepted: squares and products of positions (and their
/// products with inverse covariances) must stay far from double overflow.
inline constexpr double kMaxPositionMagnitude = 1e100;
/// Range accepted for covariance eigenvalues: Σ⁻¹ (the dual map's q̂) and Σ⁻¹μ stay finite and normal.
inline constexpr double kMinCovarianceEigenvalue = 1e-100, kMaxCovarianceEigenvalue = 1e100;

/// Why a position cannot be used ("has a position that is not finite", ...), or "" if it can.
std::string position_problem(const Vec3& mean);
/// Why a covariance cannot be used (not finite, not symmetric, not positive definite with its smallest
/// eigenvalue, eigenvalues whose inverse under- or overflows), or "" if it can.
std::string covariance_problem(const Mat3& covariance);

/// "vertex i <problem>" for the first vertex whose position or covariance has a problem above, or "".
std::string gaussians_problem(const CovarianceMesh& m, const ElementNames& names = {});
/// Throws gps::Error naming `source` and the vertex if a position or covariance has a problem above.
void validate_gaussians(const CovarianceMesh& m, const std::string& source = "mesh", const ElementNames& names = {});

/// Whether a covariance is symmetric (to relative 1e-9) and positive definite.
bool is_spd(const Mat3& covariance);

/// Axis-aligned bounding box [lo, hi] of the means (both zero for an empty mesh).
void bounding_box(const CovarianceMesh& m, Vec3& lo, Vec3& hi);

/// Bounding-box diagonal length of the means.
double bounding_box_diagonal(const CovarianceMesh& m);

/// The 9D point q = (vech(Σ⁻¹), Σ⁻¹μ) of every vertex (thesis Eq. 2.10), the base of the plans'
/// points and of the reference subdivision.
std::vector<Dual> base_points(const CovarianceMesh& mesh);

inline Vec3 to_vec3(const OpenMesh::Vec3d& p) { return Vec3(p[0], p[1], p[2]); }
inline OpenMesh::Vec3d to_point(const Vec3& v) { return OpenMesh::Vec3d(v[0], v[1], v[2]); }

}  // namespace gps
