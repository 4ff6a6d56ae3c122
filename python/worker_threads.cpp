#include "python/worker_threads.h"

#include <pthread.h>

#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace gps::python {
namespace {

// One worker thread: the task it was handed, if any, and where it waits for the next.
struct Worker {
  std::condition_variable woken;
  std::function<void()> run, done;
  bool has_task = false;
};

struct Workers {
  std::mutex mutex;
  std::vector<Worker*> idle;  // waiting for a task, the most recently busy last
};

// Never destroyed: idle workers wait on them until the process ends.
Workers* workers = nullptr;

void work(Workers* w, Worker* self) {
  std::unique_lock lock(w->mutex);
  for (;;) {
    self->woken.wait(lock, [self] { return self->has_task; });
    self->has_task = false;
    std::function<void()> run = std::move(self->run), done = std::move(self->done);
    lock.unlock();
    run();
    run = nullptr;  // what it holds is released before the caller hears
    lock.lock();
    w->idle.push_back(self);
    done();
  }
}

// A forked child has none of the parent's threads: it starts a set of its own.
void forget_workers_in_child() { workers = new Workers; }

Workers& the_workers() {
  static const bool made = [] {
    workers = new Workers;
    pthread_atfork(nullptr, nullptr, forget_workers_in_child);
    return true;
  }();
  (void)made;
  return *workers;
}

}  // namespace

void run_on_worker(std::function<void()> task, std::function<void()> done) {
  Workers& w = the_workers();
  std::lock_guard lock(w.mutex);
  // The worker that finished last: its OpenMP team and per-thread caches are the warmest.
  Worker* worker = nullptr;
  if (w.idle.empty()) {
    worker = new Worker;  // waits for its tasks until the process ends
    std::thread(work, &w, worker).detach();
  } else {
    worker = w.idle.back();
    w.idle.pop_back();
  }
  worker->run = std::move(task);
  worker->done = std::move(done);
  worker->has_task = true;
  worker->woken.notify_one();
}

}  // namespace gps::python
