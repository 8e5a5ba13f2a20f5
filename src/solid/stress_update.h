// The one place a body's material law is evaluated (spec §3; interface in
// solid/materials/material_law.h). update_stress is the committing update: called exactly
// once per solid sub-step (and once at set-up, for the initial state), it sets body.P from
// F_old (the previous sub-step's F) and body.F, advances the history fields, and counts
// the pass in body.history.updates. The force operators read body.P only.
#pragma once
#include <span>

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// body.P at body.F; commits body.history. F_old has body.size() entries; dt [s] the sub-step.
void update_stress(SolidBody& body, std::span<const Mat2> F_old, double dt, const Executor& exec);

// Stored strain energy per unit reference volume of particle i [J/m^3] (no side effects).
double strain_energy_density(const SolidBody& body, std::size_t i);

// Out-of-plane Cauchy stress of particle i (plane strain) [Pa] (no side effects).
double cauchy_zz(const SolidBody& body, std::size_t i);

}  // namespace slamsph
