#pragma once
// A PLY property's scalar type (char, uchar, short, ushort, int, uint, float, double and their
// sized names) and what a value of it can be.
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace gps {

struct PlyScalarType {
  int size = 0;  // bytes
  bool is_float = false;
  bool is_signed = false;

  /// Whether `value` is one the type holds: any number for a float, else a whole number in its range.
  bool holds(double value) const {
    if (is_float) return true;
    const double bits = 8.0 * size, low = is_signed ? -std::exp2(bits - 1) : 0.0;
    const double high = std::exp2(is_signed ? bits - 1 : bits) - 1;
    return value == std::floor(value) && value >= low && value <= high;
  }
  /// "a non-negative integer of 8 bits", "an integer of 32 bits", "a number".
  std::string what_it_holds() const {
    if (is_float) return "a number";
    return std::string(is_signed ? "an integer" : "a non-negative integer") + " of " + std::to_string(8 * size) +
           " bits";
  }
};

/// The type a PLY header names, or none.
inline std::optional<PlyScalarType> ply_scalar_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyScalarType{1, false, true};
  if (name == "uchar" || name == "uint8") return PlyScalarType{1, false, false};
  if (name == "short" || name == "int16") return PlyScalarType{2, false, true};
  if (name == "ushort" || name == "uint16") return PlyScalarType{2, false, false};
  if (name == "int" || name == "int32") return PlyScalarType{4, false, true};
  if (name == "uint" || name == "uint32") return PlyScalarType{4, false, false};
  if (name == "float" || name == "float32") return PlyScalarType{4, true, true};
  if (name == "double" || name == "float64") return PlyScalarType{8, true, true};
  return std::nullopt;
}

}  // namespace gps
