// Johnson–Cook solid (solid/materials/johnson_cook.h), Mie–Grüneisen pressure and
// Johnson–Cook failure at one material point, against closed forms written out here
// (docs/model.md §3 "Johnson–Cook"; docs/references.md §8 for the Al 2024-T3 numbers).
//
// Closed forms (τ the Kirchhoff stress, q its von Mises measure, ε̄p the equivalent plastic
// strain; the law compares q with the flow stress):
//  - Flow stress σ_y = (A + B ε̄p^n)(1 + C ln max(ε̇p/ε̇0, 1))(1 − T*^m), T* ∈ [0, 1].
//  - Uniaxial stress along x (F = diag(λ, λ_t, λ_t), τ_yy = τ_zz = 0; F_zz ≠ 1 is driven
//    through update_kirchhoff): q = |τ_xx|, mean τ = τ_xx/3, and the Hencky/EOS split gives
//    the elastic axial log strain ε_e,xx = τ_xx/(3μ) + ln J / 3, so
//        ln λ − ε_p,xx = τ_xx/(3μ) + ln J / 3,      ε_p,xx = Σ sign(τ_xx) Δε̄p
//    (isochoric flow along the fixed axes). Without heating (χ = 0) at fixed T, the stress
//    on the plastic branch is σ_y(ε̄p, ε̇p, T) with ε̇p = Δε̄p/Δt.
//  - Uniaxial strain (plane strain, F = diag(exp(e), 1)), monotone tension: dev ε_tr =
//    e (2/3, −1/3, −1/3) − ε̄p (1, −1/2, −1/2), so q = 2μ e − 3μ ε̄p and τ_xx − τ_yy = q,
//    mean τ = −J p_MG(J, c_v (T − T0)) with J = exp(e). With adiabatic heating, C = 0 and
//    m = 1, dT = χ σ_y dε̄p/(ρ0 c_v) integrates to
//        1 − T* = (1 − T0*) exp(−χ (A ε̄p + B ε̄p^(n+1)/(n+1)) / (ρ0 c_v (T_m − T_r))).
//  - Isochoric plane-strain stretch F = diag(λ, 1/λ): J = 1, the external work Σ P : ΔF
//    minus the stored energy is the plastic work W_p, and ρ0 c_v (T − T0) = χ W_p.
//  - Frame indifference: F → Q(θ) F with θ growing to 90° along the path gives P → Q P and
//    the same history (all of it lives in the reference frame); and along that stretch-and-
//    shear path the committed history reproduces the returned stress at the same F.
//  - Failure (Johnson & Cook 1985): ε_f = [D1 + D2 exp(D3 σ*)][1 + D4 ln ε̇*][1 + D5 T*];
//    in uniaxial stress σ* = 1/3, so at the reference rate a particle fails at ε̄p = 0.209.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "solid/materials/johnson_cook.h"
#include "solid/materials/johnson_cook_failure.h"
#include "solid/materials/material_law_choice.h"
#include "solid/materials/material_presets.h"
#include "solid/materials/mie_gruneisen.h"

using namespace slamsph;

namespace {

const JohnsonCookPreset& kAl = kAl2024T3;
const double kMu = kAl.youngs_modulus / (2 * (1 + kAl.poisson_ratio));
using History = std::array<double, JohnsonCook::kSlots>;
using JC = JohnsonCook;

JohnsonCook law(const JohnsonCookModel& m) {
  return std::get<JohnsonCook>(
      make_material_law(m, kAl.youngs_modulus, kAl.poisson_ratio, kAl.density));
}

double flow_stress(const JohnsonCookModel& m, double ep, double rate, double T) {
  const double rs = std::max(rate / m.reference_strain_rate, 1.0);
  const double ts = std::clamp(
      (T - m.reference_temperature) / (m.melting_temperature - m.reference_temperature), 0.0, 1.0);
  return (m.a + m.b * std::pow(ep, m.n)) * (1 + m.c * std::log(rs)) * (1 - std::pow(ts, m.m));
}

MieGruneisenParameters eos_of(const JohnsonCookModel& m) {
  return {kAl.density, m.eos_sound_speed, m.gruneisen_gamma, m.hugoniot_slope};
}

Mat2 rotation(double t) {
  return {std::cos(t), -std::sin(t), std::sin(t), std::cos(t)};
}

// One committed step of uniaxial stress along x at axial stretch `lx`: the lateral stretch
// λ_t (F_yy = F_zz) is found by Newton on τ_yy = 0 with trial copies of the history.
KirchhoffStress uniaxial_stress_step(const JohnsonCook& l, History& h, double lx, double dt,
                                     double& lt) {
  auto tyy = [&](double t) {
    History c = h;
    return l.update_kirchhoff(Mat2{lx, 0, 0, t}, t, dt, c).in_plane.yy;
  };
  for (int it = 0; it < 60; ++it) {
    const double r = tyy(lt);
    if (std::abs(r) < 1e-4) break;
    const double dl = 1e-8;
    lt -= r * dl / (tyy(lt + dl) - r);
  }
  return l.update_kirchhoff(Mat2{lx, 0, 0, lt}, lt, dt, h);
}

}  // namespace

TEST(JohnsonCookPoint, MieGruneisenBranchesAndColdEnergy) {
  const MieGruneisenParameters p = eos_of(kAl.model);
  const double k = p.rho0 * p.c * p.c;
  // Compression η = 0.05 by hand: p_H = k η (1+η)/(1 − 0.34 η)², p = (1 − Γη/2) p_H.
  const double J = 1 / 1.05, eta = 0.05;
  const double pH = k * eta * (1 + eta) / std::pow(1 - 0.34 * eta, 2);
  EXPECT_NEAR(mie_gruneisen_pressure(p, J, 0.0), (1 - eta) * pH, 1e-9 * pH);
  // Tension is linear in η; the thermal term Γ ρ e adds in both branches.
  EXPECT_NEAR(mie_gruneisen_pressure(p, 1 / 0.98, 0.0), k * (0.98 - 1), 1e-6);
  EXPECT_NEAR(mie_gruneisen_pressure(p, 1 / 0.98, 1e4) - mie_gruneisen_pressure(p, 1 / 0.98, 0.0),
              2.0 * p.rho0 * 0.98 * 1e4, 1e-6);
  // −dW/dJ = p on both sides of J = 1 (central differences of the cold energy).
  for (double j : {0.9, 0.97, 0.999, 1.001, 1.02, 1.1}) {
    const double d = 1e-6;
    const double dw =
        (mie_gruneisen_cold_energy(p, j + d) - mie_gruneisen_cold_energy(p, j - d)) / (2 * d);
    EXPECT_NEAR(-dw, mie_gruneisen_pressure(p, j, 0.0), 1e-5 * k * std::abs(j - 1)) << j;
  }
  EXPECT_EQ(mie_gruneisen_cold_energy(p, 1.05, true), 0.0);
}

TEST(JohnsonCookPoint, FailureStrainOfAl2024MatchesTheReferenceSheet) {
  const FailureModel& f = kAl.model.failure;
  EXPECT_NEAR(johnson_cook_failure_strain(f, 0.0, 1.0, 0.0), 0.26, 1e-12);
  EXPECT_NEAR(johnson_cook_failure_strain(f, 1.0 / 3.0, 1.0, 0.0), 0.209, 5e-4);
  // Rate term: × (1 + 0.011 ln 1000) at 1000/s; none below the reference rate.
  EXPECT_NEAR(johnson_cook_failure_strain(f, 0.0, 1e3, 0.0), 0.26 * (1 + 0.011 * std::log(1e3)),
              1e-12);
  EXPECT_EQ(johnson_cook_failure_strain(f, 0.0, 1e-3, 0.0), 0.26);
}

TEST(JohnsonCookPoint, FlowStressOfAl2024MatchesTheReferenceSheet) {
  // docs/references.md §8: 265 MPa at 0, 460 at 0.1, 511 at 0.2 (rate 1/s); ×1.10 at 1000/s.
  const JohnsonCookModel& m = kAl.model;
  EXPECT_NEAR(flow_stress(m, 0.0, 1.0, 293), 265e6, 1);
  EXPECT_NEAR(flow_stress(m, 0.1, 1.0, 293), 460e6, 0.5e6);
  EXPECT_NEAR(flow_stress(m, 0.2, 1.0, 293), 511e6, 1e6);
  EXPECT_NEAR(flow_stress(m, 0.1, 1e3, 293) / flow_stress(m, 0.1, 1.0, 293), 1.10, 0.005);
}

// Uniaxial stress: load to ε = 0.22, unload through zero stress into reverse yield, at three
// rates and two temperatures, isothermal (χ = 0) so the closed-form curve applies.
TEST(JohnsonCookPoint, UniaxialStressFollowsTheClosedFormCurveLoadingAndUnloading) {
  for (double rate : {1.0, 1e3, 1e4}) {
    for (double T0 : {293.0, 534.0, 250.0}) {  // T* = 0, 0.5 and below T_r (clipped to 0)
      JohnsonCookModel m = kAl.model;
      m.heating_fraction = 0.0;
      m.initial_temperature = T0;
      m.failure = {};
      const JohnsonCook l = law(m);
      History h = l.initial_history();
      double lt = 1.0, ep_axial = 0.0, e = 0.0;
      double max_yield = 0.0, max_split = 0.0, max_det = 0.0, max_unload_flow = 0.0;
      double q_at_01 = 0.0, rate_at_01 = 0.0;
      bool plastic_seen = false, reverse_seen = false;
      // Path in log strain: 0 → 0.22 (440 steps) → 0.21 (100 steps) → 0.19 (100 steps).
      std::vector<double> path;
      for (int k = 1; k <= 440; ++k) path.push_back(0.22 * k / 440);
      for (int k = 1; k <= 200; ++k) path.push_back(0.22 - 0.03 * k / 200);
      for (double e_new : path) {
        const double dt = std::abs(e_new - e) / rate;
        const double ep_old = h[JC::kPlasticStrain];
        const KirchhoffStress t = uniaxial_stress_step(l, h, std::exp(e_new), dt, lt);
        e = e_new;
        const double d = h[JC::kPlasticStrain] - ep_old;
        ep_axial += std::copysign(d, t.in_plane.xx);
        const double q = std::abs(t.in_plane.xx);
        ASSERT_LT(std::abs(t.in_plane.yy) + std::abs(t.zz), 1e-3) << "not uniaxial";
        if (d > 0) {
          // On the yield surface of the committed state (rate = Δε̄p/Δt).
          const double y = flow_stress(m, h[JC::kPlasticStrain], d / dt, T0);
          max_yield = std::max(max_yield, std::abs(q - y) / y);
          EXPECT_NEAR(h[JC::kPlasticStrainRate], d / dt, 1e-9 * d / dt);
          plastic_seen = true;
          if (t.in_plane.xx < 0) reverse_seen = true;
        } else {
          // Elastic: inside the surface of the committed state at zero plastic rate.
          max_unload_flow = std::max(max_unload_flow, q / flow_stress(m, ep_old, 0.0, T0));
        }
        // Elastic–plastic split (isochoric flow, Hencky deviator, EOS mean stress).
        const double J = std::exp(e) * lt * lt;
        max_split = std::max(
            max_split, std::abs((e - ep_axial) - (t.in_plane.xx / (3 * kMu) + std::log(J) / 3)));
        const double detc =
            (h[JC::kCpInvXX] * h[JC::kCpInvYY] - h[JC::kCpInvXY] * h[JC::kCpInvXY]) *
            h[JC::kCpInvZZ];
        max_det = std::max(max_det, std::abs(detc - 1));
        if (q_at_01 == 0.0 && h[JC::kPlasticStrain] >= 0.1) {
          q_at_01 = q;
          rate_at_01 = d / dt;
        }
      }
      EXPECT_TRUE(plastic_seen && reverse_seen) << rate << " " << T0;
      EXPECT_LT(max_yield, 1e-9) << rate << " " << T0;
      EXPECT_LE(max_unload_flow, 1.0 + 1e-12) << rate << " " << T0;
      EXPECT_LT(max_split, 1e-9) << rate << " " << T0;
      EXPECT_LT(max_det, 1e-12) << rate << " " << T0;  // plastic incompressibility
      EXPECT_EQ(h[JC::kTemperature], T0);              // χ = 0: no heating
      // Against the nominal curve: the plastic rate is the applied rate to within the
      // elastic share of the strain rate (tangent/E < 1 %).
      EXPECT_NEAR(rate_at_01 / rate, 1.0, 0.02);
      const double nominal = flow_stress(m, 0.1, rate, T0);
      EXPECT_NEAR(q_at_01 / nominal, 1.0, 2e-3) << rate << " " << T0;
    }
  }
}

// Plane strain (uniaxial strain) with adiabatic heating against an independent scalar
// solution per step (bisection on the 1D consistency condition), and, with C = 0 and
// m = 1, against the closed-form adiabatic curve.
TEST(JohnsonCookPoint, UniaxialStrainWithAdiabaticHeating) {
  for (double rate : {1.0, 1e3, 1e4}) {
    JohnsonCookModel m = kAl.model;
    m.failure = {};
    const JohnsonCook l = law(m);
    const MieGruneisenParameters eos = eos_of(m);
    const double rc = kAl.density * m.specific_heat;
    History h = l.initial_history();
    double ep = 0.0, T = m.initial_temperature, e = 0.0;
    double max_err = 0.0;
    const int n = 300;
    for (int k = 1; k <= n; ++k) {
      const double e_new = 0.3 * k / n, dt = (e_new - e) / rate;
      e = e_new;
      const Mat2 F{std::exp(e), 0, 0, 1};
      const KirchhoffStress t = l.update_kirchhoff(F, 1.0, dt, h);
      // Independent 1D step: q_tr = 2μe − 3μ ε̄p,n.
      const double qtr = 2 * kMu * e - 3 * kMu * ep;
      auto res = [&](double d) {
        const double y = qtr - 3 * kMu * d;
        return y - flow_stress(m, ep + d, d / dt, T + m.heating_fraction * y * d / rc);
      };
      double d = 0.0;
      if (res(0.0) > 0) {
        double lo = 0, hi = qtr / (3 * kMu);
        for (int it = 0; it < 200; ++it) (res(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
        d = 0.5 * (lo + hi);
      }
      const double q = qtr - 3 * kMu * d;
      T += m.heating_fraction * q * d / rc;
      ep += d;
      const double J = std::exp(e);
      const double mean = -J * mie_gruneisen_pressure(eos, J, m.specific_heat * (T - 293.0));
      max_err = std::max({max_err, std::abs(t.in_plane.xx - t.in_plane.yy - q) / q,
                          std::abs((t.in_plane.xx + t.in_plane.yy + t.zz) / 3 - mean) / q,
                          std::abs(t.in_plane.yy - t.zz) / q});
      EXPECT_NEAR(h[JC::kPlasticStrain], ep, 1e-10) << k;
      EXPECT_NEAR(h[JC::kTemperature], T, 1e-8) << k;
    }
    EXPECT_LT(max_err, 1e-9) << rate;
    EXPECT_GT(T - 293.0, 20.0) << rate;  // it heated
  }
  // Closed-form adiabatic curve (C = 0, m = 1), 3000 steps to ε̄p ≈ 0.25.
  JohnsonCookModel m = kAl.model;
  m.c = 0.0;
  m.failure = {};
  const JohnsonCook l = law(m);
  History h = l.initial_history();
  for (int k = 1; k <= 3000; ++k)
    l.update_kirchhoff(Mat2{std::exp(0.25 * k / 3000), 0, 0, 1}, 1.0, 1e-6, h);
  const double ep = h[JC::kPlasticStrain];
  const double theta =
      std::exp(-m.heating_fraction * (m.a * ep + m.b * std::pow(ep, m.n + 1) / (m.n + 1)) /
               (kAl.density * m.specific_heat * (m.melting_temperature - m.reference_temperature)));
  const KirchhoffStress t = l.elastic_kirchhoff(Mat2{std::exp(0.25), 0, 0, 1}, 1.0, h);
  const double closed = (m.a + m.b * std::pow(ep, m.n)) * theta;
  EXPECT_NEAR((t.in_plane.xx - t.in_plane.yy) / closed, 1.0, 1e-3);
  EXPECT_NEAR(h[JC::kTemperature], 293.0 + (1 - theta) * (775.0 - 293.0), 0.05);
  EXPECT_LT(theta, 0.95);  // softening is not negligible here
}

// Isochoric stretch: heat = heating fraction × plastic work (work minus stored energy).
TEST(JohnsonCookPoint, HeatIsTheHeatingFractionOfThePlasticWork) {
  JohnsonCookModel m = kAl.model;
  m.failure = {};
  const JohnsonCook l = law(m);
  History h = l.initial_history();
  Mat2 F_old = Mat2::identity(), P_old{};
  double work = 0.0;
  const int n = 8000;
  // Out to a stretch of 1.3 and back to 1.2 (plastic loading, elastic unloading).
  for (int k = 1; k <= n; ++k) {
    const double s = k <= 6000 ? 0.3 * k / 6000 : 0.3 - 0.1 * (k - 6000) / 2000;
    const Mat2 F{1 + s, 0, 0, 1 / (1 + s)};
    const Mat2 P = l.update(F_old, F, 1e-5, h);
    const Mat2 dF = F - F_old, Pm = 0.5 * (P + P_old);
    work += Pm.xx * dF.xx + Pm.xy * dF.xy + Pm.yx * dF.yx + Pm.yy * dF.yy;
    F_old = F;
    P_old = P;
  }
  const double wp = work - l.energy_density(F_old, h);
  const double heat = kAl.density * m.specific_heat * (h[JC::kTemperature] - 293.0);
  EXPECT_GT(h[JC::kPlasticStrain], 0.2);
  EXPECT_NEAR(heat / (0.9 * wp), 1.0, 1e-4);
}

TEST(JohnsonCookPoint, FrameIndifferentUnderALargeRotation) {
  JohnsonCookModel m = kAl.model;
  const JohnsonCook l = law(m);
  History ha = l.initial_history(), hb = ha;
  Mat2 Fa_old = Mat2::identity(), Fb_old = Fa_old;
  double max_p = 0.0, max_diff = 0.0, max_h = 0.0, max_commit = 0.0;
  const int n = 400;
  for (int k = 1; k <= n; ++k) {
    const double s = double(k) / n;
    // Stretch with shear (principal axes rotate), then partly back.
    const double g = 0.4 * std::sin(3.0 * s), e = 0.15 * std::sin(2.5 * s);
    const Mat2 Fa{std::exp(e), g, 0.0, 1.0};
    const Mat2 Q = rotation(0.5 * M_PI * s);
    const Mat2 Fb = Q * Fa;
    const KirchhoffStress ta = l.update_kirchhoff(Fa, 1.0, 1e-4, ha);
    const Mat2 Pa = ta.in_plane * transpose(inverse(Fa));
    const Mat2 Pb = l.update(Fb_old, Fb, 1e-4, hb);
    // The committed history reproduces the returned stress (every Cp⁻¹ component written).
    const KirchhoffStress te = l.elastic_kirchhoff(Fa, 1.0, ha);
    max_commit = std::max({max_commit, std::abs(te.in_plane.xx - ta.in_plane.xx),
                           std::abs(te.in_plane.xy - ta.in_plane.xy),
                           std::abs(te.in_plane.yy - ta.in_plane.yy), std::abs(te.zz - ta.zz)});
    Fa_old = Fa;
    Fb_old = Fb;
    const Mat2 d = Pb - Q * Pa;
    max_p = std::max({max_p, std::abs(Pa.xx), std::abs(Pa.xy), std::abs(Pa.yx), std::abs(Pa.yy)});
    max_diff = std::max({max_diff, std::abs(d.xx), std::abs(d.xy), std::abs(d.yx), std::abs(d.yy)});
    for (std::size_t j = 0; j < ha.size(); ++j)
      max_h = std::max(max_h, std::abs(ha[j] - hb[j]) / std::max(1.0, std::abs(ha[j])));
  }
  EXPECT_GT(ha[JC::kPlasticStrain], 0.05);
  EXPECT_LT(max_diff, 1e-9 * max_p);
  EXPECT_LT(max_h, 1e-9);
  EXPECT_LT(max_commit, 1e-9 * max_p);
  EXPECT_NEAR(l.cauchy_zz(Fb_old, hb), l.cauchy_zz(Fa_old, ha), 1e-9 * max_p);
}

TEST(JohnsonCookPoint, JohnsonCookFailureInUniaxialStressAtTheTriaxialityOfAThird) {
  JohnsonCookModel m = kAl.model;  // failure D1..D5 of Al 2024-T3
  m.heating_fraction = 0.0;
  const JohnsonCook l = law(m);
  History h = l.initial_history();
  double lt = 1.0, e = 0.0, ep_fail = -1.0;
  for (int k = 1; k <= 1000 && ep_fail < 0; ++k) {
    const double e_new = 0.3 * k / 1000;
    uniaxial_stress_step(l, h, std::exp(e_new), (e_new - e) / 1.0, lt);
    e = e_new;
    if (h[JC::kFailed] > 0.5) ep_fail = h[JC::kPlasticStrain];
  }
  const double ef = johnson_cook_failure_strain(m.failure, 1.0 / 3.0, 1.0, 0.0);
  EXPECT_NEAR(ep_fail, ef, 4e-4);  // one step of ε̄p
  EXPECT_NEAR(h[JC::kTriaxiality], 1.0 / 3.0,
              1e-4);  // the last step fails (lateral stretch of the failed state)
  EXPECT_EQ(h[JC::kDamage], 1.0);
  // Failed: no deviatoric stress, no tension; compression still carries pressure.
  const KirchhoffStress t = l.update_kirchhoff(Mat2{std::exp(e + 0.01), 0, 0, lt}, lt, 1e-2, h);
  EXPECT_EQ(t.in_plane.xx, 0.0);
  EXPECT_EQ(t.in_plane.yy, 0.0);
  EXPECT_EQ(t.zz, 0.0);
  const Mat2 Fc{0.99, 0.02, 0.0, 0.99};
  const KirchhoffStress c = l.update_kirchhoff(Fc, 1.0, 1e-2, h);
  const double J = det(Fc);
  const double p = mie_gruneisen_pressure(eos_of(m), J, 0.0);
  EXPECT_GT(p, 0.0);
  EXPECT_NEAR(c.in_plane.xx, -J * p, 1e-6 * p);
  EXPECT_NEAR(c.in_plane.yy, -J * p, 1e-6 * p);
  EXPECT_NEAR(c.in_plane.xy, 0.0, 1e-6 * p);
  EXPECT_NEAR(c.zz, -J * p, 1e-6 * p);
}

TEST(JohnsonCookPoint, CriticalPlasticStrainFailure) {
  JohnsonCookModel m = kAl.model;
  m.failure = FailureModel{FailureKind::CriticalPlasticStrain, 0, 0, 0, 0, 0, 0.05};
  const JohnsonCook l = law(m);
  History h = l.initial_history();
  double ep_before = 0.0;
  for (int k = 1; k <= 400 && h[JC::kFailed] < 0.5; ++k) {
    ep_before = h[JC::kPlasticStrain];
    l.update_kirchhoff(Mat2{std::exp(0.2 * k / 400), 0, 0, 1}, 1.0, 1e-6, h);
  }
  EXPECT_LT(ep_before, 0.05);
  EXPECT_GE(h[JC::kPlasticStrain], 0.05);
  EXPECT_EQ(h[JC::kFailed], 1.0);
  // Without a failure model nothing fails.
  m.failure = {};
  const JohnsonCook n = law(m);
  History g = n.initial_history();
  for (int k = 1; k <= 400; ++k)
    n.update_kirchhoff(Mat2{std::exp(0.5 * k / 400), 0, 0, 1}, 1.0, 1e-6, g);
  EXPECT_EQ(g[JC::kFailed], 0.0);
  EXPECT_EQ(g[JC::kDamage], 0.0);
}

TEST(JohnsonCookPoint, VirginStateAndInitialTemperature) {
  JohnsonCookModel m = kAl.model;
  m.initial_temperature = 400.0;
  const JohnsonCook l = law(m);
  History h = l.initial_history();
  EXPECT_EQ(h[JC::kTemperature], 400.0);
  const Mat2 P = l.update(Mat2::identity(), Mat2::identity(), 0.0, h);
  EXPECT_EQ(P.xx, 0.0);
  EXPECT_EQ(P.yy, 0.0);
  EXPECT_EQ(l.energy_density(Mat2::identity(), h), 0.0);
  const std::vector<double> init = initial_history(MaterialLaw(l));
  EXPECT_EQ(init[JC::kTemperature], 400.0);
  EXPECT_EQ(init[JC::kCpInvXX], 1.0);
  EXPECT_THROW(make_material_law(m, 1e9, 0.3, 0.0), std::invalid_argument);
}
