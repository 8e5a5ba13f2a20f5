#include "fluid/fluid_energy.h"

#include <cmath>

namespace slamsph {

double tait_specific_internal_energy(const TaitEos& eos, double rho) {
  const double d = rho / eos.rho0 - 1.0;  // r − 1
  const double g1 = eos.gamma - 1.0;
  // (r^(γ−1) − 1)/(γ−1) + 1/r − 1, with 1/r − 1 = −d/r
  const double a = std::abs(g1) > 0.0 ? std::expm1(g1 * std::log1p(d)) / g1 : std::log1p(d);
  return eos.stiffness() / eos.rho0 * (a - d / (1.0 + d));
}

FluidEnergies fluid_energies(const FluidParticles& f, const TaitEos& eos, Vec2 gravity) {
  FluidEnergies e;
  for (std::size_t i = 0; i < f.size(); ++i) {
    e.kinetic += 0.5 * f.m[i] * norm2(f.v[i]);
    e.potential -= f.m[i] * dot(gravity, f.x[i]);
    e.internal += f.m[i] * tait_specific_internal_energy(eos, f.rho[i]);
  }
  return e;
}

}  // namespace slamsph
