// gpsurf bench --preprocess: plan building and stencil application, per mesh (issue "plans").
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "core/atomic_file.h"
#include "core/dual_map.h"
#include "core/error.h"
#include "core/plan_builder.h"
#include "core/samples.h"
#include "core/stencil_table.h"

namespace gps {

namespace {

using Clock = std::chrono::steady_clock;

// Median seconds of `f` over repeats that fill about `budget` seconds (at least 3, at most 200).
template <class F>
double median_seconds(F&& f, double budget = 0.3) {
  std::vector<double> times;
  const auto start = Clock::now();
  while (times.size() < 3 || (times.size() < 200 && std::chrono::duration<double>(Clock::now() - start).count() < budget)) {
    const auto t0 = Clock::now();
    f();
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::nth_element(times.begin(), times.begin() + long(times.size() / 2), times.end());
  return times[times.size() / 2];
}

nlohmann::json bench_preprocess(const std::string& name, int size, int depth) {
  const CovarianceMesh mesh = make_sample(name, size);
  const PolygonTopology topology = topology_of(mesh.mesh);
  PlanTables tables;
  const double preprocess = median_seconds([&] { tables = build_plans(topology, depth); });
  std::vector<Dual> q(mesh.n_vertices());
  for (size_t i = 0; i < q.size(); ++i) q[i] = to_dual(mesh.mean(i), mesh.covariance(i));
  std::vector<Dual> points;
  const double apply = median_seconds([&] { points = apply_stencils(tables.stencils, q); });
  const StencilDependents deps = stencil_dependents(tables.stencils);
  const std::vector<int> one_vertex = {int(mesh.n_vertices() / 2)};
  const double update = median_seconds([&] { update_stencils(tables.stencils, deps, one_vertex, points); });
  const double dual_map = median_seconds([&] {
    for (size_t i = 0; i < q.size(); ++i) q[i] = to_dual(mesh.mean(i), mesh.covariance(i));
  });
  return {{"mesh", name + (size ? "/" + std::to_string(size) : "")},
          {"faces", mesh.n_faces()},
          {"patches", tables.plans.n_patches()},
          {"depth", depth},
          {"nodes_ints", tables.plans.nodes.size()},
          {"stencil_rows", tables.stencils.n_rows()},
          {"stencil_nonzeros", tables.stencils.indices.size()},
          {"preprocess_ms", preprocess * 1e3},
          {"preprocess_us_per_face", preprocess * 1e6 / double(mesh.n_faces())},
          {"dual_map_ms", dual_map * 1e3},
          {"stencil_apply_ms", apply * 1e3},
          {"stencil_update_one_vertex_us", update * 1e6}};
}

}  // namespace

void add_bench_command(CLI::App& app) {
  struct Args {
    bool preprocess = false;
    int depth = 3;
    std::string json;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("bench", "Benchmarks (figures for the closing notes; see also build/bench/)");
  cmd->add_flag("--preprocess", args->preprocess, "plan building and stencil application per mesh");
  cmd->add_option("--depth", args->depth, "maximum plan depth")->check(CLI::Range(1, 8));
  cmd->add_option("--json", args->json, "also write the figures as JSON");
  cmd->callback([args] {
    if (!args->preprocess) throw usage_error("bench: choose what to measure (--preprocess)");
    std::vector<std::pair<std::string, int>> meshes = {{"cube", 0}, {"wirecube", 0}};
    for (int n = 3; n <= 10; ++n) meshes.emplace_back("valence" + std::to_string(n), 0);
    meshes.insert(meshes.end(), {{"sphere", 250}, {"grid", 1000}, {"grid", 10000}, {"grid", 100000},
                                 {"sphere", 1000}, {"sphere", 10000}, {"sphere", 100000}});
    nlohmann::json all = nlohmann::json::array();
    std::printf("%-14s %7s %8s %7s %8s %12s %11s %10s %10s %10s\n", "mesh", "faces", "patches", "rows", "nnz",
                "preprocess", "us/face", "dual map", "apply", "1-vertex");
    for (const auto& [name, size] : meshes) {
      const auto r = bench_preprocess(name, size, args->depth);
      std::printf("%-14s %7d %8d %7d %8d %9.3f ms %11.3f %7.3f ms %7.3f ms %7.2f us\n", r["mesh"].get<std::string>().c_str(),
                  r["faces"].get<int>(), r["patches"].get<int>(), r["stencil_rows"].get<int>(), r["stencil_nonzeros"].get<int>(),
                  r["preprocess_ms"].get<double>(), r["preprocess_us_per_face"].get<double>(), r["dual_map_ms"].get<double>(),
                  r["stencil_apply_ms"].get<double>(), r["stencil_update_one_vertex_us"].get<double>());
      std::fflush(stdout);
      all.push_back(r);
    }
    if (!args->json.empty()) write_file_atomically(args->json, [&](std::ostream& out) { out << all.dump(2) << "\n"; });
  });
}

}  // namespace gps
