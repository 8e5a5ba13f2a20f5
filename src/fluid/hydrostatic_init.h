// Water at rest starts in hydrostatic equilibrium (no start-up shock), spec §2:
// dp/dz = rho(p) |g| integrated exactly for the Tait EOS below `surface`, rho from the
// inverse EOS, m = rho dx^2.
#pragma once
#include <vector>

#include "core/vec.h"
#include "fluid/fluid_particles.h"
#include "fluid/tait_eos.h"

namespace slamsph {

// Pressure of hydrostatic rest at `depth` below the free surface (0 above it): the exact
// solution of dp/dz = rho(p) g for the Tait EOS,
// p = B [(1 + (gamma-1)/gamma rho0 g z / B)^(gamma/(gamma-1)) - 1], B = rho0 c0^2/gamma.
double hydrostatic_pressure(double depth, double g, const TaitEos& eos);

// Appends particles at `pts` (each owning volume dx^2) with hydrostatic state below the
// free surface `surface`; ids continue from the current size.
void append_hydrostatic_block(FluidParticles& f, const std::vector<Vec2>& pts, double dx,
                              double surface, Vec2 gravity, const TaitEos& eos);

}  // namespace slamsph
