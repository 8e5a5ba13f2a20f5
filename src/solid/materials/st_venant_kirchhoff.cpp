#include "solid/materials/st_venant_kirchhoff.h"

#include <cmath>

namespace slamsph {

SvkParameters svk_from_young(double youngs_modulus, double poisson_ratio) {
  const double nu = poisson_ratio;
  return {youngs_modulus * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)),
          youngs_modulus / (2.0 * (1.0 + nu))};
}

double svk_strain_energy_density(const SvkParameters& p, const Mat2& F) {
  const Mat2 E = green_lagrange(F);
  const double tr = trace(E);
  return 0.5 * p.lambda * tr * tr + p.mu * ddot(E, E);
}

double svk_cauchy_zz(const SvkParameters& p, const Mat2& F) {
  return p.lambda * trace(green_lagrange(F)) / det(F);
}

CauchyStress cauchy_from_pk1(const Mat2& P, const Mat2& F, double sigma_zz) {
  const Mat2 s = P * transpose(F);
  const double J = det(F);
  return {s.xx / J, s.yy / J, 0.5 * (s.xy + s.yx) / J, sigma_zz};
}

double von_mises_stress(const CauchyStress& s) {
  const double a = s.xx - s.yy, b = s.yy - s.zz, c = s.zz - s.xx;
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * s.xy * s.xy);
}

double pressure(const CauchyStress& s) {
  return -(s.xx + s.yy + s.zz) / 3.0;
}

double equivalent_strain(const Mat2& E) {
  const double m = (E.xx + E.yy) / 3.0;  // E_zz = 0
  const double dxx = E.xx - m, dyy = E.yy - m, dzz = -m;
  const double exy = 0.5 * (E.xy + E.yx);
  const double dd = dxx * dxx + dyy * dyy + dzz * dzz + 2.0 * exy * exy;
  return std::sqrt(2.0 / 3.0 * dd);
}

}  // namespace slamsph
