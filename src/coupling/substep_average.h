// The solid state the fluid sees after a sub-cycled fluid step (issue 9; docs/model.md §6).
// With dual time stepping an elastic body takes n sub-steps inside one fluid step; its
// velocity and acceleration at the last sub-step carry structural ringing and hourglass
// noise of the sub-step scale (aluminium skins: ~100 sub-steps per fluid step), which the
// virtual pressure's rho (g - a) . r term and the contact's U_R would turn into pressure
// noise. The fluid step only resolves the motion averaged over it, so the contact takes the
// time averages over [t_n, t_n + dt] (as SPHinXsys does), which are exact for any sub-step
// sequence: v_mean = (x(t_n + dt) - x(t_n)) / dt, a_mean = (v(t_n + dt) - v(t_n)) / dt.
// Positions stay the current ones.
#pragma once
#include <vector>

#include "core/vec.h"
#include "coupling/contact_layout.h"
#include "coupling/contact_particles.h"
#include "solid/solid_body.h"

namespace slamsph {

struct SubstepAverage {
  std::vector<Vec2> x0, v0;          // body state at the start of the fluid step
  std::vector<Vec2> v_mean, a_mean;  // averages over the step (valid after end())
  bool valid = false;

  void begin(const SolidBody& body);
  void end(const SolidBody& body, double dt);
};

// Replaces the gathered velocity and acceleration of body b's contact particles (and of
// their ghosts) by the averages, where `avg` is valid.
void apply_substep_average(ContactParticles& contact, const ContactLayout& layout, std::size_t b,
                           const SubstepAverage& avg);

}  // namespace slamsph
