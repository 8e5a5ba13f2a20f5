// The choice of numerics.fluid_integrator (docs/case_format.md, docs/model.md §5).
#pragma once

namespace slamsph {

// How the fluid step advances x, v, rho (app/fsi_stepper.h, docs/model.md §5):
//   KickDriftKick  one fused rate evaluation per step at the predicted state (the default;
//                  stable to an acoustic CFL of about 0.35, docs/validation.md §6);
//   Symplectic     position Verlet with the density split around the velocity step
//                  (Zhang, Hu & Adams 2017; SPHinXsys): a momentum pass at mid-step and a
//                  continuity pass at the new velocity, stable to CFL ~0.7; the bodies
//                  advance in two halves around the momentum pass.
enum class FluidIntegrator { KickDriftKick, Symplectic };

// Which of the two rate sums a pass computes (fluid/gsph_fluid_rates.h, coupling/contact_rates.h).
//   Both        a and drho (the kick-drift-kick step's fused pass);
//   Momentum    a only (drho left untouched), and the contact reaction on the solids;
//   Continuity  drho only (a left untouched).
enum class RatePass { Both, Momentum, Continuity };

}  // namespace slamsph
