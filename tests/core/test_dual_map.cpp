#include "core/mesh/dual_map.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "tests/support/random_spd.h"

namespace gps {
namespace {

using test::random_spd;

Vec3 random_vec(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  return Vec3(u(rng), u(rng), u(rng));
}

TEST(DualMap, RoundTripIsExact) {
  std::mt19937 rng(7);
  for (int k = 0; k < 200; ++k) {
    const Vec3 mu = random_vec(rng);
    const Mat3 sigma = random_spd(rng);
    const auto back = from_dual(to_dual(mu, sigma));
    ASSERT_TRUE(back.has_value());
    EXPECT_LT((back->mean - mu).norm(), 1e-10 * (1 + mu.norm()));
    EXPECT_LT((back->covariance - sigma).norm(), 1e-10 * sigma.norm());
  }
}

TEST(DualMap, LayoutIsVechOfPrecisionThenPrecisionTimesMean) {
  const Mat3 sigma = Vec3(2.0, 4.0, 8.0).asDiagonal();
  const Vec3 mu(1.0, 2.0, 3.0);
  const Dual q = to_dual(mu, sigma);
  Dual expected;
  expected << 0.5, 0, 0, 0.25, 0, 0.125, 0.5, 0.5, 0.375;
  EXPECT_LT((q - expected).norm(), 1e-15);
}

TEST(DualMap, NotPositiveDefiniteHasNoInverse) {
  Dual q = Dual::Zero();
  q[0] = 1.0;
  q[3] = -1.0;
  q[5] = 1.0;
  EXPECT_FALSE(is_positive_definite(q));
  EXPECT_FALSE(from_dual(q).has_value());
  EXPECT_FALSE(mean_from_dual(q).has_value());
}

// μ(t) = F⁻¹(q0 + t·dq): the tangent of Eq. 3.12 must match central differences.
TEST(DualMap, TangentMatchesFiniteDifferences) {
  std::mt19937 rng(11);
  for (int k = 0; k < 100; ++k) {
    const Dual q = to_dual(random_vec(rng), random_spd(rng));
    Dual dq = to_dual(random_vec(rng), random_spd(rng)) - q;
    dq *= 0.3;
    const Vec3 mu = *mean_from_dual(q);
    const Vec3 analytic = mean_derivative(q, dq, mu);
    const double h = 1e-6;
    const Vec3 numeric = (*mean_from_dual(q + h * dq) - *mean_from_dual(q - h * dq)) / (2 * h);
    EXPECT_LT((analytic - numeric).norm(), 1e-6 * (1 + analytic.norm()));
  }
}

}  // namespace
}  // namespace gps
