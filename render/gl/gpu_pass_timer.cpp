#include "render/gl/gpu_pass_timer.h"

#include <glad/gl.h>

#include "core/support/error.h"
#include "render/gl/gl_context.h"

namespace gps {

namespace {
constexpr int kSlots = 4;  // frames a pass's results may lag before it goes untimed
}

GpuPassTimer::GpuPassTimer() : software_(software_renderer()) {}
GpuPassTimer::~GpuPassTimer() = default;

void GpuPassTimer::begin(const std::string& pass, Work work) {
  if (open_ >= 0) throw Error("GPU pass '" + pass + "' begun inside '" + passes_[size_t(open_)].name + "'");
  size_t i = 0;
  while (i < passes_.size() && passes_[i].name != pass) ++i;
  if (i == passes_.size()) {
    const bool by_clock = software_ && work == Work::dispatches;
    passes_.push_back(
        {pass, by_clock ? nullptr : std::make_unique<QueryRing>(std::vector<unsigned>{GL_TIME_ELAPSED}, kSlots), {}});
  }
  if (passes_[i].queries)
    passes_[i].queries->begin();
  else
    clock_start_ = std::chrono::steady_clock::now();
  open_ = int(i);
}

void GpuPassTimer::end() {
  if (open_ < 0) throw Error("GPU pass ended without a begin");
  Pass& pass = passes_[size_t(open_)];
  if (pass.queries)
    pass.queries->end();
  else
    pass.clock_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - clock_start_).count();
  open_ = -1;
}

std::vector<std::pair<std::string, double>> GpuPassTimer::latest() {
  std::vector<std::pair<std::string, double>> out;
  for (const Pass& p : passes_)
    if (!p.queries) {
      if (p.clock_ms) out.emplace_back(p.name, *p.clock_ms);
    } else if (const auto& ns = p.queries->latest()) {
      out.emplace_back(p.name, double((*ns)[0]) * 1e-6);
    }
  return out;
}

GpuPassScope::GpuPassScope(GpuPassTimer* timer, const std::string& pass, GpuPassTimer::Work work) : timer_(timer) {
  if (timer_) timer_->begin(pass, work);
}

GpuPassScope::~GpuPassScope() {
  if (timer_) timer_->end();
}

}  // namespace gps
