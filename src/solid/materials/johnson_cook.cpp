#include "solid/materials/johnson_cook.h"

#include <algorithm>
#include <cmath>

#include "solid/materials/johnson_cook_failure.h"
#include "solid/materials/plane_spectral.h"

namespace slamsph {
namespace {

using JC = JohnsonCook;

// Elastic state from b_e = F Cp⁻¹ Fᵀ (zz: F_zz² Cp⁻¹_zz): spectral form, principal
// logarithmic strains and the volume ratio J = det F · F_zz (= det Fe: the flow is isochoric).
struct ElasticState {
  Spectral sp;
  double eps[3];
  double J;
};

ElasticState elastic_state(const Mat2& F, double Fzz, std::span<const double> h) {
  const Mat2 C{h[JC::kCpInvXX], h[JC::kCpInvXY], h[JC::kCpInvXY], h[JC::kCpInvYY]};
  const Mat2 b = F * C * transpose(F);
  ElasticState st{spectral(b.xx, 0.5 * (b.xy + b.yx), b.yy), {}, det(F) * Fzz};
  st.eps[0] = 0.5 * std::log(st.sp.e1);
  st.eps[1] = 0.5 * std::log(st.sp.e2);
  // In plane strain with no plastic flow yet the zz stretch is exactly 1: skip the log.
  const double zz = Fzz * Fzz * h[JC::kCpInvZZ];
  st.eps[2] = zz == 1.0 ? 0.0 : 0.5 * std::log(zz);
  return st;
}

// Deviatoric Kirchhoff stress s_a = 2μ dev ε_a and its von Mises measure q = sqrt(3/2 s:s).
double deviator(double mu, const double eps[3], double s[3]) {
  const double mean = (eps[0] + eps[1] + eps[2]) / 3.0;
  for (int a = 0; a < 3; ++a) s[a] = 2.0 * mu * (eps[a] - mean);
  return std::sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
}

}  // namespace

JohnsonCook::JohnsonCook(JohnsonCookParameters p)
    : p_(p), eos_{p.rho0, p.jc.eos_sound_speed, p.jc.gruneisen_gamma, p.jc.hugoniot_slope} {}

double JohnsonCook::homologous_temperature(double T) const {
  const double t =
      (T - p_.jc.reference_temperature) / (p_.jc.melting_temperature - p_.jc.reference_temperature);
  return std::clamp(t, 0.0, 1.0);
}

std::array<double, JohnsonCook::kSlots> JohnsonCook::initial_history() const {
  std::array<double, kSlots> h{};
  for (std::size_t k = 0; k < kSlots; ++k) h[k] = kHistory[k].initial;
  h[kTemperature] = p_.jc.initial_temperature;
  return h;
}

namespace {

// Residual r(Δ) = q_tr − 3μΔ − σ_y(ε̄p + Δ, Δ/Δt, T(Δ)) of the consistency condition and
// dr/dΔ, with the adiabatic temperature T(Δ) = T_n + χ (q_tr − 3μΔ) Δ / (ρ0 c_v) (the
// returned stress q_tr − 3μΔ equals σ_y at the root).
struct Consistency {
  const JohnsonCookModel& jc;
  double mu, rho0, q, ep, T, dt;

  double operator()(double d, double& dr) const {
    const double e = ep + d;
    // ε̄p^(n-1) as ε̄p^n / ε̄p: one pow per Newton iteration instead of two (the slope only
    // steers the iteration; the root is converged to the same tolerance).
    const double pe = std::pow(e, jc.n);
    const double hard = jc.a + jc.b * pe;
    const double dhard =
        e > 0.0 ? jc.n * jc.b * (pe / e) : jc.n * jc.b * std::pow(e, jc.n - 1.0);  // +inf for n < 1
    const double x = dt > 0.0 ? d / (dt * jc.reference_strain_rate) : 0.0;
    const double rate = x > 1.0 ? 1.0 + jc.c * std::log(x) : 1.0;
    const double drate = x > 1.0 ? jc.c / d : 0.0;
    const double heat = jc.heating_fraction / (rho0 * jc.specific_heat);
    const double Td = T + heat * (q - 3.0 * mu * d) * d;
    const double dT = heat * (q - 6.0 * mu * d);
    const double span = jc.melting_temperature - jc.reference_temperature;
    const double t = (Td - jc.reference_temperature) / span;
    double theta = 1.0, dtheta = 0.0;
    if (t >= 1.0) {
      theta = 0.0;
    } else if (t > 0.0) {
      // m = 1 (the Al 2024-T3 preset): T*^1 = T* and T*^0 = 1 exactly, as pow returns them,
      // without its two calls (with those of the hardening, pow was 43 % of a notched
      // specimen's run yielding to failure: perf, docs/validation.md §6 "Cost model").
      theta = 1.0 - (jc.m == 1.0 ? t : std::pow(t, jc.m));
      dtheta = -jc.m * (jc.m == 1.0 ? 1.0 : std::pow(t, jc.m - 1.0)) * dT / span;
    }
    const double y = hard * rate * theta;
    dr = -3.0 * mu - (dhard * rate * theta + hard * drate * theta + hard * rate * dtheta);
    return q - 3.0 * mu * d - y;
  }
};

// True if the trial stress q is certainly inside the yield surface, decided without the
// powers of the flow stress: with B ≥ 0 and m ≥ 1 (T*^m ≤ T*), σ_y(ε̄p, ε̇* = 1, T) ≥
// A (1 − T*), and a margin of 1e-12 covers the rounding of both sides. Then r(0) ≤ 0 too,
// so the elastic check costs no pow for the (many) particles far from yielding and the
// result is the same bit for bit. T* as Consistency computes it at Δ = 0.
bool surely_elastic(const JohnsonCookModel& jc, double q, double T) {
  if (!(jc.b >= 0.0) || !(jc.a > 0.0)) return false;
  const double t =
      (T - jc.reference_temperature) / (jc.melting_temperature - jc.reference_temperature);
  double theta = 1.0;
  if (t > 0.0) {
    if (!(t < 1.0) || !(jc.m >= 1.0)) return false;
    theta = 1.0 - t;
  }
  return q < (1.0 - 1e-12) * jc.a * theta;
}

// The root Δ ∈ [0, q/(3μ)] (r(0) > 0 ≥ r(q/3μ) = −σ_y): Newton steps in ln Δ kept inside
// the bracket, bisection when a step leaves it or the slope is not finite (ε̄p = 0 with
// n < 1). In ln Δ the rate term C ln(Δ/(Δt ε̇0)) is linear: Newton in Δ itself, started at the
// rate-free return r(0)/3μ (right of the root, r convex), jumps to just above 0, where the
// rate term's slope C σ/Δ is huge, and climbs back a factor of a few per iteration (13.3
// iterations per yielding update in the notched specimen; 6.4 in ln Δ). r0 = r(0), which the
// caller has evaluated to decide that the step yields.
double solve_consistency(const Consistency& r, double r0) {
  double lo = 0.0, hi = r.q / (3.0 * r.mu);
  double dr = 0.0;
  double d = std::min(r0 / (3.0 * r.mu), hi);
  for (int it = 0; it < 200; ++it) {
    const double res = r(d, dr);
    if (res > 0.0)
      lo = d;
    else
      hi = d;
    if (std::abs(res) <= 1e-13 * r.q || hi - lo <= 1e-16 * hi) break;
    // u = ln Δ: u' = u − r / (dr/du), dr/du = Δ dr/dΔ.
    double next = d * std::exp(-res / (dr * d));
    if (!std::isfinite(next) || next <= lo || next >= hi) next = 0.5 * (lo + hi);
    d = next;
  }
  return d;
}

}  // namespace

KirchhoffStress JohnsonCook::update_kirchhoff(const Mat2& F, double Fzz, double dt,
                                              std::span<double> h) const {
  const JohnsonCookModel& jc = p_.jc;
  ElasticState st = elastic_state(F, Fzz, h);
  double s[3];
  const double q = deviator(p_.mu, st.eps, s);
  const bool failed = h[kFailed] > 0.5;
  if (!failed) {
    const double ep = h[kPlasticStrain];
    const double T = h[kTemperature];
    const Consistency r{jc, p_.mu, p_.rho0, q, ep, T, dt};
    double dr = 0.0;
    double d = 0.0;
    if (!surely_elastic(jc, q, T)) {
      const double r0 = r(0.0, dr);
      if (r0 > 0.0) d = solve_consistency(r, r0);
    }
    double q_new = q;
    if (d > 0.0) {
      // Radial return (Simo & Hughes 1998, Box 9.1) with the Δε̄p of the JC consistency.
      q_new = q - 3.0 * p_.mu * d;
      const double flow = 1.5 * d / q;
      for (int a = 0; a < 3; ++a) {
        st.eps[a] -= flow * s[a];
        s[a] *= q_new / q;
      }
      h[kPlasticStrain] = ep + d;
      h[kTemperature] = T + jc.heating_fraction * q_new * d / (p_.rho0 * jc.specific_heat);
      const Mat2 be = compose(st.sp, std::exp(2.0 * st.eps[0]), std::exp(2.0 * st.eps[1]));
      const Mat2 Fi = inverse(F);
      const Mat2 C = Fi * be * transpose(Fi);
      h[kCpInvXX] = C.xx;
      h[kCpInvXY] = 0.5 * (C.xy + C.yx);
      h[kCpInvYY] = C.yy;
      h[kCpInvZZ] = std::exp(2.0 * st.eps[2]) / (Fzz * Fzz);
    }
    const double rate = dt > 0.0 ? d / dt : 0.0;
    const double e = jc.specific_heat * (h[kTemperature] - jc.initial_temperature);
    const double mean = -st.J * mie_gruneisen_pressure(eos_, st.J, e);
    // σ* is undefined at zero deviatoric stress; below a micro-stress (1e-9 A) it is 0.
    const double triax = q_new > 1e-9 * jc.a ? mean / q_new : 0.0;
    h[kPlasticStrainRate] = rate;
    h[kTriaxiality] = triax;
    if (d > 0.0) {
      h[kDamage] += damage_increment(jc.failure, d, triax, rate / jc.reference_strain_rate,
                                     homologous_temperature(h[kTemperature]));
      if (h[kDamage] >= 1.0) {
        h[kDamage] = 1.0;
        h[kFailed] = 1.0;
      }
    }
    if (h[kFailed] < 0.5) {
      const Mat2 t = compose(st.sp, mean + s[0], mean + s[1]);
      return {t, mean + s[2]};
    }
  }
  return elastic_kirchhoff(F, Fzz, h);
}

KirchhoffStress JohnsonCook::elastic_kirchhoff(const Mat2& F, double Fzz,
                                               std::span<const double> h) const {
  const ElasticState st = elastic_state(F, Fzz, h);
  double s[3];
  deviator(p_.mu, st.eps, s);
  const double e = p_.jc.specific_heat * (h[kTemperature] - p_.jc.initial_temperature);
  double p = mie_gruneisen_pressure(eos_, st.J, e);
  if (h[kFailed] > 0.5) {
    // Failed (spec §5): no deviatoric stress, no tension.
    s[0] = s[1] = s[2] = 0.0;
    p = std::max(p, 0.0);
  }
  const double mean = -st.J * p;
  return {compose(st.sp, mean + s[0], mean + s[1]), mean + s[2]};
}

Mat2 JohnsonCook::update(const Mat2& /*F_old*/, const Mat2& F_new, double dt,
                         std::span<double> h) const {
  // The rate enters through Δε̄p/Δt; F_old is not needed (Cp⁻¹ carries the history).
  return update_kirchhoff(F_new, 1.0, dt, h).in_plane * transpose(inverse(F_new));  // P = τ F⁻ᵀ
}

double JohnsonCook::cauchy_zz(const Mat2& F, std::span<const double> h) const {
  return elastic_kirchhoff(F, 1.0, h).zz / det(F);
}

double JohnsonCook::energy_density(const Mat2& F, std::span<const double> h) const {
  // Stored energy per reference volume: deviatoric Hencky μ dev ε_e : dev ε_e plus the cold
  // Mie–Grüneisen energy −∫ p(J, 0) dJ. The thermal pressure Γρe is not a potential of the
  // strain and is left out (its work is part of the heat budget); a failed particle stores
  // only compression.
  const ElasticState st = elastic_state(F, 1.0, h);
  const bool failed = h[kFailed] > 0.5;
  double dev = 0.0;
  if (!failed) {
    const double mean = (st.eps[0] + st.eps[1] + st.eps[2]) / 3.0;
    for (int a = 0; a < 3; ++a) dev += (st.eps[a] - mean) * (st.eps[a] - mean);
  }
  return p_.mu * dev + mie_gruneisen_cold_energy(eos_, st.J, failed);
}

}  // namespace slamsph
