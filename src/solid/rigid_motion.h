// Rigid-body kinds (spec §4 walls and rigid bodies): fixed, prescribed velocity table, and
// free motion under the fluid force and gravity. Particles follow the body rigidly:
//   x_i = com + R(angle) (X_i − com0),  v_i = vel + ω × r_i,  a_i = acc + α × r_i − ω² r_i.
#pragma once
#include <span>

#include "solid/solid_body.h"

namespace slamsph {

// Velocity of a prescribed table at time t: linear interpolation, held at the ends.
Vec2 prescribed_velocity(std::span<const PrescribedVelocity> table, double t);
// ∫_t0^t1 of the table velocity (exact for the piecewise-linear table).
Vec2 prescribed_displacement(std::span<const PrescribedVelocity> table, double t0, double t1);

// Mass, centre of mass and inertia from the particles (mass/inertia overrides: < 0 = none;
// a mass override alone scales the particle inertia by mass / Σm).
void init_rigid_state(SolidBody& body, double mass_override, double inertia_override);

// Places every particle from the rigid state (x, v, a).
void place_rigid_particles(SolidBody& body);

// One step of each rigid kind, holding body.f_fluid constant over [t, t + dt].
void advance_rigid(SolidBody& body, double t, double dt, Vec2 gravity);

}  // namespace slamsph
