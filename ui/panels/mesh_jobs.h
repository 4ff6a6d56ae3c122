#pragma once
// File → Simplify… and Fit to…: the dialog of each long mesh computation (ui/panels/job_dialog.h), the
// settings each had last (kept between openings), the work those settings make, and what the user
// applied, handed back once.
#include <memory>
#include <optional>
#include <string>

#include "core/fitting/limit_fit.h"
#include "core/mesh/covariance_mesh.h"
#include "ui/panels/job_dialog.h"

namespace gps {

class MeshJobs {
public:
  struct SimplifySettings {
    int vertices = 0;  // 0: a tenth of the mesh's
    double bias = 0.05;
  };
  struct FitSettings {
    std::string target;  // the dense mesh
    int iterations = FitOptions().iterations;
    bool plain = false;
  };
  /// What an applied job made; for a fit, the file fitted to (shown as points over the surface).
  struct Applied {
    Modelled made;
    std::optional<std::string> fit_target;
  };

  /// Opens Simplify… on `input`, the vertices to keep clamped to what it has.
  void open_simplify(std::shared_ptr<const CovarianceMesh> input);
  /// Opens Fit to… on `coarse`, the target at first `source_path` (after Simplify…, the dense mesh it came
  /// from is the target a fit most likely wants).
  void open_fit(std::shared_ptr<const CovarianceMesh> coarse, const std::string& source_path);
  /// Draws the dialog open (Dear ImGui); what the user applied, once.
  std::optional<Applied> draw();
  bool is_open() const { return dialog_.is_open(); }
  /// Whether a job is running: a replay waits for it rather than going on.
  bool running() const { return dialog_.running(); }

  /// The work of each dialog's Start for `settings`; throws gps::Error for settings it cannot use.
  static BackgroundJob::Work simplify_work(std::shared_ptr<const CovarianceMesh> input,
                                           const SimplifySettings& settings);
  static BackgroundJob::Work fit_work(std::shared_ptr<const CovarianceMesh> coarse, const FitSettings& settings);

private:
  SimplifySettings simplify_;
  FitSettings fit_;
  JobDialog dialog_;
  bool is_fit_ = false;  // the dialog open is Fit to…
};

}  // namespace gps
