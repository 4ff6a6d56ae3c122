#include "render/gl/query_ring.h"

#include <glad/gl.h>

#include "core/support/error.h"
#include "render/gl/gl_context.h"

namespace gps {

QueryRing::QueryRing(const std::vector<unsigned>& targets, int slots)
    : targets_(targets), queries_(targets.size() * size_t(slots)), slots_(slots) {
  // Queries without a target (gl_kind::Query: Mesa 22.3's glCreateQueries refuses the
  // pipeline-statistics targets); each takes its target at its first glBeginQuery.
  check_gl_errors("creating GL queries");
}

bool QueryRing::begin() {
  if (active_) throw Error("a GL query ring was begun twice without an end");
  if (issued_ - taken_ == slots_) collect();
  if (issued_ - taken_ == slots_) return false;
  const size_t slot = size_t(issued_ % slots_);
  for (size_t t = 0; t < targets_.size(); ++t) glBeginQuery(targets_[t], queries_[slot * targets_.size() + t]);
  active_ = true;
  return true;
}

void QueryRing::end() {
  if (!active_) return;
  for (const unsigned target : targets_) glEndQuery(target);
  active_ = false;
  ++issued_;
}

const std::optional<std::vector<unsigned long long>>& QueryRing::latest() {
  collect();
  return latest_;
}

void QueryRing::collect() {
  while (taken_ < issued_) {
    const GlQuery* slot = &queries_[size_t(taken_ % slots_) * targets_.size()];
    for (size_t t = 0; t < targets_.size(); ++t) {
      GLuint available = GL_FALSE;
      glGetQueryObjectuiv(slot[t], GL_QUERY_RESULT_AVAILABLE, &available);
      if (!available) return;
    }
    std::vector<unsigned long long> values(targets_.size());
    for (size_t t = 0; t < targets_.size(); ++t) {
      GLuint64 value = 0;
      glGetQueryObjectui64v(slot[t], GL_QUERY_RESULT, &value);
      values[t] = value;
    }
    latest_ = std::move(values);
    ++taken_;
  }
}

}  // namespace gps
