#pragma once
// The subcommands of `gpsurf`, one file each (app/cmd_<name>.cpp).
#include <CLI/CLI.hpp>

namespace gps {
void add_info_command(CLI::App& app);
void add_sample_command(CLI::App& app);
void add_infer_command(CLI::App& app);
void add_subdivide_command(CLI::App& app);
void add_tessellate_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_diff_command(CLI::App& app);
void add_edit_command(CLI::App& app);
void add_simplify_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_fit_command(CLI::App& app);
}  // namespace gps
