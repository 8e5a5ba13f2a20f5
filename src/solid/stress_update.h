// The one place a body's material law is evaluated (spec §3; interface in
// solid/materials/material_law.h). update_stress is the committing update: called exactly
// once per solid sub-step (and once at set-up, for the initial state), it sets body.P from
// F_old (the previous sub-step's F) and body.F, advances the history fields, and counts
// the pass in body.history.updates. The force operators read body.P only.
#pragma once
#include <array>
#include <span>

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// The committing update of one particle i by `law` (the body of update_stress, for the fused
// sub-step of solid/elastic_substep.h, which dispatches on the law once per call): returns
// P_i at F_new and advances i's history in `hist`. The caller counts the pass
// (++hist.updates) once per sub-step.
template <class Law>
inline Mat2 commit_stress_at(const Law& law, MaterialHistory& hist, const Mat2& F_old,
                             const Mat2& F_new, double dt, std::size_t i) {
  constexpr std::size_t nh = Law::kHistory.size();
  if constexpr (nh == 0) {
    return law.update(F_old, F_new, dt, {});
  } else {
    std::array<double, nh> h;
    for (std::size_t k = 0; k < nh; ++k) h[k] = hist.values[k][i];
    const Mat2 P = law.update(F_old, F_new, dt, h);
    for (std::size_t k = 0; k < nh; ++k) hist.values[k][i] = h[k];
    return P;
  }
}

// body.P at body.F; commits body.history. F_old has body.size() entries; dt [s] the sub-step.
void update_stress(SolidBody& body, std::span<const Mat2> F_old, double dt, const Executor& exec);

// Stored strain energy per unit reference volume of particle i [J/m^3] (no side effects).
double strain_energy_density(const SolidBody& body, std::size_t i);

// Out-of-plane Cauchy stress of particle i (plane strain) [Pa] (no side effects).
double cauchy_zz(const SolidBody& body, std::size_t i);

}  // namespace slamsph
