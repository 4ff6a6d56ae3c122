#include "core/plans/sharpness_replanner.h"

#include <algorithm>
#include <exception>

#include "core/plans/loop_crease_plan_builder.h"
#include "core/plans/loop_plan_builder.h"
#include "core/plans/patch_adjacency.h"

namespace gps {

std::vector<int> faces_reading(const PolygonTopology& t, const MeshConnectivity& c, const std::vector<int>& edges,
                               const std::vector<int>& vertices) {
  std::vector<int> holders;  // the faces that hold a changed edge or vertex
  for (const int e : edges)
    for (int k = 0; k < 2; ++k)
      if (const int f = c.edge_faces[2 * size_t(e) + size_t(k)]; f >= 0) holders.push_back(f);
  for (const int v : vertices)
    for (int i = c.vertex_face_offsets[size_t(v)]; i < c.vertex_face_offsets[size_t(v) + 1]; ++i)
      holders.push_back(c.vertex_faces[size_t(i)]);
  std::vector<int> faces;
  for (const int g : holders)
    for (int k = t.offsets[size_t(g)]; k < t.offsets[size_t(g) + 1]; ++k) {
      const int w = t.verts[size_t(k)];
      faces.insert(faces.end(), c.vertex_faces.begin() + c.vertex_face_offsets[size_t(w)],
                   c.vertex_faces.begin() + c.vertex_face_offsets[size_t(w) + 1]);
    }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

SharpnessReplanner::SharpnessReplanner(const PolygonTopology& topology, const PlanOptions& options,
                                       const Sharpness& sharpness, int faces_per_range)
    : options_(options),
      scheme_(scheme_for(topology, options)),
      faces_per_range_(std::max(1, faces_per_range)),
      base_(base_local_mesh(topology, sharpness)) {
  if (scheme_ == Scheme::loop)
    check_loop_plans(topology);
  else
    check_quad_plans(topology, options.depth, options.exact ? ExtraordinaryNodes::exact : ExtraordinaryNodes::bezier);
  std::vector<int> all(static_cast<size_t>(n_ranges()));
  for (size_t r = 0; r < all.size(); ++r) all[r] = int(r);
  build(all, sharpness);
}

int SharpnessReplanner::n_ranges() const {
  return std::max(1, (base_.topology.n_faces() + faces_per_range_ - 1) / faces_per_range_);
}

void SharpnessReplanner::build(const std::vector<int>& which, const Sharpness& sharpness) {
  const PolygonTopology& t = base_.topology;
  if (scheme_ == Scheme::loop && !base_.has_creases()) {  // Loop's smooth builder, as build_surface_plans
    ranges_.clear();
    loop_tables_.reset();
    tables_ = build_loop_plans(t, options_.loop_beta);
    add_patch_adjacency(tables_.plans, t, sharpness);
    return;
  }
  ranges_.resize(size_t(n_ranges()));
  if (scheme_ == Scheme::loop && !loop_tables_) loop_tables_ = std::make_unique<LoopCreaseTables>(options_.loop_beta);
  if (scheme_ == Scheme::catmull_clark && !quad_tables_) quad_tables_ = std::make_unique<QuadExtraordinaryTableCache>();
  const ExtraordinaryNodes extraordinary = options_.exact ? ExtraordinaryNodes::exact : ExtraordinaryNodes::bezier;
  const int n_faces = t.n_faces();
  std::vector<std::exception_ptr> failures(which.size());
#pragma omp parallel for schedule(dynamic)
  for (size_t i = 0; i < which.size(); ++i) {
    const int r = which[i], first = r * faces_per_range_, last = std::min(n_faces, first + faces_per_range_);
    try {
      ranges_[size_t(r)] = scheme_ == Scheme::loop
                               ? build_creased_loop_range(base_, first, last, options_.loop_beta, *loop_tables_)
                               : build_quad_range(base_, first, last, options_.depth, extraordinary, true, *quad_tables_);
    } catch (...) {
      failures[i] = std::current_exception();
    }
  }
  for (const auto& failure : failures)
    if (failure) std::rethrow_exception(failure);
  tables_ = merge_ranges(ranges_, t.n_vertices, false);
  add_patch_adjacency(tables_.plans, t, sharpness);
}

std::vector<int> SharpnessReplanner::set_sharpness(const Sharpness& sharpness) {
  const PolygonTopology& t = base_.topology;
  const MeshConnectivity& c = base_.connectivity;
  CreaseLevel level = crease_level(sharpness, c, t.n_vertices);
  if (level.empty()) level = {};
  const CreaseLevel& old = base_.creases;
  std::vector<int> faces;
  if (level.empty() != old.empty()) {  // the first sharpness or the last: every plan
    faces.resize(size_t(t.n_faces()));
    for (size_t f = 0; f < faces.size(); ++f) faces[f] = int(f);
  } else if (!level.empty()) {
    std::vector<int> edges, vertices;
    for (size_t e = 0; e < level.edges.size(); ++e)
      if (level.edges[e] != old.edges[e]) edges.push_back(int(e));
    for (size_t v = 0; v < level.vertices.size(); ++v)
      if (level.vertices[v] != old.vertices[v]) vertices.push_back(int(v));
    faces = faces_reading(t, c, edges, vertices);
  }
  base_.creases = std::move(level);
  if (faces.empty()) {  // the same plans; the patch adjacency reads the sharpness as given
    add_patch_adjacency(tables_.plans, t, sharpness);
    return faces;
  }
  std::vector<int> which;
  for (const int f : faces)
    if (which.empty() || which.back() != f / faces_per_range_) which.push_back(f / faces_per_range_);
  build(which, sharpness);
  return faces;
}

}  // namespace gps
