// Bit-exact shared patch edges on the GPU: in the captured output of the tessellation
// evaluation shaders, every vertex on a patch edge inside the mesh has a vertex of another patch at
// exactly the same position (bit for bit), and the vertices of different patches that lie at one
// point (within a small tolerance) are all bit-identical: quads, split n-gons (T-junctions),
// Loop triangles, open meshes, uniform levels 1, 2, 3, 7, 64 and adaptive.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "core/io/mesh_io.h"
#include "core/plans/patch_adjacency.h"
#include "core/modelling/samples.h"
#include "render/pipeline/surface_renderer.h"
#include "tests/support/gl_fixture.h"
#include "tests/support/test_meshes.h"

namespace gps {
namespace {

using SharedEdges = test::GlTest;

// A vertex on a patch's boundary, once per (patch, position).
struct EdgeVertex {
  int patch;
  float u, v;
  std::array<float, 3> position;
  bool needs_partner;  // one of its patch edges has a neighbour (not all on the mesh's open boundary)
};

bool bit_equal(const std::array<float, 3>& a, const std::array<float, 3>& b) {
  return std::memcmp(a.data(), b.data(), sizeof(a)) == 0;
}

// The patch edges a vertex at (u, v) lies on (own parameters as the shader reports them).
std::vector<int> edges_at(PatchShape shape, float u, float v) {
  std::vector<int> k;
  if (shape == PatchShape::quad) {
    if (v == 0.0f) k.push_back(0);
    if (u == 1.0f) k.push_back(1);
    if (v == 1.0f) k.push_back(2);
    if (u == 0.0f) k.push_back(3);
  } else {
    if (v == 0.0f) k.push_back(0);
    if (std::abs(u + v - 1.0f) < 1e-6f) k.push_back(1);
    if (u == 0.0f) k.push_back(2);
  }
  return k;
}

// The boundary vertices of every patch, captured a range of patches at a time (bounded memory).
std::vector<EdgeVertex> capture_edge_vertices(SurfaceRenderer& renderer, const CovarianceMesh& mesh,
                                              const DrawOptions& o) {
  const PatchPlans& plans = renderer.tables().plans;
  const int level = o.pixels > 0.0f ? 64 : int(std::ceil(o.level));
  const int chunk = std::max(1, 400000 / ((level + 1) * (level + 1) * 6));
  std::vector<EdgeVertex> out;
  std::unordered_map<std::string, bool> seen;
  for (int first = 0; first < plans.n_patches(); first += chunk)
    for (const TessellatedVertex& t :
         renderer.capture_vertices(frame_mesh(mesh, 35.0f, 25.0f), o, 512, 512, first, chunk)) {
      const std::vector<int> k = edges_at(plans.shape, t.u, t.v);
      if (k.empty()) continue;
      EdgeVertex e{int(t.patch), t.u, t.v, {t.position[0], t.position[1], t.position[2]}, false};
      std::string key(reinterpret_cast<const char*>(&e.patch), sizeof(int));
      key.append(reinterpret_cast<const char*>(e.position.data()), sizeof(e.position));
      if (!seen.emplace(key, true).second) continue;
      for (const int edge : k) e.needs_partner = e.needs_partner || edge_neighbour(plans, e.patch, edge).patch >= 0;
      out.push_back(e);
    }
  return out;
}

struct SharedEdgeCheck {
  size_t vertices = 0;      // boundary vertices (per patch)
  size_t without_twin = 0;  // needing a partner but no other patch's vertex is bit-identical
  size_t near_misses = 0;   // other patches' vertices within the tolerance that are not bit-identical
};

SharedEdgeCheck check_shared_edges(SurfaceRenderer& renderer, const CovarianceMesh& mesh, const DrawOptions& o) {
  const std::vector<EdgeVertex> vertices = capture_edge_vertices(renderer, mesh, o);
  const double tolerance = 5e-7 * bounding_box_diagonal(mesh);  // the pawn at 64 has distinct points 2e-6 apart
  std::unordered_map<long long, std::vector<size_t>> cells;
  const auto cell = [&](const std::array<float, 3>& p, int dx, int dy, int dz) {
    const auto c = [&](int k, int d) { return (long long)std::floor(p[size_t(k)] / tolerance) + d; };
    return (c(0, dx) * 73856093LL) ^ (c(1, dy) * 19349663LL) ^ (c(2, dz) * 83492791LL);
  };
  for (size_t i = 0; i < vertices.size(); ++i) cells[cell(vertices[i].position, 0, 0, 0)].push_back(i);
  SharedEdgeCheck check;
  check.vertices = vertices.size();
  for (const EdgeVertex& v : vertices) {
    bool twin = false, miss = false;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(cell(v.position, dx, dy, dz));
          if (it == cells.end()) continue;
          for (const size_t j : it->second) {
            const EdgeVertex& w = vertices[j];
            if (w.patch == v.patch) continue;
            const double d = std::hypot(double(w.position[0]) - v.position[0], double(w.position[1]) - v.position[1],
                                        double(w.position[2]) - v.position[2]);
            if (d > tolerance) continue;
            if (bit_equal(w.position, v.position))
              twin = true;
            else
              miss = true;
          }
        }
    check.without_twin += v.needs_partner && !twin;
    check.near_misses += miss;
  }
  return check;
}

// Every sample (the sized ones small), open and mixed meshes of the test set, and creased meshes
// (tests/data), whose infinitely sharp creases share positions but not normals.
std::vector<std::string> every_sample() {
  std::vector<std::string> names = sample_names();
  names.insert(names.end(),
               {"open-cylinder", "triangle-grid", "prism", "creased_cube", "creased_cylinder", "creased_cone"});
  return names;
}

CovarianceMesh mesh_named(const std::string& name) {
  if (name == "open-cylinder") return test::open_cylinder_mesh();
  if (name == "triangle-grid") return test::with_random_covariances(test::triangle_grid_mesh(5, 4), 5);
  if (name == "prism") return test::prism_mesh();
  if (name.rfind("creased", 0) == 0) return read_mesh(std::string(GPS_TEST_DATA_DIR) + "/" + name + ".ply");
  if (name == "grid") return make_sample(name, 100);
  if (name == "sphere") return make_sample(name, 96);
  if (name == "icosphere") return make_sample(name, 320);
  return make_sample(name);
}

class EverySample : public SharedEdges, public ::testing::WithParamInterface<std::string> {};

// Exact plans (the default) at levels 1, 2, 3, 7, 64 and adaptive; the thesis' Bézier plans of
// depth 3 (--depth 3) at levels 3 and 64.
TEST_P(EverySample, SharesItsEdgeVerticesBitForBit) {
  const std::string name = GetParam();
  const CovarianceMesh mesh = mesh_named(name);
  SurfaceRenderer renderer;
  std::vector<std::pair<bool, DrawOptions>> settings;
  for (const int level : {1, 2, 3, 7, 64}) {
    DrawOptions o;
    o.level = float(level);
    settings.push_back({true, o});
  }
  DrawOptions adaptive;
  adaptive.pixels = 3.0f;
  settings.push_back({true, adaptive});
  for (const int level : {3, 64}) {
    DrawOptions o;
    o.level = float(level);
    settings.push_back({false, o});
  }
  int loaded = -1;  // the plans set: 1 exact, 0 Bézier
  for (const auto& [exact, o] : settings) {
    if (loaded != int(exact)) {
      PlanOptions plans;
      plans.exact = exact;
      renderer.set_mesh(mesh, plans);
      loaded = int(exact);
    }
    const std::string what =
        name + (exact ? "" : " depth-3") + (o.pixels > 0 ? " adaptive 3 px" : " level " + std::to_string(int(o.level)));
    const SharedEdgeCheck c = check_shared_edges(renderer, mesh, o);
    EXPECT_GT(c.vertices, 0u) << what;
    EXPECT_EQ(c.without_twin, 0u) << what;
    EXPECT_EQ(c.near_misses, 0u) << what;
    std::printf("%-28s %8zu edge vertices: %zu without a bit-identical twin, %zu near misses\n", what.c_str(),
                c.vertices, c.without_twin, c.near_misses);
  }
}

INSTANTIATE_TEST_SUITE_P(Samples, EverySample, ::testing::ValuesIn(every_sample()), [](const auto& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

// The check can fail: neighbouring patches given different edge levels on purpose leave vertices
// without a twin.
TEST_F(SharedEdges, MismatchedEdgeLevelsLeaveVerticesWithoutATwin) {
  for (const char* name : {"cube", "cylinder", "icosphere"}) {
    const CovarianceMesh mesh = make_sample(name);
    SurfaceRenderer renderer;
    renderer.set_mesh(mesh);
    DrawOptions o;
    o.level = 3.0f;
    o.diagnostics.mismatched_edge_levels = true;
    EXPECT_GT(check_shared_edges(renderer, mesh, o).without_twin, 0u) << name;
  }
}

}  // namespace
}  // namespace gps
