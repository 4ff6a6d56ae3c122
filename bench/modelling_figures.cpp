#include "bench/modelling_figures.h"

#include <glad/gl.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <functional>
#include <thread>

#include "core/modelling/samples.h"
#include "core/modelling/affine_transform.h"
#include "core/modelling/bevel.h"
#include "core/modelling/delete_elements.h"
#include "core/modelling/edge_operations.h"
#include "core/modelling/extrude.h"
#include "core/modelling/inset.h"
#include "core/modelling/knife.h"
#include "core/modelling/loop_cut.h"
#include "core/modelling/merge_vertices.h"
#include "core/modelling/slide.h"
#include "core/modelling/subdivide_mesh.h"
#include "core/plans/surface_replanner.h"
#include "core/support/error.h"
#include "core/support/median.h"
#include "render/gl/gpu_pass_timer.h"
#include "render/gl/render_target.h"
#include "render/pipeline/surface_renderer.h"
#include "view/camera.h"

namespace gps {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The last surface pass's GPU time (the frame was finished: its query has its result).
double surface_pass_seconds(GpuPassTimer& timer) {
  for (const auto& [pass, ms] : timer.latest())
    if (pass == "surface") return ms * 1e-3;
  return 0.0;
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v;
  return values.empty() ? 0.0 : sum / double(values.size());
}

// The operations the bench times, each on a face in the middle of the mesh, or on an edge or a vertex of it.
// The face an operation applies to, and its corners.
struct Target {
  int face;
  std::span<const int> corners;
};
using Operation = std::function<Modelled(const CovarianceMesh&, const Target&)>;
const std::vector<std::pair<std::string, Operation>>& operation_table() {
  static const std::vector<std::pair<std::string, Operation>> table = {
      {"extrude 1 face", [](const CovarianceMesh& m, const Target& t) { return extrude_faces(m, {t.face}, 0.01); }},
      {"inset 1 face", [](const CovarianceMesh& m, const Target& t) { return inset_faces(m, {t.face}, 1e-3); }},
      {"loop cut", [](const CovarianceMesh& m, const Target& t) { return loop_cut(m, t.corners[0], t.corners[1], 1); }},
      {"subdivide 1 face", [](const CovarianceMesh& m, const Target& t) { return subdivide_faces(m, {t.face}); }},
      {"delete 1 face", [](const CovarianceMesh& m, const Target& t) { return delete_faces(m, {t.face}); }},
      {"merge 2 vertices",
       [](const CovarianceMesh& m, const Target& t) {
         return merge_vertices(m, {t.corners[0], t.corners[1]}, MergePoint::center);
       }},
      {"split 1 edge",
       [](const CovarianceMesh& m, const Target& t) { return split_edge(m, t.corners[0], t.corners[1]); }},
      {"dissolve 1 edge",
       [](const CovarianceMesh& m, const Target& t) {
         return dissolve_edges(m, {{t.corners[0], t.corners[1]}});
       }},
      {"bevel 1 edge",
       [](const CovarianceMesh& m, const Target& t) {
         BevelOptions bevel;
         bevel.width = 0.2 * (m.mean(size_t(t.corners[0])) - m.mean(size_t(t.corners[1]))).norm();
         return bevel_edges(m, {{t.corners[0], t.corners[1]}}, bevel);
       }},
      {"slide 1 edge",
       [](const CovarianceMesh& m, const Target& t) {
         return edge_slide(m, {{t.corners[0], t.corners[1]}}, 0.3);
       }},
      {"knife 1 face",
       [](const CovarianceMesh& m, const Target& t) {
         Vec3 centroid = Vec3::Zero();
         for (const int v : t.corners) centroid += m.mean(size_t(v)) / double(t.corners.size());
         const auto toward = [&](int k) { return 0.5 * (centroid + m.mean(size_t(t.corners[size_t(k)]))); };
         return knife(m, {toward(0), toward(int(t.corners.size()) / 2)});
       }},
      {"transform all",
       [](const CovarianceMesh& m, const Target&) {
         return transform_vertices(m, {}, AffineMap::about(Vec3::Zero(), 1.01 * Mat3::Identity()));
       }},
      {"rotate all",
       [](const CovarianceMesh& m, const Target&) {
         const Mat3 turn = Eigen::AngleAxisd(0.1, Vec3::UnitZ()).toRotationMatrix();
         return transform_vertices(m, {}, AffineMap::about(Vec3::Zero(), turn));
       }},
      {"stretch all", [](const CovarianceMesh& m, const Target&) {
         return transform_vertices(m, {}, AffineMap::about(Vec3::Zero(), Vec3(1.01, 1.0, 1.0).asDiagonal()));
       }}};
  return table;
}

}  // namespace

const std::vector<std::string>& modelling_operations() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> listed;
    for (const auto& [name, operation] : operation_table()) listed.push_back(name);
    return listed;
  }();
  return names;
}

std::vector<std::string> modelling_operations_named(const std::vector<std::string>& words) {
  std::vector<char> named(modelling_operations().size(), 0);
  for (const std::string& word : words) {
    bool found = false;
    for (size_t i = 0; i < named.size(); ++i) {
      const std::string& operation = modelling_operations()[i];
      if (!word.empty() && operation.compare(0, word.size(), word) == 0 &&
          (operation.size() == word.size() || operation[word.size()] == ' '))
        named[i] = 1, found = true;
    }
    if (!found) {
      std::string list;
      for (const std::string& operation : modelling_operations()) list += (list.empty() ? "" : ", ") + operation;
      throw Error("'" + word + "' names no operation (" + list + ")");
    }
  }
  std::vector<std::string> chosen;
  for (size_t i = 0; i < named.size(); ++i)
    if (named[i]) chosen.push_back(modelling_operations()[i]);
  return chosen;
}

nlohmann::json modelling_figures(const std::string& name, int faces, const PlanOptions& options, int crease_every,
                                 const std::vector<std::string>& only) {
  CovarianceMesh mesh = make_sample(name, faces);
  for (size_t e = 0; crease_every > 0 && e < mesh.n_edges(); e += size_t(crease_every))
    mesh.sharpness.set_crease(mesh.edge(e)[0], mesh.edge(e)[1], 2.0);
  SurfaceRenderer renderer;
  renderer.surface_cache().set_whole_weld_delay(SurfaceCache::kPauseWeldDelay);  // as the editor draws
  GpuPassTimer timer;
  renderer.set_pass_timer(&timer);
  RenderTarget target(1280, 720);
  DrawOptions draw;
  draw.pixels = 6.0f;
  const Camera camera = frame_mesh(mesh);
  const PolygonTopology& topology = mesh.topology();
  SurfaceReplanner replanner(topology, options, mesh.sharpness);
  renderer.set_mesh(mesh, replanner.shared_tables(), NormalisedFrame::of(mesh), replanner.last_change(), {});
  renderer.draw(target, camera, draw);
  glFinish();

  // The plans and the renderer follow each operation incrementally (core/plans/surface_replanner.h), in
  // the frame the editor keeps (NormalisedFrame::following), and go back the same way, as an undo,
  // before the next round; a full re-plan of the same result is timed beside them.
  nlohmann::json rows = nlohmann::json::array();
  const int f = int(mesh.n_faces() / 2);
  const std::span<const int> corners = mesh.face(size_t(f));
  for (const auto& [label, made_by] : operation_table()) {
    if (!only.empty() && std::find(only.begin(), only.end(), label) == only.end()) continue;
    const auto operation = [&, &made_by = made_by](const CovarianceMesh& m) { return made_by(m, {f, corners}); };
    // An operation that this mesh refuses (a loop cut across triangles), or that takes it to the other
    // scheme (an inset of triangles makes quads: a full re-plan by the other builder), is left out.
    try {
      const Modelled trial = operation(mesh);
      if (scheme_for(trial.mesh.topology(), options, &trial.mesh.connectivity()) != replanner.scheme()) {
        rows.push_back({{"operation", label}, {"skipped", "it changes the subdivision scheme"}});
        continue;
      }
    } catch (const Error& error) {
      rows.push_back({{"operation", label}, {"skipped", error.what()}});
      continue;
    }
    std::vector<double> op_s, plan_s, full_s, upload_s, frame_s, total_s, next_s, pause_s, still_s, edit_s, undo_s,
        undo_frame_s;
    // How the surface cache drew: full captures in the frame after the operation, the patches its
    // refresh captured or evaluated again, and whether the still frame drew stored, welded triangles.
    std::vector<double> captures, refreshed, still_cached, still_welded;
    const SurfaceCache& cache = renderer.surface_cache();
    // The GPU's own time of the surface pass (capture or refresh, and the draw) in the frame after the
    // operation and in the still frame: where it is far below the frame's, the rest waits on the CPU.
    std::vector<double> frame_gpu_s, still_gpu_s;
    int planned = 0;
    for (int round = 0; round < 6; ++round) {
      const Clock::time_point start = Clock::now();
      const Modelled result = operation(mesh);
      op_s.push_back(seconds_since(start));
      const Clock::time_point planning = Clock::now();
      planned = replanner.set_topology(result.mesh, result.vertex_origin);
      plan_s.push_back(seconds_since(planning));
      const Clock::time_point uploading = Clock::now();
      renderer.set_mesh(result.mesh, replanner.shared_tables(), renderer.frame().following(result.mesh),
                        replanner.last_change(), result.vertex_origin);
      glFinish();
      upload_s.push_back(seconds_since(uploading));
      const int captures_before = cache.captures(), refreshes_before = cache.refreshes();
      const Clock::time_point drawn = Clock::now();
      renderer.draw(target, camera, draw);
      glFinish();
      frame_s.push_back(seconds_since(drawn));
      frame_gpu_s.push_back(surface_pass_seconds(timer));
      captures.push_back(cache.captures() - captures_before);
      refreshed.push_back(cache.refreshes() > refreshes_before ? cache.refreshed_patches() : 0);
      total_s.push_back(seconds_since(start));
      // The next frame; then, once a user would pause, the frame that welds what the operation's frame
      // stored (on llvmpipe: surface_cache.h); then the same mesh drawn again once settled: the frame of
      // the mesh without an operation, which the first two are held to.
      const Clock::time_point next = Clock::now();
      renderer.draw(target, camera, draw);
      glFinish();
      next_s.push_back(seconds_since(next));
      std::this_thread::sleep_for(SurfaceCache::kPauseWeldDelay);
      const Clock::time_point paused = Clock::now();
      renderer.draw(target, camera, draw);
      glFinish();
      pause_s.push_back(seconds_since(paused));
      const Clock::time_point still = Clock::now();
      renderer.draw(target, camera, draw);
      glFinish();
      still_s.push_back(seconds_since(still));
      still_gpu_s.push_back(surface_pass_seconds(timer));
      still_cached.push_back(renderer.last_statistics().cached);
      still_welded.push_back(cache.has_stored_triangles() && cache.stored_vertices_welded());
      // The first edit of the new topology, as the move that follows an extrusion: the vertices the
      // operation selects moved, up to the end of the compute passes that follow them.
      CovarianceMesh moved = result.mesh;
      for (const int v : result.selection) moved.set_mean(size_t(v), 1.01 * moved.mean(size_t(v)));
      const Clock::time_point editing = Clock::now();
      renderer.update_vertices(moved, result.selection);
      glFinish();
      edit_s.push_back(seconds_since(editing));
      const Clock::time_point full = Clock::now();
      const SurfaceTables whole = build_surface_plans(result.mesh, options);
      full_s.push_back(seconds_since(full));
      // The undo: the mesh before, re-planned and uploaded the same way.
      const Clock::time_point undoing = Clock::now();
      const std::vector<int> back = inverse_origin(result.vertex_origin, mesh.n_vertices());
      replanner.set_topology(mesh, back);
      renderer.set_mesh(mesh, replanner.shared_tables(), renderer.frame().following(mesh), replanner.last_change(),
                        back);
      glFinish();
      undo_s.push_back(seconds_since(undoing));
      // The frame after the undo, which the next round's operation would otherwise pay for.
      const Clock::time_point undone = Clock::now();
      renderer.draw(target, camera, draw);
      glFinish();
      undo_frame_s.push_back(seconds_since(undone));
    }
    // The first round of each operation warms the allocator and the driver's buffers up for its sizes
    // (the first operation timed paid twice the others' upload): not counted.
    for (std::vector<double>* times :
         {&op_s, &plan_s, &full_s, &upload_s, &frame_s, &total_s, &next_s, &pause_s, &still_s, &edit_s, &undo_s,
          &undo_frame_s, &captures, &refreshed, &still_cached, &still_welded, &frame_gpu_s, &still_gpu_s})
      times->erase(times->begin());
    rows.push_back({{"operation", label},
                    {"operation_ms", median(op_s) * 1e3},
                    {"replan_ms", median(plan_s) * 1e3},
                    {"faces_planned", planned},
                    {"full_replan_ms", median(full_s) * 1e3},
                    {"upload_ms", median(upload_s) * 1e3},
                    {"frame_ms", median(frame_s) * 1e3},
                    {"total_ms", median(total_s) * 1e3},
                    {"next_frame_ms", median(next_s) * 1e3},
                    {"pause_frame_ms", median(pause_s) * 1e3},
                    {"still_frame_ms", median(still_s) * 1e3},
                    {"first_edit_ms", median(edit_s) * 1e3},
                    {"undo_ms", median(undo_s) * 1e3},
                    {"undo_frame_ms", median(undo_frame_s) * 1e3},
                    {"frame_gpu_ms", median(frame_gpu_s) * 1e3},
                    {"still_gpu_ms", median(still_gpu_s) * 1e3},
                    {"frame_captures", mean(captures)},
                    {"frame_refreshed_patches", median(refreshed)},
                    {"still_cached", mean(still_cached)},
                    {"still_welded", mean(still_welded)}});
  }
  return {{"mesh", name + "/" + std::to_string(faces) + (crease_every > 0 ? "+creases" : "")},
          {"faces", mesh.n_faces()},
          {"creased_edges", mesh.sharpness.creases.size()},
          {"vertices", mesh.n_vertices()},
          {"operations", rows}};
}

}  // namespace gps
