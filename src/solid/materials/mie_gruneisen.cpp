#include "solid/materials/mie_gruneisen.h"

#include <algorithm>
#include <cmath>

namespace slamsph {

double mie_gruneisen_pressure(const MieGruneisenParameters& p, double J, double e) {
  const double eta = 1.0 / J - 1.0;
  const double k = p.rho0 * p.c * p.c;
  const double thermal = p.gamma * (p.rho0 / J) * e;
  if (eta <= 0.0) return k * eta + thermal;
  const double den = 1.0 - (p.s - 1.0) * eta;
  const double hugoniot = k * eta * (1.0 + eta) / (den * den);
  return (1.0 - 0.5 * p.gamma * eta) * hugoniot + thermal;
}

double mie_gruneisen_cold_energy(const MieGruneisenParameters& p, double J, bool compression_only) {
  // −∫_1^J p dJ' by 5-point Gauss–Legendre on [J, 1] or [1, J], split at J' = 1 where the
  // branches meet (the integrand is smooth on each side; strains in a metal are small, so
  // the rule is exact to round-off in practice). The tension branch has the closed form
  // ρ0c² (J − 1 − ln J).
  if (J >= 1.0) return compression_only ? 0.0 : p.rho0 * p.c * p.c * (J - 1.0 - std::log(J));
  static constexpr double x[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                  0.9061798459386640};
  static constexpr double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                  0.2369268850561891, 0.2369268850561891};
  const double mid = 0.5 * (1.0 + J), half = 0.5 * (1.0 - J);
  double sum = 0.0;
  for (int k = 0; k < 5; ++k) sum += w[k] * mie_gruneisen_pressure(p, mid + half * x[k], 0.0);
  return half * sum;  // −∫_1^J p = ∫_J^1 p (p > 0 in compression)
}

}  // namespace slamsph
