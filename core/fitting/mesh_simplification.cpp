#include "core/fitting/mesh_simplification.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <unordered_set>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
// QuadricT.hh uses vector_traits without including it.
#include <OpenMesh/Core/Utils/vector_traits.hh>
#include <OpenMesh/Core/Geometry/QuadricT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include "core/fitting/halfedge_collapse.h"
#include "core/fitting/triangle_pairing.h"
#include "core/mesh/element_names.h"
#include "core/support/error.h"

namespace gps {
namespace {

/// What a vertex of the decimated mesh has gathered from the input region collapsed into it: the
/// error quadric of its planes, the region's area and the area-weighted tensor of its face normals.
///
/// The covariance of a region carries the GPS inference (Eq. 16–17) from a vertex's fan to its
/// region: the precisions of the region's faces add up. Two things change with the scale. A fine
/// face's own moment C_f describes the input's triangulation (a long thin triangle, a diagonal
/// split), which means nothing at the coarse vertex; what the region knows is its faces' planes. So
/// each face stands for a disc in its plane of the region's size, with Eq. 16's bias:
/// Σ_f = s²[(1 + b)(I − n nᵀ) + b n nᵀ]. And summed as they are, a region of many faces would get
/// that many times a fan's precision, while GPS is invariant under one scale of all Σ but not under a
/// scale per vertex: a vertex that absorbed more faces would pull the surface harder. So the
/// precisions are averaged by area, not summed, and the disc's size is the region's, s² = A_v (its
/// area; a global factor GPS ignores):
///     Σ_v⁻¹ = [(I − N_v)/(1 + b) + N_v/b] / A_v,   N_v = Σ a_f n_f n_fᵀ / A_v.
/// The shape is the region's (a flat disc across a smooth patch, a needle along a sharp edge, the
/// needle exactly along the edge, as every normal there is perpendicular to it) and the size the
/// coarse mesh's, whatever the density of the input there. Each input face is shared by its corners,
/// a third of its area each, so area and normal tensor add up as regions merge.
struct Region {
  int vertex = -1;  // the input vertex this one is
  OpenMesh::Geometry::Quadricd quadric;
  double area = 0;                    // A_v
  Mat3 normal_moment = Mat3::Zero();  // A_v N_v = Σ a_f n_f n_fᵀ
};

/// Weight of the merged region's squared area in a collapse's priority: among collapses of (nearly)
/// equal quadric error, as across a flat side where all are zero, the one that makes the smaller
/// region goes first, so regions grow evenly and one on a sharp edge takes both sides of it alike.
constexpr double kRegionAreaWeight = 1e-3;

/// Weight of a boundary edge's plane (perpendicular to its face through the edge) against the face
/// planes, per squared edge length: large, so that collapses keep the boundary's shape.
constexpr double kBoundaryPlaneWeight = 100;

/// The input as triangles, faces of more sides fanned from their first corner, in a frame where its
/// bounding box is centred on the origin with a unit diagonal (`scale` its diagonal): the quadric
/// errors and areas the priorities hold in single precision stay far from under- and overflow.
CollapseMesh triangles_of(const CovarianceMesh& input, bool& triangulated, double& scale) {
  Vec3 lo, hi;
  bounding_box(input, lo, hi);
  const Vec3 centre = 0.5 * (lo + hi);
  scale = (hi - lo).norm() > 0 ? (hi - lo).norm() : 1.0;
  CollapseMesh t;
  t.reserve(input.n_vertices(), input.n_edges(), input.n_faces());
  for (const Vec3& mean : input.means()) t.add_vertex(to_point((mean - centre) / scale));
  triangulated = false;
  // OpenMesh writes a refused face to its error stream ("complex edge"): the refusal below says it.
  static const bool quiet = (omerr().disable(), true);
  (void)quiet;
  std::vector<CollapseMesh::VertexHandle> corners;
  std::unordered_set<uint64_t> diagonals;  // the fans' diagonals so far, by their ends
  const auto key = [](int a, int b) { return uint64_t(uint32_t(std::min(a, b))) << 32 | uint32_t(std::max(a, b)); };
  for (size_t f = 0; f < input.n_faces(); ++f) {
    const std::span<const int> c = input.face(f);
    const size_t n = c.size();
    triangulated = triangulated || n > 3;
    // The fan's apex: the first corner whose diagonals are neither edges of the mesh nor diagonals of
    // faces fanned before (either would put a third triangle on an edge), as a triangle lying on two
    // edges of a quad beside it asks.
    size_t apex = 0;
    const auto free = [&](size_t a) {
      for (size_t k = 2; k + 1 < n; ++k) {
        const int u = c[a], w = c[(a + k) % n];
        if (input.find_edge(u, w) >= 0 || diagonals.count(key(u, w))) return false;
      }
      return true;
    };
    while (apex < n && !free(apex)) ++apex;
    if (apex == n)
      throw ElementError(ElementError::Element::face, int(f), "",
                         ": no fan of it into triangles keeps every edge between two faces (its corners are joined "
                         "by edges of the mesh across it); split it into triangles first");
    corners.clear();
    for (size_t k = 0; k < n; ++k) corners.push_back(CollapseMesh::VertexHandle(c[(apex + k) % n]));
    for (size_t k = 2; k + 1 < n; ++k) diagonals.insert(key(c[apex], c[(apex + k) % n]));
    for (size_t k = 1; k + 1 < n; ++k)
      if (!t.add_face(corners[0], corners[k], corners[k + 1]).is_valid())
        throw ElementError(ElementError::Element::face, int(f), "",
                           ": fanning it into triangles makes an edge non-manifold; split it into triangles first");
  }
  return t;
}

/// The input's creases and corners as OpenMesh features, which the decimater keeps: a vertex on a
/// crease collapses only along it, and a corner or a vertex where creases meet or end (not two of
/// them) does not move. Each crease edge keeps its sharpness in `crease`, carried by the edges that
/// survive the collapses.
void mark_sharpness(CollapseMesh& t, const Sharpness& sharpness, OpenMesh::EPropHandleT<double> crease) {
  for (const auto e : t.edges()) t.property(crease, e) = 0;
  for (const EdgeCrease& c : sharpness.creases) {
    const auto h = t.find_halfedge(CollapseMesh::VertexHandle(c.a), CollapseMesh::VertexHandle(c.b));
    if (!h.is_valid()) continue;
    const auto e = t.edge_handle(h);
    t.status(e).set_feature(true);
    t.property(crease, e) = c.sharpness;
    t.status(CollapseMesh::VertexHandle(c.a)).set_feature(true);
    t.status(CollapseMesh::VertexHandle(c.b)).set_feature(true);
  }
  for (const auto v : t.vertices()) {
    if (!t.status(v).feature() && sharpness.corner(v.idx()) == 0) continue;
    int creases = 0;
    for (const auto e : t.ve_range(v)) creases += t.status(e).feature();
    if (creases != 2 || sharpness.corner(v.idx()) > 0) t.status(v).set_locked(true);
  }
}

/// Every vertex's region before any collapse: its quadric, and a third of each face around it.
void seed_regions(CollapseMesh& t, OpenMesh::VPropHandleT<Region> region) {
  for (const auto v : t.vertices()) t.property(region, v).vertex = v.idx();
  std::vector<Vec3> corners(3);
  for (const auto f : t.faces()) {
    int k = 0;
    for (const auto v : t.fv_range(f)) corners[size_t(k++)] = to_vec3(t.point(v));
    const Vec3 cross = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    const double area = 0.5 * cross.norm();
    if (!(area > 0)) continue;
    const Vec3 n = cross.normalized();
    OpenMesh::Geometry::Quadricd plane(n[0], n[1], n[2], -n.dot(corners[0]));
    plane *= area;
    for (const auto v : t.fv_range(f)) {
      Region& r = t.property(region, v);
      r.quadric += plane;
      r.area += area / 3;
      r.normal_moment += (area / 3) * n * n.transpose();
    }
  }
  for (const auto h : t.halfedges()) {
    if (!t.is_boundary(h)) continue;
    const auto face = t.face_handle(t.opposite_halfedge_handle(h));
    const Vec3 a = to_vec3(t.point(t.from_vertex_handle(h))), b = to_vec3(t.point(t.to_vertex_handle(h)));
    const Vec3 normal = to_vec3(t.calc_face_normal(face));
    const Vec3 across = (b - a).cross(normal);
    if (!(across.norm() > 0)) continue;
    const Vec3 m = across.normalized();
    OpenMesh::Geometry::Quadricd plane(m[0], m[1], m[2], -m.dot(a));
    plane *= kBoundaryPlaneWeight * (b - a).squaredNorm();
    t.property(region, t.from_vertex_handle(h)).quadric += plane;
    t.property(region, t.to_vertex_handle(h)).quadric += plane;
  }
}

/// The covariance of a region (see Region); where its faces have no area (all degenerate), an
/// isotropic one with σ half the mean length of the vertex's edges.
Mat3 region_covariance(const CollapseMesh& t, CollapseMesh::VertexHandle v, const Region& r, double bias) {
  if (r.area > 0) {
    const Mat3 normals = r.normal_moment / r.area;
    const Mat3 precision = ((Mat3::Identity() - normals) / (1 + bias) + normals / bias) / r.area;
    const Eigen::LLT<Mat3> llt{precision};
    if (llt.info() == Eigen::Success) {
      const Mat3 covariance = llt.solve(Mat3::Identity());
      return 0.5 * (covariance + covariance.transpose());
    }
  }
  double length = 0;
  int count = 0;
  for (const auto e : t.ve_range(v)) length += t.calc_edge_length(e), ++count;
  const double sigma = count && length > 0 ? 0.5 * length / count : 1.0;
  return sigma * sigma * Mat3::Identity();
}

}  // namespace

SimplifiedMesh simplify_mesh(const CovarianceMesh& input, const SimplifyOptions& options) {
  if (options.target_vertices < 4)
    throw usage_error("the target vertex count must be at least 4, got " + std::to_string(options.target_vertices));
  SimplifiedMesh result;
  result.input_vertices = input.n_vertices();
  double scale = 1;
  CollapseMesh t = triangles_of(input, result.triangulated, scale);
  result.input_triangles = t.n_faces();

  OpenMesh::VPropHandleT<Region> region;
  t.add_property(region);
  seed_regions(t, region);

  t.request_vertex_status();
  t.request_edge_status();
  t.request_face_status();
  OpenMesh::EPropHandleT<double> crease;
  t.add_property(crease);
  mark_sharpness(t, input.sharpness, crease);
  // A collapse's priority is the quadric error of the merged region at the position it keeps plus the
  // region term; after a collapse from → into, into's region takes from's.
  HalfedgeCollapses collapses;
  collapses.priority = [&](CollapseMesh::VertexHandle from, CollapseMesh::VertexHandle into) {
    const Region& a = t.property(region, from);
    const Region& b = t.property(region, into);
    const auto p = t.point(into);
    const double area = a.area + b.area, error = std::max(0.0, a.quadric(p) + b.quadric(p));
    // The mesh is scaled to a unit diagonal: max_error compares as it is.
    if (options.max_error > 0 && error > 3 * area * options.max_error * options.max_error) return -1.0f;
    return float(error + kRegionAreaWeight * area * area);
  };
  collapses.collapsed = [&](CollapseMesh::VertexHandle from, CollapseMesh::VertexHandle into) {
    const Region& a = t.property(region, from);
    Region& b = t.property(region, into);
    b.quadric += a.quadric;
    b.area += a.area;
    b.normal_moment += a.normal_moment;
  };
  collapses.max_normal_deviation_degrees = options.max_normal_deviation_degrees;
  collapses.progress = options.progress;
  collapse_halfedges(t, options.target_vertices, collapses);
  t.garbage_collection();

  std::vector<Vec3> means;
  std::vector<Mat3> covariances;
  means.reserve(t.n_vertices());
  covariances.reserve(t.n_vertices());
  for (const auto v : t.vertices()) {
    const Region& r = t.property(region, v);
    means.push_back(input.mean(size_t(r.vertex)));
    covariances.push_back(scale * scale * region_covariance(t, v, r, options.bias));
  }
  std::vector<std::vector<int>> faces;
  faces.reserve(t.n_faces());
  for (const auto f : t.faces()) {
    std::vector<int>& face = faces.emplace_back();
    for (const auto v : t.fv_range(f)) face.push_back(v.idx());
  }
  result.mesh = make_covariance_mesh(means, covariances, faces, "the simplified mesh");
  for (const auto e : t.edges())
    if (t.property(crease, e) > 0) result.mesh.sharpness.set_crease(e.v0().idx(), e.v1().idx(), t.property(crease, e));
  for (const auto v : t.vertices())
    if (const double corner = input.sharpness.corner(t.property(region, v).vertex); corner > 0)
      result.mesh.sharpness.set_corner(v.idx(), corner, int(t.n_vertices()));
  result.mesh.sharpness.normalise();
  if (options.quads) result.quads = pair_triangles(result.mesh);
  return result;
}

}  // namespace gps
