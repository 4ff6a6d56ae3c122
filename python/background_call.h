#pragma once
// A computing call run off the interpreter: the work runs on a worker thread without the GIL,
// while the calling thread wakes every few milliseconds to check for Ctrl-C and to pass the work's
// progress to an optional Python callback. Other Python threads run meanwhile.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <utility>

#include "core/support/progress.h"
#include "python/worker_threads.h"

namespace gps::python {

namespace py = pybind11;

/// What a call's work and its caller share: the caller asks it to stop, the work reports how far it is.
class CallControl {
public:
  /// Whether the caller asked the work to stop (Ctrl-C, or the progress callback returned False).
  bool stop_requested() const { return stop_.load(std::memory_order_relaxed); }
  /// The fraction done, 0 to 1.
  void report(double fraction) { fraction_.store(fraction, std::memory_order_relaxed); }
  /// A core ProgressReport that records the fraction and asks the computation to stop when the caller did.
  ProgressReport progress_report() {
    return [this](double fraction) {
      report(fraction);
      return !stop_requested();
    };
  }
  /// Throws gps::Cancelled if the caller asked the work to stop.
  void throw_if_stopped() const {
    if (stop_requested()) throw Cancelled();
  }

  /// Asks the work to stop (the caller's side).
  void request_stop() { stop_.store(true, std::memory_order_relaxed); }
  /// The last fraction reported, or −1 before the first.
  double fraction() const { return fraction_.load(std::memory_order_relaxed); }

private:
  std::atomic<bool> stop_{false};
  std::atomic<double> fraction_{-1};
};

/// Whether the interpreter is finalizing: Python then ends any other thread that takes the GIL.
inline bool interpreter_finalizing() {
#if PY_VERSION_HEX >= 0x030D0000
  return Py_IsFinalizing();
#else
  return _Py_IsFinalizing();
#endif
}

/// `work()` run with the GIL released; its result, or its exception, once the GIL is taken back.
/// Taken back in plain code, not in a destructor as pybind11's gil_scoped_release does: while the
/// interpreter finalizes, Python ends any other thread that takes the GIL with an unwind, which aborts
/// the process where it meets a noexcept frame. Such a thread (a daemon thread at exit) waits for the
/// process to end instead; the thread finalizing the interpreter (releasing the GIL in a finalizer)
/// takes it back.
template <class Work>
auto without_gil(Work&& work) {
  using Result = decltype(work());
  if constexpr (std::is_void_v<Result>) {
    without_gil([&] {
      work();
      return true;
    });
  } else {
    const bool finalizing_thread = interpreter_finalizing();  // only it runs Python once finalizing
    PyThreadState* const state = PyEval_SaveThread();
    std::optional<Result> result;
    std::exception_ptr error;
    try {
      result.emplace(work());
    } catch (...) {
      error = std::current_exception();
    }
    while (!finalizing_thread && interpreter_finalizing()) std::this_thread::sleep_for(std::chrono::hours(1));
    PyEval_RestoreThread(state);
    if (error) std::rethrow_exception(error);
    return std::move(*result);
  }
}

namespace detail {
template <class Result>
struct BackgroundJob {
  CallControl control;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::optional<Result> result;
  std::exception_ptr error;
};
/// How often the calling thread checks for Ctrl-C and progress.
inline constexpr std::chrono::milliseconds kPollInterval{20};
}  // namespace detail

/// Runs `work(CallControl&)` on a worker thread (python/worker_threads.h) with the GIL released and
/// returns its result (or rethrows its exception) on the calling thread. Ctrl-C stops the call within
/// kPollInterval plus the time the work takes to notice stop_requested(): when `stops_promptly`, the
/// caller waits for it; otherwise it raises KeyboardInterrupt at once and the work, which owns
/// everything it reads, finishes unseen. `progress`, if not None, is called with the fraction done whenever it changed; a
/// False return stops the call with gpsurf.Error("cancelled"), an exception stops it and propagates.
template <class Work>
auto call_in_background(Work work, const py::object& progress, bool stops_promptly) {
  using Result = decltype(work(std::declval<CallControl&>()));
  auto job = std::make_shared<detail::BackgroundJob<Result>>();
  run_on_worker(
      [job, work = std::make_shared<Work>(std::move(work))] {
        try {
          job->result.emplace((*work)(job->control));
        } catch (...) {
          job->error = std::current_exception();
        }
      },
      [job] {
        std::lock_guard lock(job->mutex);
        job->done = true;
        job->finished.notify_all();
      });
  const auto wait = [&](std::optional<std::chrono::milliseconds> limit) {
    return without_gil([&] {
      std::unique_lock lock(job->mutex);
      if (!limit) {
        job->finished.wait(lock, [&] { return job->done; });
        return true;
      }
      return job->finished.wait_for(lock, *limit, [&] { return job->done; });
    });
  };
  double reported = -1;
  // Whether the callback's answer says to go on. An answer whose truth raises (a numpy array of
  // several values) raises, not cancels, at every call, the last included.
  const auto answer_goes_on = [&](double fraction) {
    const py::object answer = progress(fraction);
    const int truth = answer.is_none() ? 1 : PyObject_IsTrue(answer.ptr());
    if (truth < 0) throw py::error_already_set();
    return truth == 1;
  };
  const auto stop = [&] {
    job->control.request_stop();
    if (stops_promptly) wait(std::nullopt);
  };
  while (!wait(detail::kPollInterval)) {
    if (PyErr_CheckSignals() != 0) {
      stop();
      throw py::error_already_set();
    }
    const double fraction = job->control.fraction();
    if (!progress.is_none() && fraction != reported && fraction >= 0) {
      reported = fraction;
      bool go_on = true;
      try {
        go_on = answer_goes_on(fraction);
      } catch (...) {
        stop();
        throw;
      }
      if (!go_on) {
        stop();
        throw Cancelled();
      }
    }
  }
  if (job->error) std::rethrow_exception(job->error);
  // The work is done: a False answer now has nothing to cancel.
  if (!progress.is_none() && reported < 1) answer_goes_on(1.0);
  return std::move(*job->result);
}

/// Runs `work(CallControl&)` in the calling thread with the GIL released: for calls too short to be
/// worth a thread of their own, which Ctrl-C then interrupts when they return.
template <class Work>
auto call_released(Work work) {
  CallControl control;
  return without_gil([&] { return work(control); });
}

}  // namespace gps::python
