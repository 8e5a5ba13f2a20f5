// The Lagrangian → Eulerian switch of failed solid particles (paper §3, spec §5;
// docs/model.md §3 "Eulerian switch of failed particles"; state in solid/eulerian_state.h).
//
// A particle is switched when it has failed (the law's `failed` history field) or one of
// its reference neighbours (the full reference pair list) has. Switched particles leave the
// total-Lagrangian sums: the topology is rebuilt over the intact particles only
// (solid/solid_topology.h, a subset build), so every remaining TL sum is the one of an
// intact body with a free surface where the switched particles were. Every pair with at
// least one switched particle is an Eulerian pair over current neighbours (a cell list over
// the body's current positions, support 2 h_ij with h_ij = (h_i + h_j)/2, the body's kernel).
//
// A switched particle keeps its law: its deformation gradient is advanced in the current
// configuration, F ← (1 − ½ h L)⁻¹ (1 + ½ h L) F, with the corrected velocity gradient
//
//   L_i = Σ_j (v_j − v_i) ⊗ g_ij,  g_ij = K_i V0_j ∇_iW_ij,  K_i = M_i⁻ᵀ,
//   M_i = Σ_j (x_j − x_i) ⊗ V0_j ∇_iW_ij
//
// over all its current neighbours (exact for a linear velocity field; K = 1 when
// det M <= 0.1, an almost isolated particle), and the law's committing update gives P (a
// failed Johnson–Cook particle: compression only). ρ = ρ0/det F then integrates the
// continuity equation on the current neighbours (d ln J/dt = tr L).
//
// Force (docs/model.md §3 "Eulerian switch", Eq. E1): minus the derivative of the stress
// power with respect to the velocities. i's stress power is V0_i P_i : Ḟ_i = V0_i τ_i : L_i
// = Σ_j (v_j − v_i)·A_i V0_j ∇_iW_ij, with the Kirchhoff stress τ = P Fᵀ (= J σ) and the
// stress map A_i = V0_i τ_i K_i, so f_k = −∂/∂v_k Σ_i V0_i P_i : Ḟ_i is, pair by pair,
//
//   f_i += (V0_j A_i + V0_i A_j) ∇_iW_ij,   A = 0 for an intact particle:
//
// the corrected SPH form V_i V0_j σ_i K_i ∇_iW_ij + V_j V0_i σ_j K_j ∇_iW_ij (V = V0 J), each
// particle's Cauchy stress through its own corrected gradient, as the total-Lagrangian pair
// force takes P B (spec §3, Eq. 10). The pair forces are antisymmetric bit for bit (linear
// momentum); their torque vanishes where K is the correction (Σ_j (x_j − x_i) ⊗ g_ij = 1
// and τ symmetric: angular momentum; for K = 1 only for an isotropic τ); and their power is
// minus the switched particles' stress power, so the energy balance closes. The intact
// particles' stress acts only through their own (rebuilt, one-sided) total-Lagrangian sums,
// whose power is their stress power. Π_ij is Monaghan's viscosity with the body's α, β and
// P-wave speed, Π = (−α c μ + β μ²)/ρ̄, μ = h v_ij·x_ij/(r² + 0.01 h²), accounted in f_av.
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
// positions x and velocities v, Ḟ = L (F_old + F_new)/2 for the stress power, and the
// correction K of its gradient at x (header comment).
void eulerian_motion(const SolidBody& body, std::span<const Vec2> x, std::span<const Vec2> v,
                     double h, std::size_t i, Mat2& F_new, Mat2& Fdot, Mat2& K);

// The stress map A_i = V0_i sym(P_i F_iᵀ) K_i of a switched particle from body.F and body.P.
Mat2 eulerian_stress_map(const SolidBody& body, std::size_t i, const Mat2& K);

// The Eulerian pair forces on particle i over body.eulerian.pairs (empty for most intact
// particles) with the stress maps A (0 for intact particles): stress part `fs` and viscous
// part `fv` [N/m]; adds i's half of each pair's viscous dissipation to `heat` [W/m].
void eulerian_force_on(const SolidBody& body, std::span<const Vec2> x, std::span<const Vec2> v,
                       std::span<const Mat2> A, std::size_t i, Vec2& fs, Vec2& fv, double& heat);

// Adds the Eulerian pair forces of every particle to f_stress and f_av and the heating to heat
// (builds the pairs at body.x; the standalone operator, for internal_forces).
void add_eulerian_forces(SolidBody& body, std::span<const Vec2> v, const Executor& exec,
                         std::span<Vec2> f_stress, std::span<Vec2> f_av, std::span<double> heat);

}  // namespace slamsph
