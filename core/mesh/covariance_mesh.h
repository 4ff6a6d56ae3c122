#pragma once
// A covariance mesh: a polygon mesh whose vertex i carries a Gaussian (μ_i, Σ_i) (docs/design.md §1).
#include <array>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/connectivity_update.h"
#include "core/mesh/element_names.h"
#include "core/mesh/linalg.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/mesh/mesh_shape.h"
#include "core/mesh/sharpness.h"

namespace gps {

/// A polygon mesh whose vertex i carries the Gaussian (μ_i, Σ_i): the means and faces are fixed when
/// it is made (make_covariance_mesh checks them and builds the connectivity once), the means can be
/// moved and the covariances and sharpness changed in place. Vertices, edges, faces and corners are
/// numbered as in its topology and connectivity, which every part of gpsurf reads without converting.
/// The faces and connectivity are one MeshShape that the mesh's copies, and the plans made from it,
/// share rather than copy.
class CovarianceMesh {
public:
  CovarianceMesh() = default;
  CovarianceMesh(const CovarianceMesh&) = default;
  CovarianceMesh& operator=(const CovarianceMesh&) = default;
  /// A mesh moved from is left a mesh of nothing: no vertices, no faces.
  CovarianceMesh(CovarianceMesh&& other) noexcept { *this = std::move(other); }
  CovarianceMesh& operator=(CovarianceMesh&& other) noexcept {
    covariances = std::move(other.covariances);
    sharpness = std::move(other.sharpness);
    means_ = std::move(other.means_);
    shape_ = std::exchange(other.shape_, empty_mesh_shape());
    return *this;
  }

  std::vector<Mat3> covariances;
  /// Edge creases and vertex corners by vertex index; empty for a smooth mesh.
  Sharpness sharpness;

  size_t n_vertices() const { return means_.size(); }
  size_t n_faces() const { return size_t(shape_->topology.n_faces()); }
  size_t n_edges() const { return size_t(shape_->connectivity.n_edges()); }
  size_t n_corners() const { return shape_->topology.verts.size(); }

  const Vec3& mean(size_t i) const { return means_[i]; }
  void set_mean(size_t i, const Vec3& mean) { means_[i] = mean; }
  const std::vector<Vec3>& means() const { return means_; }
  const Mat3& covariance(size_t i) const { return covariances[i]; }
  void set_covariance(size_t i, const Mat3& covariance) { covariances[i] = covariance; }

  /// The faces as corner lists, and their edges and incidences.
  const PolygonTopology& topology() const { return shape_->topology; }
  const MeshConnectivity& connectivity() const { return shape_->connectivity; }
  /// The faces and connectivity together, shared with the mesh's copies (never null).
  const std::shared_ptr<const MeshShape>& shape() const { return shape_; }
  /// The vertices of face f in order (its corners).
  std::span<const int> face(size_t f) const {
    return {shape_->topology.verts.data() + shape_->topology.offsets[f], size_t(shape_->topology.face_size(int(f)))};
  }
  int face_size(size_t f) const { return shape_->topology.face_size(int(f)); }
  /// The ends of edge e, the lower index first.
  std::array<int, 2> edge(size_t e) const {
    return {shape_->connectivity.edge_verts[2 * e], shape_->connectivity.edge_verts[2 * e + 1]};
  }
  bool is_boundary_edge(size_t e) const { return shape_->connectivity.is_boundary_edge(int(e)); }
  /// The edge joining vertices a and b, or −1.
  int find_edge(int a, int b) const { return shape_->connectivity.find_edge(a, b); }
  /// The number of edges at vertex v; whether it lies on a boundary (an isolated vertex does not).
  int valence(size_t v) const { return shape_->connectivity.valence(int(v)); }
  bool is_boundary_vertex(size_t v) const;

private:
  friend class CovarianceMeshAssembly;
  std::vector<Vec3> means_;
  std::shared_ptr<const MeshShape> shape_ = empty_mesh_shape();
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
/// The same with the faces' connectivity already built (`connectivity` = connectivity_of(faces)).
CovarianceMesh make_covariance_mesh(std::vector<Vec3>&& means, std::vector<Mat3>&& covariances, PolygonTopology&& faces,
                                    MeshConnectivity&& connectivity, const std::string& source = "mesh");
/// A mesh made from `before` by a modelling operation, `origins` saying where its vertices and faces
/// came from: its connectivity is carried over from before's where updated_connectivity can
/// (core/mesh/connectivity_update.h), at the cost of what changed, else built and checked whole. The
/// same mesh, or the same error, either way.
CovarianceMesh make_covariance_mesh(const CovarianceMesh& before, std::vector<Vec3>&& means,
                                    std::vector<Mat3>&& covariances, PolygonTopology&& faces,
                                    const MeshOrigins& origins, const std::string& source = "mesh");

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

/// The point the CPU evaluates a mesh's limit surface about: its bounding box's centre where the mesh
/// lies farther from the origin than its diagonal, else the origin. Σ⁻¹μ carries μ's distance from the
/// origin, so the 9D points of a mesh far from it keep too few digits for its own size once combined;
/// GPS commutes with translations (docs/design.md §1), so the surface evaluated about this point and
/// moved back by it is the mesh's.
Vec3 evaluation_origin(const CovarianceMesh& mesh);

/// The 9D point q = (vech(Σ⁻¹), Σ⁻¹(μ − origin)) of every vertex (thesis Eq. 2.10), the base of the
/// plans' points and of the reference subdivision: the mesh's, moved by −origin.
std::vector<Dual> base_points(const CovarianceMesh& mesh, const Vec3& origin = Vec3::Zero());

}  // namespace gps
