// Cavitation limit of the contact star state (coupling/contact_pair.h, docs/model.md §4):
// p* = max(p*, p_min) and, where the limit acts, the interface velocity of a cavity at p_min
// in the continuity term.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/contact_pair.h"

namespace slamsph {
namespace {

constexpr double kH = 0.013;

ContactPairInput receding_pair(double p_fluid, double p_solid) {
  ContactPairInput in{};
  in.xi = {0.0, 0.0};
  in.xs = {0.0, -0.01};  // e = (0, -1) from fluid to solid
  in.vi = {0.0, 0.0};    // U_L = 0
  in.vs = {0.0, -1.0};   // U_R = +1: moving away from the fluid
  in.rhoi = in.rhos = 1000.0;
  in.pi = p_fluid;
  in.ps = p_solid;
  in.Vi = in.Vs = 1e-4;
  return in;
}

TEST(CouplingCavitation, SuctionAboveTheLimitActsUnchanged) {
  const Kernel k(KernelType::WendlandC2, kH);
  const ContactPairInput in = receding_pair(-500.0, -500.0);
  const ContactPairResult r = contact_pair<false>(in, k, 25.0, 3.0, 0.0, -101325.0);
  ASSERT_TRUE(r.active);
  // Separating pair: beta = 0, p* = -500; U* = (1000 * 1 + 0) / 2000 = 0.5.
  EXPECT_DOUBLE_EQ(r.p_star, -500.0);
  const double dwr = k.dw_over_r(0.01);
  EXPECT_NEAR(r.force.y, -2.0 * 1e-8 * -500.0 * dwr * 0.01, 1e-15);
  EXPECT_LT(r.force.y, 0.0);  // the solid below pulls the fluid down, towards itself
  EXPECT_NEAR(r.drho_term, 1e-4 * (0.0 - 0.5) * (-dwr * 0.01), 1e-15);
}

TEST(CouplingCavitation, BelowTheLimitTheWaterSeparates) {
  const Kernel k(KernelType::WendlandC2, kH);
  const double c0 = 25.0, dwr = k.dw_over_r(0.01);
  // p* unlimited = (100 - 3000)/2 = -1450 < p_min = -1000.
  const ContactPairInput in = receding_pair(100.0, -3000.0);
  const ContactPairResult r = contact_pair<false>(in, k, c0, 3.0, 0.0, -1000.0);
  EXPECT_DOUBLE_EQ(r.p_star, -1000.0);
  EXPECT_NEAR(r.force.y, -2.0 * 1e-8 * -1000.0 * dwr * 0.01, 1e-15);
  // Cavity interface: U* = U_L + (p_L - p_min)/(rho_L c0) = 1100 / 25000 = 0.044, not the
  // unlimited (1000 + 3100/25)/2000 = 0.562.
  EXPECT_NEAR(r.drho_term, 1e-4 * (0.0 - 0.044) * (-dwr * 0.01), 1e-15);
  // p_min = 0 is the old no-adhesion clamp: no force; a fluid at negative pressure sees a
  // cavity moving with itself (no continuity change).
  const ContactPairResult r0 = contact_pair<false>(receding_pair(-500.0, -500.0), k, c0, 3.0, 0.0);
  EXPECT_EQ(r0.force.y, 0.0);
  EXPECT_EQ(r0.p_star, 0.0);
  EXPECT_EQ(r0.drho_term, 0.0);
}

}  // namespace
}  // namespace slamsph
