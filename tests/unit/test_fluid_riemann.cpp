// Linearised Riemann solver with the low-dissipation limiter (spec §2) and the Tait EOS.
#include <gtest/gtest.h>

#include "fluid/riemann_solver.h"
#include "fluid/tait_eos.h"

using namespace slamsph;

constexpr double kC0 = 40.0, kOmega = 3.0;

TEST(Riemann, EqualStatesReturnTheState) {
  const RiemannState s{1003.0, 0.7, 2.5e4};
  const RiemannStar r = solve_riemann(s, s, kC0, kOmega);
  EXPECT_DOUBLE_EQ(r.u, 0.7);
  EXPECT_DOUBLE_EQ(r.p, 2.5e4);
}

TEST(Riemann, ApproachingPairsRaisePressure) {
  const RiemannState L{1000.0, 1.0, 1e4}, R{1000.0, -1.0, 1e4};
  const RiemannStar r = solve_riemann(L, R, kC0, kOmega);
  // beta = min(3 * 2, 40) = 6: p* = p + beta rho (UL - UR)/2 = 1e4 + 6 * 1000 * 2 / 2.
  EXPECT_DOUBLE_EQ(r.p, 1e4 + 6000.0);
  EXPECT_DOUBLE_EQ(r.u, 0.0);
}

TEST(Riemann, DissipationIsCappedAtSoundSpeed) {
  const RiemannState L{1000.0, 20.0, 0.0}, R{1000.0, -20.0, 0.0};
  const RiemannStar r = solve_riemann(L, R, kC0, kOmega);
  EXPECT_DOUBLE_EQ(r.p, kC0 * 1000.0 * 40.0 / 2.0);  // beta = c0, acoustic impedance
}

TEST(Riemann, SeparatingPairsGetNoDissipation) {
  const RiemannState L{1000.0, -1.0, 3e3}, R{1010.0, 1.0, 5e3};
  const RiemannStar r = solve_riemann(L, R, kC0, kOmega);
  EXPECT_DOUBLE_EQ(r.p, (1010.0 * 3e3 + 1000.0 * 5e3) / 2010.0);
}

TEST(Riemann, GalileanInvariant) {
  const RiemannState L{1001.0, 0.3, 2e3}, R{998.0, -0.4, 1e3};
  const double shift = 5.0;
  const RiemannStar a = solve_riemann(L, R, kC0, kOmega);
  const RiemannStar b =
      solve_riemann({L.rho, L.u + shift, L.p}, {R.rho, R.u + shift, R.p}, kC0, kOmega);
  EXPECT_NEAR(b.u, a.u + shift, 1e-12);
  EXPECT_NEAR(b.p, a.p, 1e-9);
}

TEST(Riemann, SwappingSidesGivesSamePressureExactly) {
  // Pair antisymmetry: from j's side the axis is reversed and the states swap.
  const RiemannState L{1001.0, 0.3, 2e3}, R{998.0, -0.4, 1e3};
  const RiemannStar a = solve_riemann(L, R, kC0, kOmega);
  const RiemannStar b = solve_riemann({R.rho, -R.u, R.p}, {L.rho, -L.u, L.p}, kC0, kOmega);
  EXPECT_EQ(a.p, b.p);
  EXPECT_NEAR(a.u, -b.u, 1e-15);
}

TEST(TaitEos, RoundTripAndRestState) {
  const TaitEos eos{1000.0, 25.0, 7.0};
  EXPECT_DOUBLE_EQ(eos.pressure(1000.0), 0.0);
  for (double p : {-5e4, -1e3, 0.0, 1e3, 3.9e3, 1e5})
    EXPECT_NEAR(eos.pressure(eos.density(p)), p, 1e-7);
  // Linearisation: dp/drho = c0^2 at rest.
  const double e = 1e-4;
  EXPECT_NEAR((eos.pressure(1000.0 + e) - eos.pressure(1000.0 - e)) / (2 * e), 625.0, 1e-5);
}
