// The Lagrangian → Eulerian switch of failed solid particles (paper §3, spec §5;
// docs/model.md §3 "Eulerian switch of failed particles"; state in solid/eulerian_state.h).
//
// A particle is switched when it has failed (the law's `failed` history field) or one of
// its reference neighbours (the full reference pair list) has. Switched particles leave the
// total-Lagrangian sums: the topology is rebuilt over the intact particles only
// (solid/solid_topology.h, a subset build), so every remaining TL sum is the one of an
// intact body with a free surface where the switched particles were. Every pair with at
// least one switched particle is an Eulerian pair over current neighbours (a cell list over
// the body's current positions, support 2 h_ij with h_ij = (h_i + h_j)/2, the body's kernel):
//
//   m_i dv_i/dt += Σ_j m_i m_j [ ê·(T_i/ρ_i² + T_j/ρ_j²)ê − Π_ij ] W'(r) ê,
//   ê = (x_i − x_j)/r,  T = 2σ − ½ tr σ 1,  σ = sym(P Fᵀ)/J,  ρ = ρ0/J,
//
// the usual symmetric SPH stress form m_i m_j (σ_i/ρ_i² + σ_j/ρ_j²)·∇_iW_ij projected on the
// pair direction, with T chosen so that the projection has the same continuum limit (−∇·σ/ρ
// on an isotropic neighbourhood: the fourth moment of ê is (δδ + δδ + δδ)/8 in 2D). For an
// isotropic stress (a failed particle: σ = −max(p, 0) 1) T = σ and the two forms are the same
// pair by pair. The projection makes every pair force central, so linear and angular
// momentum are conserved to round-off for any stress (the unprojected form conserves angular
// momentum only for isotropic stresses). Π_ij is Monaghan's viscosity with the body's α, β
// and P-wave speed, Π = (−α c μ + β μ²)/ρ̄, μ = h v_ij·x_ij/(r² + 0.01 h²).
//
// A switched particle keeps its law: its deformation gradient is advanced in the current
// configuration, F ← (1 − ½ h L)⁻¹ (1 + ½ h L) F with the corrected velocity gradient
// L = [Σ_j V0_j (v_j − v_i) ⊗ ∇W_ij] M⁻¹, M = Σ_j V0_j (x_j − x_i) ⊗ ∇W_ij (exact for a linear
// velocity field; uncorrected when det M < 0.1, an almost isolated particle), and the law's
// committing update gives P (a failed Johnson–Cook particle: compression only). ρ = ρ0/det F
// then integrates the continuity equation on the current neighbours (d ln J/dt = tr L).
#pragma once
#include <span>

#include "core/vec.h"
#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// The law's `failed` history field of the body (1 = failed), or null if its law cannot fail.
const std::vector<double>* failed_flags(const SolidBody& body);

// Updates body.eulerian from the law's `failed` field (a no-op returning false for a body
// whose law cannot fail or that has no failed particle). When the failed set has grown, the
// switched set is recomputed and body.topology rebuilt over the intact particles; if that
// meets a degenerate neighbourhood, the intact particles next to the switched ones are
// switched too, until it does not. Returns body.eulerian.active.
bool update_eulerian_switch(SolidBody& body, const Executor& exec);

// body.eulerian.pairs at positions x (serial counting sort and ordered fills: the list does not
// depend on the thread count). Requires body.eulerian.active.
void build_eulerian_pairs(SolidBody& body, std::span<const Vec2> x);

// For a switched particle i: F_new from body.F[i] over a step h [s] with the current
// positions x and velocities v, and Ḟ = L (F_old + F_new)/2 for the stress power.
void eulerian_motion(const SolidBody& body, std::span<const Vec2> x, std::span<const Vec2> v,
                     double h, std::size_t i, Mat2& F_new, Mat2& Fdot);

// The Eulerian pair forces on particle i over body.eulerian.pairs (empty for most intact
// particles) from body.F and body.P: stress part `fs` and viscous part `fv` [N/m]; adds i's
// half of each pair's viscous dissipation to `heat` [W/m].
void eulerian_force_on(const SolidBody& body, std::span<const Vec2> x, std::span<const Vec2> v,
                       std::size_t i, Vec2& fs, Vec2& fv, double& heat);

// Adds the Eulerian pair forces of every particle to f_stress and f_av and the heating to heat
// (builds the pairs at body.x; the standalone operator, for internal_forces).
void add_eulerian_forces(SolidBody& body, std::span<const Vec2> v, const Executor& exec,
                         std::span<Vec2> f_stress, std::span<Vec2> f_av, std::span<double> heat);

}  // namespace slamsph
