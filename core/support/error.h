#pragma once
// The one error type of gpsurf: a one-line message meant for the user.
#include <stdexcept>
#include <string>

namespace gps {

/// What went wrong, in one line a user can act on (names the file, line or vertex).
/// `usage` marks errors in how the program was called (exit code 2) as opposed to
/// failures while doing the work (exit code 1).
class Error : public std::runtime_error {
public:
  enum class Kind { runtime, usage };
  explicit Error(const std::string& message, Kind kind = Kind::runtime) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const { return kind_; }
  int exit_code() const { return kind_ == Kind::usage ? 2 : 1; }

private:
  Kind kind_;
};

/// Shorthand for a usage error (exit code 2).
inline Error usage_error(const std::string& message) { return Error(message, Error::Kind::usage); }

}  // namespace gps
