// Reference curves against the tables of ../shared/validation/README.md (§1, §2, §5, §6).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "io/reference_curves.h"

namespace slamsph {
namespace {

// The paper's case: ρ 1000, V 2.33 m/s, R 0.1 m (ρV²R = 542.9 N/m).
constexpr double kRho = 1000.0, kV = 2.33, kR = 0.1;

TEST(IoReferenceCurves, SlammingForceMatchesReadmeTable) {
  const double sd[] = {0, 0.005, 0.0125, 0.025, 0.05, 0.1, 0.2, 0.3};
  const double cw[] = {2796, 2555, 2263, 1903, 1449, 994, 642, 507};
  const double vk[] = {1706, 1689, 1663, 1620, 1535, 1364, 1023, 682};
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(slamming_force(SlammingTheory::CampbellWeynberg, sd[i], kRho, kV, kR), cw[i], 1.0)
        << "s/D " << sd[i];
    EXPECT_NEAR(slamming_force(SlammingTheory::VonKarman, sd[i], kRho, kV, kR), vk[i], 1.0)
        << "s/D " << sd[i];
    EXPECT_NEAR(slamming_force(SlammingTheory::Wagner, sd[i], kRho, kV, kR), 3411.0, 1.0);
  }
  EXPECT_NEAR(kRho * kV * kV * kR, 542.9, 0.05);
  // Coefficients at s = 0 (README §1 table).
  EXPECT_DOUBLE_EQ(slamming_coefficient(SlammingTheory::CampbellWeynberg, 0.0), 5.15);
  EXPECT_DOUBLE_EQ(slamming_coefficient(SlammingTheory::VonKarman, 0.0), std::numbers::pi);
  EXPECT_DOUBLE_EQ(slamming_coefficient(SlammingTheory::Wagner, 0.0), 2 * std::numbers::pi);
  EXPECT_EQ(slamming_coefficient(SlammingTheory::VonKarman, 0.6), 0.0);  // clamped
}

TEST(IoReferenceCurves, DamBreakTables) {
  const FrontTable mm = martin_moyce_1952(), ko = koshizuka_oka_1996();
  ASSERT_EQ(mm.T.size(), 13u);
  ASSERT_EQ(mm.Z.size(), 13u);
  ASSERT_EQ(ko.T.size(), 9u);
  ASSERT_EQ(ko.Z.size(), 9u);
  EXPECT_DOUBLE_EQ(mm.T.front(), 0.41);
  EXPECT_DOUBLE_EQ(mm.Z.front(), 1.11);
  EXPECT_DOUBLE_EQ(mm.T.back(), 2.96);
  EXPECT_DOUBLE_EQ(mm.Z.back(), 3.67);
  EXPECT_DOUBLE_EQ(ko.T[4], 1.537);
  EXPECT_DOUBLE_EQ(ko.Z[4], 1.892);
  EXPECT_DOUBLE_EQ(ko.Z.back(), 3.624);
  for (std::size_t i = 1; i < mm.T.size(); ++i) EXPECT_GT(mm.T[i], mm.T[i - 1]);
  for (std::size_t i = 1; i < ko.T.size(); ++i) EXPECT_GT(ko.T[i], ko.T[i - 1]);
}

TEST(IoReferenceCurves, CantileverPlate) {
  // README §5: L 0.2, H 0.02, ρ 1000, E 2 MPa, ν 0.3975 → ω 24.73 rad/s, f 3.94 Hz.
  const double w = cantilever_omega(2e6, 1000, 0.3975, 0.02, 0.2);
  EXPECT_NEAR(w, 24.73, 0.01);
  EXPECT_NEAR(w / (2 * std::numbers::pi), 3.94, 0.005);
  EXPECT_NEAR(cantilever_tip_amplitude(0.001, 2e6, 1000, 0.3975, w), 2.3e-3, 0.05e-3);
  EXPECT_NEAR(cantilever_tip_amplitude(0.01, 2e6, 1000, 0.3975, w), 23e-3, 0.5e-3);
  EXPECT_NEAR(cantilever_tip_amplitude(0.05, 2e6, 1000, 0.3975, w), 115e-3, 1.5e-3);
}

TEST(IoReferenceCurves, GateExperiment) {
  const GateExperiment g = antoci_2007_gate();
  EXPECT_DOUBLE_EQ(g.peak_dx, 0.040);
  EXPECT_DOUBLE_EQ(g.t_peak_min, 0.15);
  EXPECT_DOUBLE_EQ(g.t_peak_max, 0.20);
  EXPECT_DOUBLE_EQ(g.peak_dy_min, 0.012);
  EXPECT_DOUBLE_EQ(g.peak_dy_max, 0.014);
}

}  // namespace
}  // namespace slamsph
