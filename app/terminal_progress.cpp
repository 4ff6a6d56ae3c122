#include "app/terminal_progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace gps {
namespace {

constexpr int kBarWidth = 30;
constexpr double kRedrawSeconds = 0.1;

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

TerminalProgress::TerminalProgress(std::string stage, bool quiet)
    : TerminalProgress(std::move(stage), std::cerr, !quiet && ::isatty(STDERR_FILENO) == 1, steady_seconds) {}

TerminalProgress::TerminalProgress(std::string stage, std::ostream& out, bool shown, Clock clock)
    : stage_(std::move(stage)), out_(out), shown_(shown), clock_(std::move(clock)), start_(clock_()) {}

TerminalProgress::~TerminalProgress() {
  if (shown_ && last_drawn_ >= 0 && !finished_) out_ << "\n" << std::flush;
}

void TerminalProgress::update(double fraction) {
  if (!shown_ || finished_) return;
  const double now = clock_();
  if (last_drawn_ >= 0 && now - last_drawn_ < kRedrawSeconds) return;
  last_drawn_ = now;
  draw(fraction);
}

ProgressReport TerminalProgress::report() {
  return [this](double fraction) {
    update(fraction);
    return true;
  };
}

void TerminalProgress::clear() {
  if (!shown_ || last_drawn_ < 0) return;
  out_ << "\r" << std::string(drawn_width_, ' ') << "\r" << std::flush;
  last_drawn_ = -1;
}

void TerminalProgress::finish() {
  if (!shown_ || finished_) return;
  last_drawn_ = clock_();
  draw(1);
  out_ << "\n" << std::flush;
  finished_ = true;
}

void TerminalProgress::draw(double fraction) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const int filled = int(std::floor(fraction * kBarWidth));
  char numbers[64];
  std::snprintf(numbers, sizeof numbers, "] %3d%% %6.1f s", int(std::floor(fraction * 100)), last_drawn_ - start_);
  const std::string line = stage_ + " [" + std::string(size_t(filled), '#') +
                           std::string(size_t(kBarWidth - filled), ' ') + numbers;
  out_ << "\r" << line << std::flush;
  drawn_width_ = line.size();
}

}  // namespace gps
