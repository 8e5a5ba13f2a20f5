// What the run driver calls on a solid body (spec §3, §6): setup from the case, the stable
// step, advancing over a (fluid) step with sub-cycling, energies and summaries.
//
// Elastic bodies advance by kick–drift–kick leapfrog (second order, symplectic):
//   v+ = v + h/2 a(x, v−),  x' = x + h v+,  a' = a(x', v+),  v' = v+ + h/2 a'
// with n = ceil(dt / stable_time_step) equal sub-steps h = dt/n and the fluid force held
// constant; the internal force at the end of a call is cached and reused as the first half
// kick of the next call (one force evaluation per sub-step). Passing dt <= the stable step
// gives exactly one step (the global-step switch of spec §6).
#pragma once
#include <string>
#include <vector>

#include "core/vec.h"
#include "solid/body_setup.h"
#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// Called after the geometry code set X, x = X, V0, m, rho0 and layer. Sets kind, scheme,
// dx, kernel, gravity flag, clamps, initial velocities (velocity + angular_velocity about the
// centre of mass, plus the "cantilever_mode" profile), the reference neighbour sets and
// operators, F = I, P = 0, the rigid state (mass, centre of mass, inertia from the particles
// unless given) and the prescribed-motion table (sorted by time). `cfg.material` is
// required for elastic bodies. Throws InputError for inconsistent input (message names the
// body).
void setup_body(SolidBody& body, const BodySetup& cfg);

// Δt_s = CFL · ℓ / (s (c_s sqrt(1 + α_hg) + max|v|)) (spec §3; α_hg the hourglass
// coefficient, s the joints' gradient factor) for elastic bodies; +inf for rigid kinds. ℓ = h
// for h <= 1.3 dx and artificial viscosity α <= 1; above, ℓ shrinks so that neither the
// stress waves (set by dx in TL-SFPM) nor the viscous damping (∝ α h) outrun the step
// (docs/model.md §3 "Solid stable step").
double stable_time_step(const SolidBody& body);

// Advances from t to t + dt holding body.f_fluid constant (see the header comment). Sets
// `a` of every particle; clamped particles stay at X with v = a = 0.
void advance_body(SolidBody& body, double t, double dt, Vec2 gravity, const Executor& exec);

struct BodyEnergies {
  double kinetic = 0.0;     // Σ ½ m v² [J/m]
  double strain = 0.0;      // Σ V0 Ψ(F) [J/m]
  double dissipated = 0.0;  // work removed by artificial viscosity since setup [J/m]
  double hourglass = 0.0;   // hourglass-control potential E_hg [J/m]
};
BodyEnergies body_energies(const SolidBody& body);

struct BodySummary {
  Vec2 com;                // mass-weighted centre [m]
  Vec2 mean_velocity;      // mass-weighted [m/s]
  Vec2 mean_acceleration;  // mass-weighted [m/s^2]
};
BodySummary body_summary(const SolidBody& body);

// Per-particle output fields for VTK, values interleaved by component.
struct SolidField {
  std::string name, unit;
  int components = 1;
  std::vector<double> values;
};
std::vector<SolidField> solid_output_fields(const SolidBody& body);

// Re-evaluates the internal force from the committed F and P and the current v. It does not
// update the material (the law's history advances exactly once per sub-step, inside
// advance_body); advance_body evaluates forces itself.
void refresh_internal_forces(SolidBody& body, const Executor& exec);

}  // namespace slamsph
