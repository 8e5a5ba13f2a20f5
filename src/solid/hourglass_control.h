// Hourglass (zero-energy mode) control for total-Lagrangian particle solids (spec §3 "Known
// risk"). Nearest-neighbour central differences (TL-SFPM) and kernel sums (TLSPH) both
// leave zig-zag displacement fields with F unchanged. Following Ganzenmüller (2015,
// CMAME 286:87, "An hourglass control algorithm for Lagrangian SPH"), the zig-zag part of
// the displacement is measured per pair by the error of the particle's own linear
// prediction,
//   ε_ij = F_i (X_j − X_i) − (x_j − x_i),
// which vanishes for every affine motion (rigid rotation included). Variant used here: the
// control is the exact gradient of the penalty potential
//   E_hg = Σ_i Σ_{j∈pairs(i)} ½ κ_ij |ε_ij|²,   κ_ij = α E V0_i V0_j W(|X_ij|) / |X_ij|²,
// (Ganzenmüller's pair stiffness, α = MaterialConfig::hourglass), so the force
//   f_m = −∂E_hg/∂x_m
// is conservative: E_hg is reported as the hourglass energy and the total energy stays
// conserved; it is invariant under translation and rotation of x, so it conserves linear
// and angular momentum; and it is zero for uniform deformation. With
// G_i = Σ_j κ_ij ε_ij ⊗ X_ij, the gradient gathered for particle m over its pairs j is
//   ∂E_hg/∂x_m = Σ_j [ G_j g_jm − G_m g_mj + κ_mj ε_mj − κ_jm ε_jm ].
// With α = 1 the same E_hg is used as a diagnostic of zig-zag energy whether or not the
// control is on.
#pragma once
#include <span>

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// E_hg with coefficient alpha over the pairs of `topo`, from body.x and body.F (F must be
// current) [J/m].
double hourglass_energy(const SolidBody& body, const SolidTopology& topo, double alpha,
                        const Executor& exec);

// f = −∂E_hg/∂x with coefficient alpha (f zero if alpha == 0); needs current body.F.
void compute_hourglass_forces(const SolidBody& body, const SolidTopology& topo, double alpha,
                              const Executor& exec, std::span<Vec2> f);

}  // namespace slamsph
