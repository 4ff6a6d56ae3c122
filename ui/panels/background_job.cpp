#include "ui/panels/background_job.h"

#include <new>

#include "core/support/error.h"

namespace gps {

BackgroundJob::~BackgroundJob() { stop(); }

void BackgroundJob::stop() {
  if (!thread_.joinable()) return;
  cancel_ = true;
  thread_.join();
}

void BackgroundJob::start(Work work) {
  stop();
  finished_ = false;
  cancel_ = false;
  progress_ = 0.0;
  result_.reset();
  refusal_.clear();
  thread_ = std::thread([this, work = std::move(work)] {
    const ProgressReport report = [this](double fraction) {
      progress_ = fraction;
      return !cancel_.load();
    };
    std::optional<Modelled> result;
    std::string refusal;
    try {
      result = work(report);
    } catch (const Error& e) {
      refusal = e.what();
    } catch (const std::bad_alloc&) {
      refusal = "out of memory";
    } catch (const std::exception& e) {
      refusal = e.what();
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      result_ = std::move(result);
      refusal_ = std::move(refusal);
    }
    finished_ = true;
  });
}

std::optional<Modelled> BackgroundJob::take(std::string& refusal) {
  if (!thread_.joinable() || !finished_) return std::nullopt;
  thread_.join();
  const std::lock_guard<std::mutex> lock(mutex_);
  refusal = refusal_;
  return std::move(result_);
}

}  // namespace gps
