// Tait equation of state, spec §2 / paper Eq. 4: p = rho0 c0^2/gamma [(rho/rho0)^gamma - 1].
#pragma once
#include <cmath>

namespace slamsph {

struct TaitEos {
  double rho0 = 1000.0;  // rest density [kg/m^3]
  double c0 = 0.0;       // artificial sound speed [m/s]
  double gamma = 7.0;    // exponent [-]

  double stiffness() const { return rho0 * c0 * c0 / gamma; }
  double pressure(double rho) const {
    const double r = rho / rho0;
    if (gamma == 7.0) {  // the usual water exponent: 4 multiplications instead of pow
      const double r2 = r * r, r4 = r2 * r2;
      return stiffness() * (r4 * r2 * r - 1.0);
    }
    return stiffness() * (std::pow(r, gamma) - 1.0);
  }
  // Inverse (used for the hydrostatic start and the virtual density of solid particles).
  double density(double p) const { return rho0 * std::pow(p / stiffness() + 1.0, 1.0 / gamma); }
};

}  // namespace slamsph
