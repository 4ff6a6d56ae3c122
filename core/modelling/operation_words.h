#pragma once
// The words modelling operations use in their summaries and refusals: "edge 3–7", "2 faces", "0.25".
#include <cstddef>
#include <sstream>
#include <string>

namespace gps {

/// "edge a–b", the vertices as given.
inline std::string edge_name(int a, int b) { return "edge " + std::to_string(a) + "–" + std::to_string(b); }

/// "1 face", "3 faces": `n` with the singular or plural noun.
inline std::string count_of(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// A number as a stream writes it by default (six significant digits: "0.25", "1e-06").
inline std::string short_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace gps
