#pragma once
// A long mesh computation (simplify, fit) run on a thread of its own while the editor keeps
// drawing: its progress for a bar, a Cancel that stops it, and its result or refusal, taken once.
#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/modelling/mesh_arrays.h"
#include "core/support/progress.h"

namespace gps {

class BackgroundJob {
public:
  /// The computation: given a progress report to call now and then, the mesh it makes. It must
  /// not touch the editor's state (it runs beside the frames); errors are thrown as gps::Error.
  using Work = std::function<Modelled(const ProgressReport&)>;

  BackgroundJob() = default;
  ~BackgroundJob();  // stops a job still running and waits for it
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  /// Starts `work` (a job still running is stopped first and its outcome dropped).
  void start(Work work);
  /// Whether a job was started and its outcome not yet taken.
  bool active() const { return thread_.joinable(); }
  /// Whether the active job has ended (made its mesh, failed or been cancelled).
  bool finished() const { return finished_; }
  /// The fraction done it last reported.
  double progress() const { return progress_; }
  /// Asks the job to stop at its next report.
  void cancel() { cancel_ = true; }

  /// The outcome of a finished job: the mesh, or nullopt with `refusal` set to why (an error's
  /// message, or "cancelled"). Ends the job (active() is false after).
  std::optional<Modelled> take(std::string& refusal);

private:
  void stop();
  std::thread thread_;
  std::atomic<bool> finished_{false}, cancel_{false};
  std::atomic<double> progress_{0.0};
  std::mutex mutex_;  // guards the outcome
  std::optional<Modelled> result_;
  std::string refusal_;
};

}  // namespace gps
