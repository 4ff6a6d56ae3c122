#include "python/worker_threads.h"

#include <pthread.h>

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace gps::python {
namespace {

struct Workers {
  std::mutex mutex;
  std::condition_variable woken;
  struct Task {
    std::function<void()> run, done;
  };
  std::deque<Task> tasks;
  int idle = 0;  // workers waiting for a task
};

// Never destroyed: idle workers wait on it until the process ends.
Workers* workers = nullptr;

void work(Workers* w) {
  std::unique_lock lock(w->mutex);
  for (;;) {
    w->woken.wait(lock, [w] { return !w->tasks.empty(); });
    --w->idle;
    Workers::Task task = std::move(w->tasks.front());
    w->tasks.pop_front();
    lock.unlock();
    task.run();
    task.run = nullptr;  // what it holds is released before the caller hears
    lock.lock();
    ++w->idle;
    task.done();
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
  w.tasks.push_back({std::move(task), std::move(done)});
  if (w.tasks.size() > size_t(w.idle)) {
    ++w.idle;  // the new worker, idle until it takes a task
    std::thread(work, &w).detach();
  } else {
    w.woken.notify_one();
  }
}

}  // namespace gps::python
