#pragma once
// The threads background calls run on (python/background_call.h), kept for the next call: a thread's
// first parallel region starts its OpenMP team, and its first operations fill the caches that core
// keeps per thread, which a new thread per call would pay again on every call.
#include <functional>

namespace gps::python {

/// Runs `task` on the idle worker thread that was busy last (its OpenMP team and caches are warm), or
/// on a new one where every worker is busy (calls from several Python threads still run side by side),
/// then `done` once the worker counts as idle again, so that a call made as soon as `done` signals its
/// caller finds the worker rather than making another. Workers wait for the next task once done and
/// stay until the process ends; a child made by fork() starts without any.
void run_on_worker(std::function<void()> task, std::function<void()> done);

}  // namespace gps::python
