// gpsurf bench: the command line and the printed tables of the figures bench/ measures: --preprocess
// (bench/preprocess_figures.h), --render (bench/frame_figures.h), --edit (bench/edit_figures.h).
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <map>
#include <sstream>
#include <nlohmann/json.hpp>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/gl_commands.h"
#include "app/plan_arguments.h"
#include "bench/edit_figures.h"
#include "bench/modelling_figures.h"
#include "bench/frame_figures.h"
#include "bench/preprocess_figures.h"
#include "core/io/atomic_file.h"
#include "core/support/error.h"
#include "core/modelling/samples.h"
#include "render/gl/gl_context.h"
#include "render/image/line_plot.h"
#include "core/io/save_target.h"
#include "core/support/quoted_text.h"

namespace gps {

namespace {

// "NAME" or "NAME:FACES" (0 in the list: the sample's default size), checked against the samples.
std::vector<std::pair<std::string, int>> sample_list(const std::vector<std::string>& specs) {
  std::vector<std::pair<std::string, int>> list;
  for (const std::string& spec : specs) {
    const size_t colon = spec.find(':');
    const std::string name = spec.substr(0, colon);
    int faces = 0;
    if (colon != std::string::npos) {
      const std::string count = spec.substr(colon + 1);
      if (count.empty() || count.size() > 8 || count.find_first_not_of("0123456789") != std::string::npos)
        throw usage_error("bench: '" + spec + "' is not NAME or NAME:FACES");
      faces = std::stoi(count);
      if (faces < 1)
        throw usage_error("bench: " + quoted_token(spec) + " asks for no faces (NAME:FACES, FACES from 1)");
      if (!sample_has_size(name)) throw usage_error("bench: the sample '" + name + "' has no size to set");
    }
    const std::vector<std::string> known = sample_names();
    if (std::find(known.begin(), known.end(), name) == known.end())
      make_sample(name);  // refuses it, listing the samples
    list.emplace_back(name, faces);
  }
  return list;
}

}  // namespace

void add_bench_command(CLI::App& app) {
  struct Args {
    bool preprocess = false, render = false, edit = false, model = false;
    int size = 0;          // the mode's default
    int crease_every = 0;  // --model: none
    PlanArguments plans;
    std::string json, plots, context = "auto", mesh;
    std::vector<std::string> meshes, operations;
    std::vector<int> levels = {1, 4, 16, 64};
    std::string levels_text;
    float adaptive_pixels = 6.0f;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("bench", gl_command_summary("bench"));
  cmd->add_flag("--preprocess", args->preprocess, "plan building and stencil application per mesh");
  cmd->add_flag("--render", args->render,
                "GPU frame times per mesh and tessellation level, against a static vertex buffer");
  cmd->add_flag("--edit", args->edit, "edit-to-frame and frame times on a large sphere (1280x720, adaptive 6 px)");
  cmd->add_flag("--model", args->model,
                "operation-to-frame times of the modelling operations on spheres of 10,000 and 100,000 faces");
  cmd->add_option("--context", args->context, "GL context for --render and --edit: auto, osmesa, egl")
      ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
  cmd->add_option("--size", args->size,
                  "--render: render size in pixels (square, default 512); --edit: faces (default 100000)")
      ->transform(integer_in(16, 4000000));
  cmd->add_option(
         "--crease-every", args->crease_every,
         "--model: crease every Nth edge at sharpness 2 first (a creased mesh's tables hold many stencil rows)")
      ->transform(integer_in(1, 1000000));
  cmd->add_option("--operations", args->operations,
                  "--model: these operations alone, each named by its first words (extrude, loop cut, ...)")
      ->delimiter(',');
  add_plan_arguments(cmd, args->plans);
  cmd->add_option("--mesh", args->mesh, "--edit: the sample to edit (default: sphere; icosphere for triangles)");
  cmd->add_option("--meshes", args->meshes,
                  "--render, --preprocess: these samples instead of the default list, each NAME or NAME:FACES")
      ->delimiter(',');
  // Read whole and split here: CLI11 drops an empty item of a list ("1,,4") without a word.
  cmd->add_option("--levels", args->levels_text, "--render: the uniform tessellation levels (default 1,4,16,64)");
  cmd->add_option("--adaptive", args->adaptive_pixels,
                  "--render: also a row at adaptive levels of this many pixels per segment (default 6; 0: none)")
      ->check(number_in(0, 1000));
  cmd->add_option("--json", args->json, "also write the figures as JSON");
  cmd->add_option("--plots", args->plots, "with --render: write PREFIX_frame_time.png and PREFIX_memory.png");
  cmd->callback([args] {
    if (int(args->preprocess) + int(args->render) + int(args->edit) + int(args->model) != 1)
      throw usage_error("bench: choose one thing to measure (--preprocess, --render, --edit, --model)");
    if (!args->levels_text.empty()) {
      args->levels.clear();
      std::stringstream items(args->levels_text + ",");
      for (std::string item; std::getline(items, item, ',');) {
        int level = 0;
        const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), level);
        if (item.empty() || ec != std::errc() || end != item.data() + item.size() || level < 1 || level > 64)
          throw usage_error("--levels: " + quoted_token(args->levels_text) + " is not a list of levels 1..64 (" +
                            quoted_token(item) + ")");
        args->levels.push_back(level);
      }
    }
    // Where the figures go is checked before the measuring, which takes minutes.
    for (const std::string& path : {args->json, args->plots.empty() ? std::string() : args->plots + "_frame_time.png",
                                    args->plots.empty() ? std::string() : args->plots + "_memory.png"})
      if (!path.empty()) inspect_save_target(path);
    const auto make_context = [&args] {
      return create_offscreen_context(args->context == "egl"      ? ContextKind::egl
                                      : args->context == "osmesa" ? ContextKind::osmesa
                                                                  : ContextKind::automatic);
    };
    if (!args->operations.empty() && !args->model) throw usage_error("bench: --operations goes with --model");
    if (args->model) {
      std::vector<std::string> operations;
      try {
        operations = modelling_operations_named(args->operations);
      } catch (const Error& e) {
        throw usage_error(std::string("bench --model: --operations: ") + e.what());
      }
      const auto context = make_context();
      const std::string name = args->mesh.empty() ? "sphere" : args->mesh;
      std::printf("device: %s, 1280x720, adaptive 6 px\n", context->description().c_str());
      std::printf("%-30s %-18s %10s %10s %8s %10s %10s %10s %10s %10s %10s %10s %10s %10s %10s %9s %8s\n", "mesh",
                  "operation", "operation", "re-plan", "faces", "full plan", "upload", "frame", "total", "next",
                  "pause", "still", "first edit", "undo", "undo frame", "captures", "still is");
      nlohmann::json all = nlohmann::json::array();
      for (const int faces : args->size ? std::vector<int>{args->size} : std::vector<int>{10000, 100000}) {
        const auto r = modelling_figures(name, faces, args->plans.options(), args->crease_every, operations);
        for (const auto& op : r["operations"]) {
          std::printf("%-30s %-18s",
                      (r["mesh"].get<std::string>() + " (" + std::to_string(r["faces"].get<int>()) + ")").c_str(),
                      op["operation"].get<std::string>().c_str());
          if (op.contains("skipped")) {
            std::printf(" skipped: %s\n", op["skipped"].get<std::string>().c_str());
            continue;
          }
          for (const char* key :
               {"operation_ms", "replan_ms", "faces_planned", "full_replan_ms", "upload_ms", "frame_ms", "total_ms",
                "next_frame_ms", "pause_frame_ms", "still_frame_ms", "first_edit_ms", "undo_ms", "undo_frame_ms"})
            if (op[key].is_number_integer())
              std::printf(" %8d", op[key].get<int>());
            else
              std::printf(" %7.2f ms", op[key].get<double>());
          // How the cache drew: full captures per frame after the operation; the still frame welded,
          // stored as captured, or live (in most rounds).
          const char* still = op["still_welded"].get<double>() > 0.5   ? "welded"
                              : op["still_cached"].get<double>() > 0.5 ? "stored"
                                                                       : "live";
          std::printf(" %9.1f %8s\n", op["frame_captures"].get<double>(), still);
        }
        std::fflush(stdout);
        all.push_back(r);
      }
      if (!args->json.empty())
        write_file_atomically(args->json, [&](std::ostream& out) { out << all.dump(2) << "\n"; });
      return;
    }
    if (args->edit) {
      const auto context = make_context();
      const auto r = edit_figures(args->mesh.empty() ? "sphere" : args->mesh, args->size ? args->size : 100000,
                                  args->plans.options());
      std::printf("device: %s\n%s: %d faces, %d patches, depth %d, 1280x720, adaptive 6 px, %lld triangles per frame\n",
                  context->description().c_str(), r["mesh"].get<std::string>().c_str(), r["faces"].get<int>(),
                  r["patches"].get<int>(), r["depth"].get<int>(), r["triangles"].get<long long>());
      const double frame = r["frame_ms"], one = r["edit_to_frame_1_vertex_ms"],
                   sixteen = r["edit_to_frame_16_vertices_ms"];
      const double full = r["full_recompute_frame_ms"];
      std::printf("%-40s %10.2f ms\n", "frame (draw + glFinish)", frame);
      std::printf("%-40s %10.2f ms\n", "edit-to-frame, 1 vertex", one);
      std::printf("%-40s %10.2f ms\n", "edit-to-frame, 16 vertices", sixteen);
      std::printf("%-40s %10.2f ms\n", "full recompute + frame", full);
      std::printf("%-40s %10.2f ms\n", "set_mesh (topology rebuild, once)", r["set_mesh_ms"].get<double>());
      std::printf("%-40s %10.3f ms\n", "compute only: edit of 1 vertex", r["edit_1_vertex_compute_ms"].get<double>());
      std::printf("%-40s %10.3f ms\n", "compute only: full recompute", r["full_recompute_ms"].get<double>());
      std::printf(
          "edit-to-frame / frame: %.3f (1 vertex), %.3f (16 vertices); full / edit-to-frame: %.2f (1 vertex), %.2f (16 "
          "vertices)\n",
          one / frame, sixteen / frame, full / one, full / sixteen);
      if (!args->json.empty()) write_file_atomically(args->json, [&](std::ostream& out) { out << r.dump(2) << "\n"; });
      return;
    }
    if (args->render) {
      if (!args->size) args->size = 512;
      if (args->size > 4096) throw usage_error("bench --render: --size is at most 4096 pixels");
      const auto context = make_context();
      const PlanOptions plans = args->plans.options();
      std::printf(
          "device: %s, %dx%d pixels, %s\n", context->description().c_str(), args->size, args->size,
          ((plans.exact ? "exact plans of depth " : "the thesis' plans of depth ") + std::to_string(plans.depth))
              .c_str());
      std::printf("%-12s %7s %5s %9s %10s %10s %10s %12s %10s %7s %10s %7s %10s %7s %9s\n", "mesh", "patches", "level",
                  "triangles", "compute", "draw(gpu)", "frame", "tri/s", "static", "ratio", "cached", "ratio", "edit",
                  "ratio", "memory");
      nlohmann::json all = nlohmann::json::array();
      // pawn against pawn-quads: a mixed mesh against its quads-only twin.
      const auto meshes = args->meshes.empty() ? sample_list({"cube", "wirecube", "cylinder", "valence5", "cone-pointy",
                                                              "icosphere", "pawn", "pawn-quads"})
                                               : sample_list(args->meshes);
      for (const auto& [name, faces] : meshes) {
        for (const auto& r : frame_figures(name, faces, plans, args->size, args->levels, args->adaptive_pixels)) {
          const int level = r["level"].get<int>();
          const std::string level_text =
              level > 0 ? std::to_string(level) : "a" + std::to_string(int(r["adaptive_pixels"].get<float>()));
          std::printf(
              "%-12s %7d %5s %9.0f %7.3f ms %7.3f ms %7.2f ms %12.3g %7.2f ms %7.2f %7.2f ms %7.2f %7.2f ms %7.2f "
              "%6.1f kB%s\n",
              r["mesh"].get<std::string>().c_str(), r["patches"].get<int>(), level_text.c_str(),
              r["triangles"].get<double>(), r["compute_gpu_ms"].get<double>(), r["draw_gpu_ms"].get<double>(),
              r["frame_ms"].get<double>(), r["triangles_per_second"].get<double>(),
              r["static_buffer_frame_ms"].get<double>(), r["ratio_to_static_buffer"].get<double>(),
              r["cached_frame_ms"].get<double>(), r["cached_ratio_to_static_buffer"].get<double>(),
              r["edit_frame_ms"].get<double>(), r["edit_ratio_to_static_buffer"].get<double>(),
              r["pipeline_buffer_bytes"].get<double>() / 1024.0,
              r["cache_held"].get<bool>() ? "" : " (past the cache's memory limit: drawn live)");
          std::fflush(stdout);
          all.push_back(r);
        }
      }
      if (!args->json.empty())
        write_file_atomically(args->json, [&](std::ostream& out) { out << all.dump(2) << "\n"; });
      if (!args->plots.empty()) {
        std::map<std::string, PlotSeries> time_over_level, memory_over_time;
        for (const auto& r : all) {
          if (r["level"].get<int>() == 0) continue;  // the adaptive row has no level to plot over
          const std::string mesh = r["mesh"];
          time_over_level[mesh].name = memory_over_time[mesh].name = mesh;
          time_over_level[mesh].points.emplace_back(r["level"].get<double>(), r["frame_ms"].get<double>());
          memory_over_time[mesh].points.emplace_back(
              r["frame_ms"].get<double>(),
              (r["pipeline_buffer_bytes"].get<double>() + r["static_buffer_bytes"].get<double>()) / 1024.0);
        }
        std::vector<PlotSeries> a, b;
        for (auto& [_, s] : time_over_level) a.push_back(s);
        for (auto& [_, s] : memory_over_time) b.push_back(s);
        write_line_plot(args->plots + "_frame_time.png", "Frame time over tessellation level", "level", "frame ms", a,
                        true, true);
        write_line_plot(args->plots + "_memory.png", "Memory over frame time (pipeline + equivalent static mesh)",
                        "frame ms", "kB", b, true, true);
        std::printf("plots: %s_frame_time.png, %s_memory.png\n", args->plots.c_str(), args->plots.c_str());
      }
      return;
    }
    std::vector<std::string> names = {"cube", "wirecube"};
    for (int n = 3; n <= 10; ++n) names.push_back("valence" + std::to_string(n));
    names.insert(names.end(), {"sphere:250", "grid:1000", "grid:10000", "grid:100000", "sphere:1000", "sphere:10000",
                               "sphere:100000", "icosphere:1280", "icosphere:20480", "icosphere:81920",
                               "icosphere:1310720", "cone-pointy"});
    const auto meshes = sample_list(args->meshes.empty() ? names : args->meshes);
    nlohmann::json all = nlohmann::json::array();
    std::printf("%-18s %7s %8s %7s %8s %12s %11s %10s %10s %10s %9s\n", "mesh", "faces", "patches", "rows", "nnz",
                "preprocess", "us/face", "dual map", "apply", "1-vertex", "B/face");
    for (const auto& [name, size] : meshes) {
      const auto r = preprocess_figures(name, size, args->plans.options());
      std::printf("%-18s %7d %8d %7d %8d %9.3f ms %11.3f %7.3f ms %7.3f ms %7.2f us %9.0f\n",
                  r["mesh"].get<std::string>().c_str(), r["faces"].get<int>(), r["patches"].get<int>(),
                  r["stencil_rows"].get<int>(), r["stencil_nonzeros"].get<int>(), r["preprocess_ms"].get<double>(),
                  r["preprocess_us_per_face"].get<double>(), r["dual_map_ms"].get<double>(),
                  r["stencil_apply_ms"].get<double>(), r["stencil_update_one_vertex_us"].get<double>(),
                  r["table_bytes_per_face"].get<double>());
      std::fflush(stdout);
      all.push_back(r);
    }
    if (!args->json.empty()) write_file_atomically(args->json, [&](std::ostream& out) { out << all.dump(2) << "\n"; });
  });
}

}  // namespace gps
