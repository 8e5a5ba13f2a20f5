// Kernels (spec §1): unit integral in 2D, compact support 2h, antisymmetric gradient,
// derivative consistent with the value.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/kernel.h"
#include "core/vec.h"

using namespace slamsph;

class KernelTest : public ::testing::TestWithParam<KernelType> {};

TEST_P(KernelTest, IntegratesToOneOverItsSupport) {
  const double h = 0.013;
  const Kernel k(GetParam(), h);
  // Radial quadrature: integral of W 2 pi r dr over [0, 2h], midpoint rule.
  const int n = 20000;
  const double dr = k.support() / n;
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * dr;
    s += k.w(r) * 2.0 * std::numbers::pi * r * dr;
  }
  EXPECT_NEAR(s, 1.0, 1e-7);
  EXPECT_NEAR(k.w(2.0 * h), 0.0, 1e-30);
  EXPECT_EQ(k.w(2.0 * h * 1.0001), 0.0);
  EXPECT_EQ(k.dw(2.0 * h * 1.0001), 0.0);
}

TEST_P(KernelTest, LatticeSumIsNearOne) {
  // Sum of W dx^2 over a Cartesian lattice with h = 1.3 dx (partition of unity, approx.).
  const double dx = 0.01;
  const Kernel k(GetParam(), 1.3 * dx);
  double s = 0.0;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j) s += k.w(dx * std::hypot(i, j)) * dx * dx;
  EXPECT_NEAR(s, 1.0, 0.02);
}

TEST_P(KernelTest, DerivativeMatchesFiniteDifference) {
  const Kernel k(GetParam(), 1.0);
  for (double r : {0.1, 0.5, 0.99, 1.01, 1.5, 1.9}) {
    const double e = 1e-6;
    const double fd = (k.w(r + e) - k.w(r - e)) / (2 * e);
    EXPECT_NEAR(k.dw(r), fd, 1e-6) << "r = " << r;
    EXPECT_NEAR(k.dw_over_r(r) * r, k.dw(r), 1e-12) << "r = " << r;
  }
}

TEST_P(KernelTest, GradientIsAntisymmetric) {
  const Kernel k(GetParam(), 0.02);
  const Vec2 xi{0.1, 0.2}, xj{0.117, 0.191};
  const Vec2 rij = xi - xj, rji = xj - xi;
  const Vec2 gi = k.dw_over_r(norm(rij)) * rij;  // grad_i W_ij
  const Vec2 gj = k.dw_over_r(norm(rji)) * rji;  // grad_j W_ji
  EXPECT_EQ(gi.x, -gj.x);
  EXPECT_EQ(gi.y, -gj.y);
  // W decreases with distance, so grad_i W_ij points from i towards j.
  EXPECT_GT(dot(gi, xj - xi), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Kernels, KernelTest,
                         ::testing::Values(KernelType::WendlandC2, KernelType::CubicSpline));
