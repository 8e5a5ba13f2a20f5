// Energy of the water for the energy balance (energy.csv, app/recorder.h): kinetic,
// gravitational potential and internal (elastic) energy of the weakly compressible fluid.
#pragma once
#include "core/vec.h"
#include "fluid/fluid_particles.h"
#include "fluid/tait_eos.h"

namespace slamsph {

// Specific internal energy of the Tait fluid at density rho [J/kg], zero at rho0: the work
// of compression e(ρ) = ∫_{ρ0}^{ρ} p/ρ'² dρ' (first law, adiabatic, spec §2 / paper Eq. 4
// for p). Closed form with B = ρ0 c0²/γ, r = ρ/ρ0:
//   e = (B/ρ0) [ (r^(γ−1) − 1)/(γ−1) + 1/r − 1 ],
// ≈ c0² (r − 1)²/2 near r = 1 (evaluated with expm1/log1p, no cancellation).
double tait_specific_internal_energy(const TaitEos& eos, double rho);

struct FluidEnergies {
  double kinetic = 0.0;    // Σ ½ m |v|² [J/m]
  double potential = 0.0;  // −Σ m g·x, gravity's potential with the datum at x = 0 [J/m]
  double internal = 0.0;   // Σ m e(ρ) [J/m]
};
FluidEnergies fluid_energies(const FluidParticles& fluid, const TaitEos& eos, Vec2 gravity);

}  // namespace slamsph
