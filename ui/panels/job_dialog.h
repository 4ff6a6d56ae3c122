#pragma once
// A dialog for a long mesh computation (File → Simplify…, Fit to…): its settings and Start; while it
// runs in the background a progress bar and Cancel; then what it made, with Apply (one undo step)
// or Discard. Enter starts and applies, Esc cancels and discards; the mesh is not changed until Apply.
#include <functional>
#include <optional>
#include <string>

#include "ui/panels/background_job.h"

namespace gps {

class JobDialog {
public:
  struct Spec {
    std::string title;                          // the window's title: "Simplify"
    std::function<void()> settings;             // draws the settings' widgets (Dear ImGui)
    std::function<BackgroundJob::Work()> work;  // on Start: the job for the settings as they are
                                                // (throws gps::Error for settings it cannot use)
  };

  /// Opens the dialog (a job of a dialog still open is stopped).
  void open(Spec spec);
  bool is_open() const { return open_; }
  /// Whether its job is running: a replay waits for it rather than going on.
  bool running() const { return job_.active() && !job_.finished(); }

  /// Draws the dialog; returns the mesh the user applied, once.
  std::optional<Modelled> draw();

private:
  void start();
  void close();
  Spec spec_;
  bool open_ = false, popup_requested_ = false;
  BackgroundJob job_;
  std::optional<Modelled> made_;  // the finished job's mesh, until applied or discarded
  std::string note_;              // the refusal, or what was made
  bool note_is_error_ = false;
};

}  // namespace gps
