// The reference's creases and corners against OpenSubdiv's Far (libosd-dev, a test dependency only):
// the same topology, sharpness and 9D points refined by Far::TopologyRefiner and
// Far::PrimvarRefinerReal<double>, level by level and to the limit, then compared point by point.
#include <gtest/gtest.h>

#ifdef GPS_HAVE_OPENSUBDIV

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>

#include "core/mesh/dual_map.h"
#include "core/mesh/mesh_connectivity.h"
#include "core/reference/catmull_clark.h"
#include "core/reference/catmull_clark_connectivity.h"
#include "core/reference/crease_rules.h"
#include "core/reference/limit_masks.h"
#include "core/reference/loop_connectivity.h"
#include "core/reference/reference_subdivision.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using namespace OpenSubdiv;

// Far's primvar interface for a 9D point.
struct FarPoint {
  Dual q = Dual::Zero();
  void Clear(void* = nullptr) { q.setZero(); }
  void AddWithWeight(const FarPoint& src, double weight) { q += weight * src.q; }
};

// Sharpness as Far stores it, in single precision: the test's values are set so, so that both
// sides decay and blend the same numbers.
double as_float(double s) { return double(float(s)); }

// One level of the reference's refinement, as reference_subdivision.cpp steps through them.
struct Level {
  PolygonTopology topology;
  MeshConnectivity connectivity;
  std::vector<Dual> values;
  CreaseLevel creases;
};

std::vector<Level> reference_levels(const CovarianceMesh& mesh, Scheme scheme, int levels) {
  std::vector<Level> out(1);
  out[0].topology = mesh.topology();
  out[0].connectivity = connectivity_of(out[0].topology);
  out[0].values = base_points(mesh);
  out[0].creases = crease_level(mesh.sharpness, out[0].connectivity, out[0].topology.n_vertices);
  for (int l = 0; l < levels; ++l) {
    const Level& p = out.back();
    Level next;
    if (scheme == Scheme::catmull_clark) {
      next.values = catmull_clark_values(p.topology, p.connectivity, p.values, &p.creases);
      next.topology = catmull_clark_topology(p.topology, p.connectivity);
      next.connectivity = catmull_clark_connectivity(p.topology, p.connectivity);
    } else {
      next.values = loop_values(p.topology, p.connectivity, p.values, LoopBeta::loop, &p.creases);
      next.topology = loop_topology(p.topology, p.connectivity);
      next.connectivity = loop_connectivity(p.topology, p.connectivity);
    }
    next.creases = refined_crease_level(p.topology, p.connectivity, p.creases, next.connectivity);
    out.push_back(std::move(next));
  }
  return out;
}

// Far's refinement of the same mesh: its finest points, their limits, and for each of its finest
// vertices the reference's index. Far numbers a level's children from vertices, then faces, then
// edges, its edges in an order of its own; the reference from vertices, then edges (by
// connectivity order), then faces. The map follows each parent element by its vertices.
struct FarRefinement {
  std::vector<Dual> refined, limit;
  std::vector<int> reference_index;
};

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

FarRefinement far_refinement(const CovarianceMesh& mesh, Scheme scheme, const std::vector<Level>& ref) {
  const PolygonTopology& base = ref[0].topology;
  std::vector<int> sizes(size_t(base.n_faces()));
  for (int f = 0; f < base.n_faces(); ++f) sizes[size_t(f)] = base.face_size(f);
  std::vector<int> crease_pairs;
  std::vector<float> crease_weights, corner_weights;
  std::vector<int> corner_vertices;
  for (const EdgeCrease& c : mesh.sharpness.creases) {
    crease_pairs.insert(crease_pairs.end(), {c.a, c.b});
    crease_weights.push_back(float(c.sharpness));
  }
  for (size_t v = 0; v < mesh.sharpness.corners.size(); ++v)
    if (mesh.sharpness.corners[v] > 0.0) {
      corner_vertices.push_back(int(v));
      corner_weights.push_back(float(mesh.sharpness.corners[v]));
    }
  Far::TopologyDescriptor desc;
  desc.numVertices = base.n_vertices;
  desc.numFaces = base.n_faces();
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = base.verts.data();
  desc.numCreases = int(crease_weights.size());
  desc.creaseVertexIndexPairs = crease_pairs.data();
  desc.creaseWeights = crease_weights.data();
  desc.numCorners = int(corner_weights.size());
  desc.cornerVertexIndices = corner_vertices.data();
  desc.cornerWeights = corner_weights.data();
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  options.SetCreasingMethod(Sdc::Options::CREASE_UNIFORM);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  const Sdc::SchemeType type = scheme == Scheme::loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(type, options)));
  EXPECT_TRUE(refiner);
  const int levels = int(ref.size()) - 1;
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);

  std::vector<FarPoint> points(size_t(base.n_vertices));
  for (size_t i = 0; i < points.size(); ++i) points[i].q = ref[0].values[i];
  std::vector<int> to_reference(points.size());
  for (size_t i = 0; i < to_reference.size(); ++i) to_reference[i] = int(i);
  Far::PrimvarRefinerReal<double> primvars(*refiner);
  for (int l = 0; l < levels; ++l) {
    const Far::TopologyLevel& far = refiner->GetLevel(l);
    const Level& r = ref[size_t(l)];
    const int nv = r.topology.n_vertices, ne = r.connectivity.n_edges();
    std::vector<FarPoint> finer(size_t(refiner->GetLevel(l + 1).GetNumVertices()));
    primvars.Interpolate(l + 1, points, finer);
    std::vector<int> finer_to_reference(finer.size(), -1);
    for (int v = 0; v < far.GetNumVertices(); ++v)
      finer_to_reference[size_t(far.GetVertexChildVertex(v))] = to_reference[size_t(v)];
    std::map<std::vector<int>, int> edges, faces;
    for (int e = 0; e < ne; ++e)
      edges[sorted({r.connectivity.edge_verts[2 * size_t(e)], r.connectivity.edge_verts[2 * size_t(e) + 1]})] = e;
    for (int f = 0; f < r.topology.n_faces(); ++f)
      faces[sorted({r.topology.verts.begin() + r.topology.offsets[size_t(f)],
                    r.topology.verts.begin() + r.topology.offsets[size_t(f) + 1]})] = f;
    const auto reference_of = [&](Far::ConstIndexArray verts) {
      std::vector<int> out;
      for (int i = 0; i < verts.size(); ++i) out.push_back(to_reference[size_t(verts[i])]);
      return sorted(out);
    };
    for (int e = 0; e < far.GetNumEdges(); ++e)
      finer_to_reference[size_t(far.GetEdgeChildVertex(e))] = nv + edges.at(reference_of(far.GetEdgeVertices(e)));
    if (scheme == Scheme::catmull_clark)
      for (int f = 0; f < far.GetNumFaces(); ++f)
        finer_to_reference[size_t(far.GetFaceChildVertex(f))] =
            nv + ne + faces.at(reference_of(far.GetFaceVertices(f)));
    points = std::move(finer);
    to_reference = std::move(finer_to_reference);
  }
  std::vector<FarPoint> limit(points.size());
  primvars.Limit(points, limit);
  FarRefinement out;
  out.reference_index = to_reference;
  out.refined.resize(points.size());
  out.limit.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    out.refined[i] = points[i].q;
    out.limit[i] = limit[i].q;
  }
  return out;
}

double max_norm(const std::vector<Dual>& q) {
  double m = 0.0;
  for (const Dual& x : q) m = std::max(m, x.norm());
  return m;
}

// The reference's limits of a level's points.
std::vector<Dual> reference_limit(const Level& level, Scheme scheme) {
  std::vector<Dual> limit(level.values.size());
  const PutLimit<Dual> put = [&](int v, const Dual& q) { limit[size_t(v)] = q; };
  if (scheme == Scheme::catmull_clark)
    catmull_clark_limit(level.topology, level.connectivity, level.values, level.topology.n_vertices, put,
                        &level.creases);
  else
    loop_limit(level.topology, level.connectivity, level.values, LoopBeta::loop, put, &level.creases);
  return limit;
}

// Whether vertex v of the level is a dart of an infinitely sharp edge: there Far's limit is the
// smooth mask's and the reference's the dart's own (core/reference/dart_masks.h).
bool infinitely_sharp_dart(const Level& level, int v) {
  if (vertex_rule(level.connectivity, level.creases, v) != VertexRule::dart) return false;
  const MeshConnectivity& c = level.connectivity;
  for (int i = c.vertex_edge_offsets[size_t(v)]; i < c.vertex_edge_offsets[size_t(v) + 1]; ++i)
    if (is_infinitely_sharp(edge_sharpness(c, level.creases, c.vertex_edges[size_t(i)]))) return true;
  return false;
}

// Far against the reference on one mesh: the 9D points after `levels` steps and their limits, and
// the means of the reference's own result (subdivide) against Far's points mapped back; the limits
// everywhere but at darts of infinitely sharp edges (FarsLimitAtDartsApproachesTheReference).
void expect_matches_far(const CovarianceMesh& mesh, Scheme scheme, int levels) {
  SCOPED_TRACE(std::string(scheme == Scheme::loop ? "Loop" : "Catmull-Clark") + ", " + std::to_string(levels) +
               " levels");
  const std::vector<Level> ref = reference_levels(mesh, scheme, levels);
  const Level& last = ref.back();
  ASSERT_FALSE(ref[0].creases.empty());
  ASSERT_FALSE(last.creases.empty());  // some sharpness is left, so the limit takes its rules
  const std::vector<Dual> limit = reference_limit(last, scheme);

  const FarRefinement far = far_refinement(mesh, scheme, ref);
  ASSERT_EQ(far.refined.size(), last.values.size());
  const double scale = max_norm(last.values);
  double refined_error = 0.0, limit_error = 0.0;
  for (size_t i = 0; i < far.refined.size(); ++i) {
    const size_t r = size_t(far.reference_index[i]);
    refined_error = std::max(refined_error, (far.refined[i] - last.values[r]).norm());
    if (!infinitely_sharp_dart(last, int(r))) limit_error = std::max(limit_error, (far.limit[i] - limit[r]).norm());
  }
  EXPECT_LE(refined_error, 1e-12 * scale);
  EXPECT_LE(limit_error, 1e-12 * scale);

  const double diagonal = bounding_box_diagonal(mesh);
  for (const bool with_limit : {false, true}) {
    const SubdivisionResult result = subdivide(mesh, SubdivisionOptions{scheme, levels, with_limit});
    const std::vector<Dual>& q = with_limit ? far.limit : far.refined;
    double error = 0.0;
    for (size_t i = 0; i < q.size(); ++i) {
      const int r = far.reference_index[i];
      if (with_limit && infinitely_sharp_dart(last, r)) continue;
      const auto mean = mean_from_dual(q[i]);
      ASSERT_TRUE(mean);
      error = std::max(error, (*mean - result.mesh.mean(size_t(r))).norm());
    }
    EXPECT_LE(error, 1e-12 * diagonal) << (with_limit ? "limit" : "refined");
  }
}

// At a dart of an infinitely sharp edge Far's limit (the smooth mask) moves with the level it is
// taken from, towards the reference's, which is the same from every level: the distance shrinks
// by the ring's subdominant eigenvalue or faster at each level.
void expect_far_approaches_at_darts(const CovarianceMesh& mesh, Scheme scheme) {
  SCOPED_TRACE(scheme == Scheme::loop ? "Loop" : "Catmull-Clark");
  const std::vector<Level> ref = reference_levels(mesh, scheme, 5);
  const std::vector<Dual> exact = reference_limit(ref[1], scheme);
  std::vector<int> darts;
  for (int v = 0; v < ref[0].topology.n_vertices; ++v)
    if (infinitely_sharp_dart(ref[0], v)) darts.push_back(v);
  ASSERT_FALSE(darts.empty());
  std::vector<double> distance;
  for (int levels = 1; levels <= 5; ++levels) {
    const std::vector<Level> to_level(ref.begin(), ref.begin() + levels + 1);
    const FarRefinement far = far_refinement(mesh, scheme, to_level);
    const std::vector<Dual> limit = reference_limit(to_level.back(), scheme);
    double worst = 0.0;
    for (size_t i = 0; i < far.limit.size(); ++i) {
      const int r = far.reference_index[i];
      if (std::find(darts.begin(), darts.end(), r) == darts.end()) continue;
      EXPECT_LT((limit[size_t(r)] - exact[size_t(r)]).norm(), 1e-12 * max_norm(ref[0].values)) << "level " << levels;
      worst = std::max(worst, (far.limit[i] - exact[size_t(r)]).norm());
    }
    distance.push_back(worst);
  }
  const double scale = max_norm(ref[0].values);
  std::printf(
      "Far's limit at darts from levels 1 to 5: %.1e %.1e %.1e %.1e %.1e of the points' size from the reference's\n",
      distance[0] / scale, distance[1] / scale, distance[2] / scale, distance[3] / scale, distance[4] / scale);
  EXPECT_GT(distance[0], 1e-4 * scale);
  for (size_t l = 1; l < distance.size(); ++l) EXPECT_LT(distance[l], 0.7 * distance[l - 1]) << "level " << l + 1;
}

// Sharpness 0.5, 1, 2.5, 4.7 and ∞ mixed on one mesh. Where more than one sharpness decays to smooth
// at a vertex in the same step, Sdc averages them in single precision: the values are placed so that
// every such average is exact in it (equal values, or two of them).
void set_crease(CovarianceMesh& m, int a, int b, double s) { m.sharpness.set_crease(a, b, as_float(s)); }
void set_corner(CovarianceMesh& m, int v, double s) { m.sharpness.set_corner(v, as_float(s), int(m.n_vertices())); }

CovarianceMesh creased_cube() {
  CovarianceMesh m = test::with_random_covariances(test::cube_mesh(), 11);
  set_crease(m, 0, 1, 0.5);
  set_crease(m, 1, 2, 1.0);
  set_crease(m, 2, 3, 2.5);
  set_crease(m, 4, 5, 4.7);
  set_crease(m, 5, 6, 10.0);
  set_crease(m, 6, 7, 10.0);
  set_corner(m, 0, 0.5);
  set_corner(m, 7, 2.5);
  return m;
}

TEST(CreaseReferenceOsd, CatmullClarkCubeMatchesFar) {
  const CovarianceMesh m = creased_cube();
  expect_matches_far(m, Scheme::catmull_clark, 3);
  expect_matches_far(m, Scheme::catmull_clark, 5);  // 4.7 decays to smooth at the fifth step
}

TEST(CreaseReferenceOsd, CatmullClarkOpenGridMatchesFar) {
  // 5 × 4 quads: a semi-sharp line across it from boundary to boundary (boundary corners that
  // become creases), an infinitely sharp line, a sharp interior vertex and a sharp boundary vertex.
  CovarianceMesh m = test::with_random_covariances(test::grid_mesh(5, 4), 12);
  const auto id = [](int i, int j) { return j * 6 + i; };
  for (int i = 0; i < 5; ++i) set_crease(m, id(i, 1), id(i + 1, 1), 2.5);
  for (int j = 0; j < 4; ++j) set_crease(m, id(3, j), id(3, j + 1), 10.0);
  set_crease(m, id(1, 2), id(1, 3), 0.5);
  set_corner(m, id(2, 3), 1.0);
  set_corner(m, id(5, 2), 4.7);
  expect_matches_far(m, Scheme::catmull_clark, 3);
}

TEST(CreaseReferenceOsd, CatmullClarkOpenCylinderMatchesFar) {
  // Quads and a triangle fan: a semi-sharp ring, a sharp ring under the fan, a sharp apex.
  CovarianceMesh m = test::with_random_covariances(test::open_cylinder_mesh(), 13);
  for (int k = 0; k < 8; ++k) set_crease(m, 8 + k, 8 + (k + 1) % 8, 0.5);
  for (int k = 0; k < 8; ++k) set_crease(m, 16 + k, 16 + (k + 1) % 8, 10.0);
  set_crease(m, 2, 10, 4.7);
  set_corner(m, 24, 2.5);
  expect_matches_far(m, Scheme::catmull_clark, 3);
}

TEST(CreaseReferenceOsd, LoopOctahedronMatchesFar) {
  CovarianceMesh m = test::with_random_covariances(test::bipyramid_mesh(4), 14);
  for (int k = 0; k < 4; ++k) set_crease(m, 2 + k, 2 + (k + 1) % 4, 2.5);
  set_crease(m, 0, 2, 1.0);
  set_corner(m, 1, 4.7);
  expect_matches_far(m, Scheme::loop, 3);
}

TEST(CreaseReferenceOsd, LoopIcosahedronMatchesFar) {
  CovarianceMesh m = test::with_random_covariances(test::icosahedron_mesh(), 15);
  set_crease(m, 0, 1, 0.5);
  set_crease(m, 1, 5, 1.0);
  set_crease(m, 5, 0, 2.5);
  set_crease(m, 3, 4, 10.0);
  set_crease(m, 4, 2, 10.0);
  set_crease(m, 2, 3, 4.7);
  set_crease(m, 7, 10, 10.0);
  set_corner(m, 6, 2.5);
  expect_matches_far(m, Scheme::loop, 3);
}

TEST(CreaseReferenceOsd, LoopOpenTriangleGridMatchesFar) {
  CovarianceMesh m = test::with_random_covariances(test::triangle_grid_mesh(5, 4), 16);
  const auto id = [](int i, int j) { return j * 6 + i; };
  for (int i = 0; i < 5; ++i) set_crease(m, id(i, 2), id(i + 1, 2), 2.5);
  for (int j = 0; j < 4; ++j) set_crease(m, id(2, j), id(2, j + 1), 10.0);
  set_crease(m, id(4, 0), id(4, 1), 0.5);
  set_corner(m, id(1, 1), 1.0);
  set_corner(m, id(4, 3), 4.7);
  expect_matches_far(m, Scheme::loop, 3);
}

TEST(CreaseReferenceOsd, FarsLimitAtDartsApproachesTheReference) {
  CovarianceMesh cube = test::with_random_covariances(test::cube_mesh(), 17);
  set_crease(cube, 4, 5, 10.0);  // darts of valence 3
  CovarianceMesh grid = test::with_random_covariances(test::grid_mesh(4, 4), 18);
  set_crease(grid, 6, 7, 10.0);  // darts of valence 4
  CovarianceMesh icosahedron = test::with_random_covariances(test::icosahedron_mesh(), 19);
  set_crease(icosahedron, 7, 10, 10.0);  // darts of valence 5
  expect_far_approaches_at_darts(cube, Scheme::catmull_clark);
  expect_far_approaches_at_darts(grid, Scheme::catmull_clark);
  expect_far_approaches_at_darts(icosahedron, Scheme::loop);
}

}  // namespace
}  // namespace gps

#else

TEST(CreaseReferenceOsd, NeedsOpenSubdiv) { GTEST_SKIP() << "built without OpenSubdiv (libosd-dev)"; }

#endif
