// Reference curves against the tables of docs/references.md (§1, §2, §5, §6).
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

// Exact-circle Wagner and modified Logvinovich (MLM) against values computed independently
// with mpmath (30 digits): k from s/R = 1 − (2/π)E(k) by root finding, Wagner Cs =
// π²k²/(2(K − E)), and MLM by numerical quadrature of the derived pressure
// p/(ρV²) = cċ/(V sqrt(c² − x²)) − 1/2 − x²(1 − x²)/(2(c² − x²)) (R = 1) up to its zero,
// with ċ from a finite difference of k(s) — not the closed form used in the code.
TEST(IoReferenceCurves, ExactCircleWagnerAndLogvinovichMatchIndependentValues) {
  struct Row {
    double s_over_r, k, wagner, mlm;
  };
  const Row rows[] = {
      {0.0001, 0.01999925, 6.28224281, 6.14245831}, {0.001, 0.06322183, 6.27375817, 5.90549079},
      {0.01, 0.19924732, 6.18869791, 5.27547685},   {0.02, 0.28070607, 6.09371463, 4.92628482},
      {0.05, 0.43867217, 5.80551379, 4.26348386},   {0.1, 0.60780439, 5.31229147, 3.53277245},
      {0.2, 0.82130156, 4.25223819, 2.44797173},    {0.3, 0.95200851, 2.96331010, 1.39174096}};
  for (const Row& r : rows) {
    const double sd = 0.5 * r.s_over_r;
    EXPECT_NEAR(wagner_circle_half_width(r.s_over_r), r.k, 1e-7) << "s/R " << r.s_over_r;
    EXPECT_NEAR(slamming_coefficient(SlammingTheory::WagnerCircle, sd), r.wagner, 1e-6)
        << "s/R " << r.s_over_r;
    EXPECT_NEAR(slamming_coefficient(SlammingTheory::ModifiedLogvinovich, sd), r.mlm, 1e-6)
        << "s/R " << r.s_over_r;
  }
  // The validation README's §11 values (3 digits).
  EXPECT_NEAR(slamming_coefficient(SlammingTheory::WagnerCircle, 0.005), 6.19, 0.005);
  EXPECT_NEAR(slamming_coefficient(SlammingTheory::WagnerCircle, 0.1), 4.25, 0.005);
  EXPECT_NEAR(slamming_coefficient(SlammingTheory::ModifiedLogvinovich, 0.05), 3.53, 0.005);
}

TEST(IoReferenceCurves, ExactCircleTheoriesHaveTheRightLimits) {
  constexpr double pi = std::numbers::pi;
  // Small s: the circle is the parabola x²/(2R), c² = 4Rs (k = 2 sqrt(s/R)), Cs → 2π.
  for (double sr : {1e-8, 1e-6}) {
    EXPECT_NEAR(wagner_circle_half_width(sr), 2.0 * std::sqrt(sr), 1e-3 * std::sqrt(sr));
    EXPECT_NEAR(slamming_coefficient(SlammingTheory::WagnerCircle, 0.5 * sr), 2 * pi, 1e-5);
  }
  // MLM approaches Wagner only logarithmically (its negative −V²x²/(2(c² − x²)) term).
  EXPECT_NEAR(slamming_coefficient(SlammingTheory::ModifiedLogvinovich, 0.5e-8), 2 * pi, 0.01);
  EXPECT_DOUBLE_EQ(slamming_coefficient(SlammingTheory::ModifiedLogvinovich, 0.0), 2 * pi);
  // Full wetting at s/R = 1 − 2/π: k → 1, K → ∞, Cs → 0; NaN beyond.
  const double smax = wagner_circle_max_s_over_r();
  EXPECT_NEAR(smax, 0.36338, 1e-5);
  EXPECT_LT(slamming_coefficient(SlammingTheory::WagnerCircle, 0.5 * smax * (1 - 1e-9)),
            0.5);  // K ~ ln(4/k')
  EXPECT_TRUE(std::isnan(slamming_coefficient(SlammingTheory::WagnerCircle, 0.5 * smax + 1e-3)));
  EXPECT_TRUE(
      std::isnan(slamming_coefficient(SlammingTheory::ModifiedLogvinovich, 0.5 * smax + 1e-3)));
  // Ordering where all are defined: MLM < Wagner (circle) < Wagner (parabola) = 2π, and both
  // decrease with s; the MLM pressure zero lies inside the wetted region.
  double prev_w = 2 * pi, prev_m = 2 * pi;
  for (double sd = 0.001; sd < 0.18; sd += 0.001) {
    const double w = slamming_coefficient(SlammingTheory::WagnerCircle, sd);
    const double m = slamming_coefficient(SlammingTheory::ModifiedLogvinovich, sd);
    EXPECT_LT(m, w) << sd;
    EXPECT_LT(w, prev_w) << sd;
    EXPECT_LT(m, prev_m) << sd;
    const double xi = logvinovich_circle_pressure_zero(2 * sd);
    EXPECT_GT(xi, 0.0);
    EXPECT_LT(xi, 1.0);
    prev_w = w;
    prev_m = m;
  }
  // von Kármán with the exact circle: added mass ρπc²/2, c² = 2Rs − s² → Cs = π(1 − s/R).
  EXPECT_NEAR(slamming_coefficient(SlammingTheory::VonKarman, 0.1), pi * 0.8, 1e-12);
  // Which are 2D: all but Campbell–Weynberg (finite cylinders in experiments).
  for (SlammingTheory th : all_slamming_theories())
    EXPECT_EQ(slamming_theory_is_2d(th), th != SlammingTheory::CampbellWeynberg);
  EXPECT_EQ(all_slamming_theories().size(), 5u);
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
