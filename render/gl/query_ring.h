#pragma once
// A small ring of GL query slots read back without stalling: each slot holds one query per target
// (begun and ended together); results are taken only once GL_QUERY_RESULT_AVAILABLE says so.
#include <optional>
#include <vector>

#include "render/gl/gl_object.h"

namespace gps {

class QueryRing {
public:
  /// `slots` slots of one query object per target; needs a current GL context.
  QueryRing(const std::vector<unsigned>& targets, int slots);
  QueryRing(const QueryRing&) = delete;
  QueryRing& operator=(const QueryRing&) = delete;

  /// Begins the next slot's queries; false (and nothing begun) while every slot awaits its result.
  bool begin();
  /// Ends the queries begun by the last successful begin(); nothing after a failed one.
  void end();
  /// The results of the newest finished slot (one per target, in the targets' order), after taking
  /// every slot whose results are available; nullopt before any finished.
  const std::optional<std::vector<unsigned long long>>& latest();

private:
  void collect();

  std::vector<unsigned> targets_;
  std::vector<GlQuery> queries_;  // slot-major: queries_[slot * targets + t]
  int slots_;
  long long issued_ = 0, taken_ = 0;  // slots ended and slots read, counted from the start
  bool active_ = false;
  std::optional<std::vector<unsigned long long>> latest_;
};

}  // namespace gps
