#pragma once
// One random symmetric positive definite 3×3 matrix for the tests: a·aᵀ + floor·I, a uniform in [−1, 1].
#include <random>

#include "core/mesh/linalg.h"

namespace gps::test {

inline Mat3 random_spd(std::mt19937& rng, double floor = 0.1) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mat3 a;
  for (int i = 0; i < 9; ++i) a.data()[i] = u(rng);
  const Mat3 c = a * a.transpose() + floor * Mat3::Identity();
  return 0.5 * (c + c.transpose());
}

}  // namespace gps::test
