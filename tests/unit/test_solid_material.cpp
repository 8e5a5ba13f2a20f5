// St Venant–Kirchhoff at one material point (spec §3) against a hand calculation (numbers
// from an independent evaluation of the formulas), frame indifference and P = ∂Ψ/∂F.
#include <gtest/gtest.h>

#include <cmath>

#include "solid/materials/st_venant_kirchhoff.h"

using namespace slamsph;

namespace {
const SvkParameters kRubber = svk_from_young(2.0e6, 0.3975);
const Mat2 kF{1.1, 0.2, 0.05, 0.95};
}  // namespace

TEST(SolidSvk, LameParameters) {
  EXPECT_NEAR(kRubber.lambda, 2774990.18281775, 1e-6);
  EXPECT_NEAR(kRubber.mu, 715563.5062611807, 1e-6);
}

TEST(SolidSvk, StressesMatchHandCalculation) {
  const Mat2 E = green_lagrange(kF);
  EXPECT_NEAR(E.xx, 0.10625, 1e-14);
  EXPECT_NEAR(E.xy, 0.13375, 1e-14);
  EXPECT_NEAR(E.yx, 0.13375, 1e-14);
  EXPECT_NEAR(E.yy, -0.02875, 1e-14);
  const Mat2 S = svk_pk2(kRubber, E);
  EXPECT_NEAR(S.xx, 367118.9842488768, 1e-6);
  EXPECT_NEAR(S.xy, 191413.23792486585, 1e-6);
  EXPECT_NEAR(S.yy, 173916.83755835792, 1e-6);
  // P = F S (row-major): not symmetric.
  const Mat2 P = svk_pk1(kRubber, kF);
  EXPECT_NEAR(P.xx, 442113.53025873774, 1e-6);
  EXPECT_NEAR(P.xy, 245337.92922902404, 1e-6);
  EXPECT_NEAR(P.yx, 200198.52524106638, 1e-6);
  EXPECT_NEAR(P.yy, 174791.6575766833, 1e-6);
  EXPECT_NEAR(svk_strain_energy_density(kRubber, kF), 42604.662070771, 1e-7);
  const CauchyStress s = cauchy_from_pk1(P, kF, svk_cauchy_zz(kRubber, kF));
  EXPECT_NEAR(s.xx, 517287.40978784196, 1e-6);
  EXPECT_NEAR(s.yy, 170108.21348782847, 1e-6);
  EXPECT_NEAR(s.xy, 246547.5451985601, 1e-6);
  EXPECT_NEAR(s.zz, 207789.11996944525, 1e-6);
  EXPECT_NEAR(von_mises_stress(s), 539655.7183602932, 1e-6);
  EXPECT_NEAR(pressure(s), -298394.9144150386, 1e-6);
}

TEST(SolidSvk, RigidRotationGivesZeroStress) {
  for (double th : {0.3, 1.2, 2.9}) {
    const Mat2 Q{std::cos(th), -std::sin(th), std::sin(th), std::cos(th)};
    const Mat2 P = svk_pk1(kRubber, Q);
    EXPECT_NEAR(std::abs(P.xx) + std::abs(P.xy) + std::abs(P.yx) + std::abs(P.yy), 0.0, 1e-8);
    EXPECT_NEAR(svk_strain_energy_density(kRubber, Q), 0.0, 1e-9);
    // Frame indifference: Ψ(QF) = Ψ(F), P(QF) = Q P(F).
    EXPECT_NEAR(svk_strain_energy_density(kRubber, Q * kF), svk_strain_energy_density(kRubber, kF),
                1e-8);
    const Mat2 d = svk_pk1(kRubber, Q * kF) - Q * svk_pk1(kRubber, kF);
    EXPECT_NEAR(std::abs(d.xx) + std::abs(d.xy) + std::abs(d.yx) + std::abs(d.yy), 0.0, 1e-7);
  }
}

TEST(SolidSvk, Pk1IsEnergyDerivative) {
  const double h = 1e-6;
  const Mat2 P = svk_pk1(kRubber, kF);
  const double* p = &P.xx;
  for (int c = 0; c < 4; ++c) {
    Mat2 Fp = kF, Fm = kF;
    (&Fp.xx)[c] += h;
    (&Fm.xx)[c] -= h;
    const double d =
        (svk_strain_energy_density(kRubber, Fp) - svk_strain_energy_density(kRubber, Fm)) / (2 * h);
    EXPECT_NEAR(d, p[c], 1e-6 * std::abs(p[c]) + 1e-3) << "component " << c;
  }
}

TEST(SolidSvk, SmallStrainLimitIsLinearPlaneStrain) {
  // Uniaxial strain ε: σxx = (λ + 2μ) ε, σyy = σzz = λ ε = ν (σxx + σyy) to first order.
  const double eps = 1e-6;
  const Mat2 F{1.0 + eps, 0.0, 0.0, 1.0};
  const CauchyStress s = cauchy_from_pk1(svk_pk1(kRubber, F), F, svk_cauchy_zz(kRubber, F));
  EXPECT_NEAR(s.xx, (kRubber.lambda + 2 * kRubber.mu) * eps, 1e-5 * s.xx);
  EXPECT_NEAR(s.yy, kRubber.lambda * eps, 1e-5 * s.yy);
  EXPECT_NEAR(s.zz, 0.3975 * (s.xx + s.yy), 1e-5 * s.zz);
}

TEST(SolidSvk, EquivalentStrainOfPureShear) {
  // Pure shear E = [[0, γ/2], [γ/2, 0]]: von Mises equivalent γ/√3.
  const double g = 0.01;
  EXPECT_NEAR(equivalent_strain(Mat2{0, g / 2, g / 2, 0}), g / std::sqrt(3.0), 1e-15);
  // Uniaxial-strain E = diag(ε, 0) (E_zz = 0): sqrt(2/3 · 2/3) ε = 2ε/3.
  EXPECT_NEAR(equivalent_strain(Mat2{g, 0, 0, 0}), 2.0 * g / 3.0, 1e-15);
}
