// Energy of a solid body for the energy balance (energy.csv, app/recorder.h). The terms
// are state functions of the body except the accumulators the integrators keep
// (SolidBody::dissipated, ::external_work), so they are exactly what the time integration
// did (solid/body_dynamics.cpp, solid/rigid_motion.cpp).
#pragma once
#include "core/vec.h"
#include "solid/solid_body.h"

namespace slamsph {

struct BodyEnergyTerms {
  double kinetic = 0.0;        // elastic: Σ ½ m |v|²; rigid: ½ M |v|² + ½ I ω² [J/m]
  double strain = 0.0;         // stored elastic energy Σ V0 Ψ(F, history) [J/m]
  double hourglass = 0.0;      // hourglass-control potential E_hg [J/m]
  double viscous = 0.0;        // work removed by the solid's artificial viscosity [J/m]
  double plastic = 0.0;        // plastic work (J2 law), see plastic_work [J/m]
  double dissipated = 0.0;     // viscous + plastic + switch_released (SolidBody) [J/m]
  double potential = 0.0;      // gravity: −Σ m g·x (rigid: −M g·x_com); 0 if the body
                               // does not feel gravity [J/m]
  double external_work = 0.0;  // work of gravity and the fluid since set-up [J/m]
  double clamp_work = 0.0;     // work of moving clamps since set-up (0 if all held fixed) [J/m]
};
// `gravity` is the case's g; a body with feels_gravity = false sees none.
// True if a clamp of the body moves (its work is then a term of the balance).
bool has_moving_clamp(const SolidBody& body);
BodyEnergyTerms body_energy_terms(const SolidBody& body, Vec2 gravity);

// Plastic work of an elastic body since set-up [J/m]. J2 with linear hardening (flow stress
// σ_y + H ε̄p, solid/materials/j2_linear_hardening.h): the Kirchhoff stress power of the
// plastic flow is q dε̄p with q = σ_y + H ε̄p on the yield surface, so per reference volume
// w_p = ∫ (σ_y + H ε̄p) dε̄p = σ_y ε̄p + ½ H ε̄p² (it includes the hardening's stored part,
// which is never given back: counted as dissipated). Johnson–Cook: ρ0 c_v (T − T0)/χ from
// the adiabatic heating of its return mapping (0 if the heating fraction χ is 0; the energy
// lost when a particle fails and the thermal pressure's work are not in it, so they show in
// the residual). 0 for St Venant–Kirchhoff.
double plastic_work(const SolidBody& body);

}  // namespace slamsph
