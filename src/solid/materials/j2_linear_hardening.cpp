#include "solid/materials/j2_linear_hardening.h"

#include <cmath>

#include "solid/materials/plane_spectral.h"

namespace slamsph {
namespace {

// Elastic state from b_e = F Cp⁻¹ Fᵀ: spectral form and principal logarithmic strains.
struct ElasticState {
  Spectral sp;
  double eps[3];  // ½ ln of the eigenvalues of b_e (in-plane 1, 2; out-of-plane 3)
};

ElasticState elastic_state(const Mat2& F, std::span<const double> h) {
  using J = J2LinearHardening;
  const Mat2 C{h[J::kCpInvXX], h[J::kCpInvXY], h[J::kCpInvXY], h[J::kCpInvYY]};
  const Mat2 b = F * C * transpose(F);
  ElasticState st{spectral(b.xx, 0.5 * (b.xy + b.yx), b.yy), {}};
  st.eps[0] = 0.5 * std::log(st.sp.e1);
  st.eps[1] = 0.5 * std::log(st.sp.e2);
  st.eps[2] = 0.5 * std::log(h[J::kCpInvZZ]);
  return st;
}

// Principal Kirchhoff stresses of the Hencky energy, τ_a = λ tr ε + 2μ ε_a.
void hencky(const J2Parameters& p, const double eps[3], double tau[3]) {
  const double l = p.lambda * (eps[0] + eps[1] + eps[2]);
  for (int a = 0; a < 3; ++a) tau[a] = l + 2.0 * p.mu * eps[a];
}

}  // namespace

Mat2 J2LinearHardening::update(const Mat2& /*F_old*/, const Mat2& F_new, double /*dt*/,
                               std::span<double> h) const {
  ElasticState st = elastic_state(F_new, h);
  double tau[3];
  hencky(p_, st.eps, tau);
  const double mean = (tau[0] + tau[1] + tau[2]) / 3.0;
  double s[3] = {tau[0] - mean, tau[1] - mean, tau[2] - mean};
  const double q = std::sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
  const double f = q - (p_.yield_stress + p_.hardening_modulus * h[kPlasticStrain]);
  if (f > 0.0) {
    // Radial return (Simo & Hughes 1998, Box 9.1): the consistency condition
    // q_tr − 3μ Δε̄ = σ_y + H (ε̄p + Δε̄) is linear in Δε̄.
    const double d = f / (3.0 * p_.mu + p_.hardening_modulus);
    const double flow = 1.5 * d / q;  // Δε̄ (3/2) / q_tr
    for (int a = 0; a < 3; ++a) {
      st.eps[a] -= flow * s[a];
      s[a] *= 1.0 - 3.0 * p_.mu * d / q;
      tau[a] = mean + s[a];
    }
    h[kPlasticStrain] += d;
    // Commit Cp⁻¹ = F⁻¹ b_e F⁻ᵀ with the returned b_e = exp(2 ε_e).
    const Mat2 be = compose(st.sp, std::exp(2.0 * st.eps[0]), std::exp(2.0 * st.eps[1]));
    const Mat2 Fi = inverse(F_new);
    const Mat2 C = Fi * be * transpose(Fi);
    h[kCpInvXX] = C.xx;
    h[kCpInvXY] = 0.5 * (C.xy + C.yx);
    h[kCpInvYY] = C.yy;
    h[kCpInvZZ] = std::exp(2.0 * st.eps[2]);
  }
  // Elastic step: b_e = b_e,tr, so Cp⁻¹ is unchanged and nothing is written.
  const Mat2 t = compose(st.sp, tau[0], tau[1]);
  return t * transpose(inverse(F_new));  // P = τ F⁻ᵀ
}

PlaneKirchhoff J2LinearHardening::elastic_kirchhoff(const Mat2& F,
                                                    std::span<const double> h) const {
  const ElasticState st = elastic_state(F, h);
  double tau[3];
  hencky(p_, st.eps, tau);
  return {compose(st.sp, tau[0], tau[1]), tau[2]};
}

double J2LinearHardening::cauchy_zz(const Mat2& F, std::span<const double> h) const {
  return elastic_kirchhoff(F, h).zz / det(F);
}

double J2LinearHardening::energy_density(const Mat2& F, std::span<const double> h) const {
  // Hencky stored energy ψ = ½ λ (tr ε_e)² + μ ε_e : ε_e (per reference volume; the
  // plastic work is dissipated and not part of it).
  const ElasticState st = elastic_state(F, h);
  const double tr = st.eps[0] + st.eps[1] + st.eps[2];
  return 0.5 * p_.lambda * tr * tr +
         p_.mu * (st.eps[0] * st.eps[0] + st.eps[1] * st.eps[1] + st.eps[2] * st.eps[2]);
}

}  // namespace slamsph
