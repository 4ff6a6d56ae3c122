// File → Simplify… and Fit to…: the long mesh computations, each in a dialog whose job runs in the background
// (ui/panels/job_dialog.h) and whose result replaces the mesh as one undo step; a fit's target is then shown
// as points over the surface (ui/editor/editor_target_points.cpp).
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "core/fitting/fit_progress.h"
#include "core/fitting/limit_fit.h"
#include "core/fitting/mesh_simplification.h"
#include "core/fitting/surface_distance.h"
#include "core/io/mesh_io.h"
#include "core/support/error.h"
#include "ui/editor/editor_app.h"

namespace gps {

namespace {

/// The limit surface a preview measures: coarse enough to take a moment, fine enough to show the error.
constexpr int kPreviewLevel = 6;
constexpr double kPreviewTriangles = 4e5;

/// "0.12 %" of a relative distance.
std::string percent(double relative) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %%", 100.0 * relative);
  return text;
}

/// Throws Cancelled when the report asks to stop.
void report_or_stop(const ProgressReport& report, double fraction) {
  if (!report(fraction)) throw Cancelled();
}

}  // namespace

void EditorApp::open_simplify_dialog() {
  if (modal_active()) return;
  job_is_fit_ = false;
  const auto input = std::make_shared<const CovarianceMesh>(document_.mesh());
  auto settings = std::make_shared<SimplifySettings>(simplify_settings_);
  settings->vertices = std::clamp(settings->vertices, 4, std::max(4, int(input->n_vertices())));
  if (settings->vertices >= int(input->n_vertices())) settings->vertices = std::max(4, int(input->n_vertices()) / 10);
  JobDialog::Spec spec;
  spec.title = "Simplify";
  spec.settings = [this, settings, n = input->n_vertices()] {
    ImGui::Text("%zu vertices now", n);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::InputInt("vertices to keep", &settings->vertices, 0);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::InputDouble("bias", &settings->bias, 0.0, 0.0, "%.3g");
    simplify_settings_ = *settings;
  };
  spec.work = [input, settings]() -> BackgroundJob::Work {
    if (settings->vertices < 4) throw Error("keep at least 4 vertices");
    if (size_t(settings->vertices) >= input->n_vertices())
      throw Error("keep fewer than the " + std::to_string(input->n_vertices()) + " vertices there are");
    if (!(settings->bias > 0.0)) throw Error("the bias must be positive");
    SimplifyOptions options;
    options.target_vertices = size_t(settings->vertices);
    options.bias = settings->bias;
    return [input, options](const ProgressReport& report) mutable {
      options.progress = [&report](double fraction) { return report(0.8 * fraction); };
      const SimplifiedMesh s = simplify_mesh(*input, options);
      report_or_stop(report, 0.8);
      const LimitTriangles limit = limit_surface_triangles(s.mesh, kPreviewLevel, {}, kPreviewTriangles);
      report_or_stop(report, 0.9);
      const DistanceSummary d = distances_to_surface(vertex_means(*input), limit.triangles);
      Modelled m;
      m.mesh = s.mesh;
      m.summary = "simplified " + std::to_string(s.input_vertices) + " to " + std::to_string(s.mesh.n_vertices()) +
                  " vertices; the input lies from the new surface within rms " + percent(d.relative_rms()) +
                  ", max " + percent(d.relative_max()) + " of its size";
      return m;
    };
  };
  job_dialog_.open(std::move(spec));
}

void EditorApp::open_fit_dialog() {
  if (modal_active()) return;
  job_is_fit_ = true;
  const auto coarse = std::make_shared<const CovarianceMesh>(document_.mesh());
  auto settings = std::make_shared<FitSettings>(fit_settings_);
  // At first the file the mesh came from: after Simplify… the dense mesh a fit most likely wants.
  if (settings->target.empty()) settings->target = document_.source_path();
  JobDialog::Spec spec;
  spec.title = "Fit to";
  spec.settings = [this, settings] {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 24.0f);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::InputText("target mesh", &settings->target);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::InputInt("iterations", &settings->iterations, 0);
    ImGui::Checkbox("positions only (plain subdivision fit)", &settings->plain);
    fit_settings_ = *settings;
  };
  spec.work = [coarse, settings]() -> BackgroundJob::Work {
    if (settings->target.empty()) throw Error("name the mesh to fit to");
    if (settings->iterations < 1 || settings->iterations > 1000) throw Error("iterations must be 1 to 1000");
    FitOptions options;
    options.iterations = settings->iterations;
    options.plain = settings->plain;
    return [coarse, options, path = settings->target](const ProgressReport& report) mutable {
      bool has_covariances = false;
      const std::vector<Vec3> targets = read_polygon_soup(path, has_covariances).positions;
      if (targets.empty()) throw Error(path + ": has no vertices to fit to");
      report_or_stop(report, 0.05);
      options.progress = [&report, done = FitProgress(options)](const FitIteration& it) mutable {
        report_or_stop(report, 0.05 + 0.95 * done.after(it));
      };
      const FitResult fit = fit_limit_surface(*coarse, targets, options);
      const DistanceSummary& before = fit.iterations.front().error;
      const DistanceSummary& after = fit.iterations.back().error;
      Modelled m;
      m.mesh = fit.mesh;
      m.summary = "fitted to the " + std::to_string(targets.size()) + " points of " + path + " in " +
                  std::to_string(fit.iterations.size() - 1) + " iterations: rms " + percent(before.relative_rms()) +
                  " to " + percent(after.relative_rms()) + ", max " + percent(before.relative_max()) + " to " +
                  percent(after.relative_max()) + " of their size";
      return m;
    };
  };
  job_dialog_.open(std::move(spec));
}

void EditorApp::draw_job_dialog() {
  std::optional<Modelled> result = job_dialog_.draw();
  if (!result) return;
  try {
    install(*result);
    operation_note(last_summary_, false);
    if (job_is_fit_) show_target_points(fit_settings_.target);  // how far the fit came, point by point
  } catch (const Error& e) {
    operation_note(e.what(), true);
  }
}

}  // namespace gps
