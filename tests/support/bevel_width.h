#pragma once
// The bevel options the tests use most: a width and a number of segments, the rest as Blender's
// defaults (core/modelling/bevel.h).
#include "core/modelling/bevel.h"

namespace gps::test {

inline BevelOptions width(double w, int segments = 1) {
  BevelOptions o;
  o.width = w;
  o.segments = segments;
  return o;
}

}  // namespace gps::test
