// Absorbing (damping) zone near chosen tank walls (issue 9 item 6; docs/model.md §2,
// "Absorbing zone"; docs/case_format.md [fluid.absorbing_zone]). A weakly compressible
// tank returns the impact's pressure wave from its walls (the paper's 0.4 m deep tank at
// c0 = 30 m/s: 2 × 0.4 / 30 = 27 ms) into the force history; in the real tank the wave
// would be far weaker (c = 1480 m/s, and it leaves through the structure). The zone relaxes
// the water inside a band of width w along each chosen wall towards hydrostatic rest:
//   dv/dt = ... − σ(d) v,   dρ/dt = ... − σ(d) (ρ − ρ_h(y)),   σ(d) = σ_w (1 − d/w)²,
// d the distance from the wall face (the tank's inner box), ρ_h the density of hydrostatic
// rest below the still surface. With the same σ on both fields the 1D acoustic
// characteristics p' ± ρ c u' decay as exp(−∫σ dt) without being coupled to each other,
// so the zone attenuates a plane wave without reflecting it (up to the discretisation);
// the quadratic ramp keeps that true for the SPH fields too. A wave crossing the zone
// and back is attenuated by exp(−2 σ_w w / (3 c0)); σ_w = strength · c0 / w, so the
// default strength 10 gives exp(−6.7) = 1.2e-3. Water at hydrostatic rest is left
// unchanged. The damping is applied as an exact exponential over each step (stable for
// any σ dt).
#pragma once
#include <array>

#include "core/box.h"
#include "core/vec.h"
#include "fluid/fluid_particles.h"
#include "fluid/tait_eos.h"

namespace slamsph {

class Executor;

struct AbsorbingZone {
  enum Wall { kLeft = 0, kRight = 1, kBottom = 2, kTop = 3 };
  Box inner;                           // the tank's inner box: the wall faces [m]
  std::array<double, 4> width{};       // band width per wall (0 = no zone there) [m]
  std::array<double, 4> sigma_wall{};  // damping rate at the wall face σ_w [1/s]
  double surface = 0.0;                // still free-surface level for ρ_h [m]
  Vec2 gravity;                        // [m/s^2]

  bool active() const { return width[0] > 0 || width[1] > 0 || width[2] > 0 || width[3] > 0; }
};

// σ at x: the largest of the walls' σ_w (1 − d/w)² with d the distance from the face into
// the tank (0 outside every band).
double absorbing_rate(const AbsorbingZone& z, Vec2 x);

// Density of hydrostatic rest at x (exact Tait hydrostatics, fluid/hydrostatic_init.h).
double absorbing_reference_density(const AbsorbingZone& z, const TaitEos& eos, Vec2 x);

// Relaxes v and ρ (and p = p(ρ)) of the particles inside the zone over a step dt:
// v ← v e^{−σ dt}, ρ ← ρ_h + (ρ − ρ_h) e^{−σ dt}. Returns the momentum change it made,
// Σ m (v_after − v_before) [N s/m] (the momentum balance, README "Momentum balance"): the
// zone is the one force on the water that is not a pair force, gravity or the contact.
Vec2 apply_absorbing_zone(FluidParticles& f, const AbsorbingZone& z, const TaitEos& eos, double dt,
                          const Executor& exec);

}  // namespace slamsph
