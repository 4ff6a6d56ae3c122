#include "ui/panels/mesh_jobs.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

#include "core/fitting/face_triangles.h"
#include "core/fitting/fit_progress.h"
#include "core/fitting/mesh_simplification.h"
#include "core/fitting/surface_distance.h"
#include "core/io/mesh_io.h"
#include "core/support/error.h"

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

BackgroundJob::Work MeshJobs::simplify_work(std::shared_ptr<const CovarianceMesh> input,
                                            const SimplifySettings& settings) {
  if (settings.vertices < 4) throw Error("keep at least 4 vertices");
  if (size_t(settings.vertices) >= input->n_vertices())
    throw Error("keep fewer than the " + std::to_string(input->n_vertices()) + " vertices there are");
  if (!(settings.bias > 0.0)) throw Error("the bias must be positive");
  SimplifyOptions options;
  options.target_vertices = size_t(settings.vertices);
  options.bias = settings.bias;
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
                " vertices; the input lies from the new surface within rms " + percent(d.relative_rms()) + ", max " +
                percent(d.relative_max()) + " of its size";
    return m;
  };
}

BackgroundJob::Work MeshJobs::fit_work(std::shared_ptr<const CovarianceMesh> coarse, const FitSettings& settings) {
  if (settings.target.empty()) throw Error("name the mesh to fit to");
  if (settings.iterations < 1 || settings.iterations > 1000) throw Error("iterations must be 1 to 1000");
  FitOptions options;
  options.iterations = settings.iterations;
  options.plain = settings.plain;
  return [coarse, options, path = settings.target](const ProgressReport& report) mutable {
    bool has_covariances = false;
    const PolygonSoup soup = read_polygon_soup(path, has_covariances);
    const std::vector<Vec3>& targets = soup.positions;
    if (targets.empty()) throw Error(path + ": has no vertices to fit to");
    report_or_stop(report, 0.05);
    options.progress = [&report, done = FitProgress(options)](const FitIteration& it) mutable {
      report_or_stop(report, 0.05 + 0.95 * done.after(it));
    };
    const FitResult fit = fit_limit_surface(*coarse, targets, options, smooth_vertex_normals(face_triangles(soup)));
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
}

void MeshJobs::open_simplify(std::shared_ptr<const CovarianceMesh> input) {
  is_fit_ = false;
  SimplifySettings& s = simplify_;
  const int n = int(input->n_vertices());
  s.vertices = std::clamp(s.vertices, 4, std::max(4, n));
  if (s.vertices >= n) s.vertices = std::max(4, n / 10);
  JobDialog::Spec spec;
  spec.title = "Simplify";
  spec.settings = [this, n] {
    ImGui::Text("%d vertices now", n);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::InputInt("vertices to keep", &simplify_.vertices, 0);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::InputDouble("bias", &simplify_.bias, 0.0, 0.0, "%.3g");
  };
  spec.work = [this, input] { return simplify_work(input, simplify_); };
  dialog_.open(std::move(spec));
}

void MeshJobs::open_fit(std::shared_ptr<const CovarianceMesh> coarse, const std::string& source_path) {
  is_fit_ = true;
  if (fit_.target.empty()) fit_.target = source_path;
  JobDialog::Spec spec;
  spec.title = "Fit to";
  spec.settings = [this] {
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 24.0f);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::InputText("target mesh", &fit_.target);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::InputInt("iterations", &fit_.iterations, 0);
    ImGui::Checkbox("positions only (plain subdivision fit)", &fit_.plain);
  };
  spec.work = [this, coarse] { return fit_work(coarse, fit_); };
  dialog_.open(std::move(spec));
}

std::optional<MeshJobs::Applied> MeshJobs::draw() {
  std::optional<Modelled> made = dialog_.draw();
  if (!made) return std::nullopt;
  return Applied{std::move(*made), is_fit_ ? std::optional<std::string>(fit_.target) : std::nullopt};
}

}  // namespace gps
