// The acceleration of an elastic body's contact particles that the contact's static term
// ρ (g − a)·r uses (numerics.wall_acceleration, wall_acceleration_kind.h; docs/model.md §4
// "Wall acceleration of a sub-cycled skin"). Runs after the body state was gathered and,
// with dual time stepping, replaced by its sub-step averages (substep_average.h).
#pragma once
#include <cstddef>

#include "coupling/contact_layout.h"
#include "coupling/contact_particles.h"
#include "coupling/wall_acceleration_kind.h"
#include "solid/solid_body.h"

namespace slamsph {

// For an elastic body b and `wall` other than Local, replaces the acceleration of its
// contact particles (and of their ghosts) by the body's mass-weighted mean Σ m a / Σ m of
// those accelerations (BodyMean) or by zero (None). Rigid bodies are left as gathered.
void apply_wall_acceleration(ContactParticles& contact, const ContactLayout& layout, std::size_t b,
                             const SolidBody& body, WallAcceleration wall);

}  // namespace slamsph
