#include "render/gl/gpu_pass_timer.h"

#include <glad/gl.h>

#include "core/support/error.h"

namespace gps {

namespace {
constexpr int kSlots = 4;  // frames a pass's results may lag before it goes untimed
}

GpuPassTimer::GpuPassTimer() = default;
GpuPassTimer::~GpuPassTimer() = default;

void GpuPassTimer::begin(const std::string& pass) {
  if (open_ >= 0) throw Error("GPU pass '" + pass + "' begun inside '" + passes_[size_t(open_)].name + "'");
  size_t i = 0;
  while (i < passes_.size() && passes_[i].name != pass) ++i;
  if (i == passes_.size())
    passes_.push_back({pass, std::make_unique<QueryRing>(std::vector<unsigned>{GL_TIME_ELAPSED}, kSlots)});
  passes_[i].queries->begin();
  open_ = int(i);
}

void GpuPassTimer::end() {
  if (open_ < 0) throw Error("GPU pass ended without a begin");
  passes_[size_t(open_)].queries->end();
  open_ = -1;
}

std::vector<std::pair<std::string, double>> GpuPassTimer::latest() {
  std::vector<std::pair<std::string, double>> out;
  for (const Pass& p : passes_)
    if (const auto& ns = p.queries->latest()) out.emplace_back(p.name, double((*ns)[0]) * 1e-6);
  return out;
}

GpuPassScope::GpuPassScope(GpuPassTimer* timer, const std::string& pass) : timer_(timer) {
  if (timer_) timer_->begin(pass);
}

GpuPassScope::~GpuPassScope() {
  if (timer_) timer_->end();
}

}  // namespace gps
