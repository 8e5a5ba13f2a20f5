// One fluid–solid pair of the Riemann-based contact, spec §4 / paper Eqs. 12–14.
// Fluid particle i is the left state, solid particle s the right state with its virtual
// pressure p'_s, virtual density rho'_s and its own velocity. The same inline function is
// evaluated from the fluid side and from the solid side with identical arguments, so the
// force on s is bit-for-bit minus the force on i and momentum is exchanged exactly.
#pragma once
#include <algorithm>
#include <cmath>

#include "core/kernel.h"
#include "core/vec.h"
#include "fluid/riemann_solver.h"

namespace slamsph {

struct ContactPairResult {
  Vec2 force;          // pressure force on fluid i, f_is = -2 V_i V_s p* grad_i W_is [N/m]
                       // plus the short-range barrier (contact_barrier_force)
  Vec2 force_viscous;  // viscous force on fluid i (Morris, with the mirrored velocity) [N/m]
  double drho_term;    // V_s (v_i - v*) . grad_i W_is (continuity, times 2 rho_i outside)
  double p_star;       // the star pressure that acts (after the cavitation limit) [Pa]
  bool active;         // false if the pair is outside the kernel support
};

struct ContactPairInput {
  Vec2 xi, vi;
  double rhoi, pi, Vi;
  Vec2 xs, vs, vs_noslip;
  double rhos, ps, Vs;
  Vec2 g_rel;  // gravity minus the solid's acceleration (the static state of p', spec §4)
};

// Short-range barrier of a fluid-solid pair (docs/model.md §4, "Short-range barrier"): zero
// unless the fluid particle is closer to the solid particle than
//   r0 = (sqrt(V_i) + sqrt(V_s)) / 4,
// half the rest distance 1/2 (dx_f + d_s) at which the fluid is laid next to a body
// (build_fluid), and then a repulsion of the Lennard-Jones form of Monaghan (1994, J. Comput.
// Phys. 110, boundary forces; exponents 4 and 2 as in Monaghan & Kajtar 2009, Comput. Phys.
// Commun. 180) scaled by the water's stiffness P_b = rho0 c0^2 / gamma:
//   f_is = 2 V_i V_s P_b [(r0/r)^4 - (r0/r)^2] / r0^3 e_si   (on fluid i; -f_is on solid s).
// It is continuous (zero at r0). Why: under tension the pair force -2 V_i V_s p* grad W is
// anti-restoring — a particle nearer the wall than its rest distance sees more wall in its
// support and is pulled further in — and against a skin finer than the water nothing else
// stops it short of the skin's mid-plane (measured: a keel water particle under the
// rebounding skin_cylinder keel, p = -23 kPa, goes from 2.8 mm to 0.5 mm off the outer layer
// in 3 ms, then, past the layer's centre line where the ghosts stop facing it, is pushed in).
// Returns the force on fluid i (zero beyond r0).
inline Vec2 contact_barrier_force(Vec2 dx, double r, double Vi, double Vs, double p_barrier) {
  if (p_barrier <= 0.0) return Vec2{};
  // (sqrt Vi + sqrt Vs)^2 <= 2 (Vi + Vs), so r0^2 <= (Vi + Vs)/8: most pairs are past r0
  // without the two square roots (the margin 1e-6 covers the rounding of r0 below).
  if (8.0 * (r * r) >= 1.000001 * (Vi + Vs)) return Vec2{};
  const double r0 = 0.25 * (std::sqrt(Vi) + std::sqrt(Vs));
  if (r >= r0) return Vec2{};
  const double s2 = (r0 * r0) / (r * r);
  const double phi = s2 * s2 - s2;
  return (2.0 * Vi * Vs * p_barrier * phi / (r0 * r0 * r0 * r)) * dx;
}

// p_min: the lowest star pressure the water sustains before it separates from the solid
// (the fluid's cavitation_pressure, gauge, <= 0; 0 = no adhesion at all).
// p_barrier: the stiffness of the short-range barrier (0 = none), contact_barrier_force.
template <bool kViscous>
inline ContactPairResult contact_pair(const ContactPairInput& in, const Kernel& kernel, double c0,
                                      double omega, double viscosity, double p_min = 0.0,
                                      double p_barrier = 0.0) {
  ContactPairResult out{};
  const Vec2 dx = in.xi - in.xs;
  const double r2 = norm2(dx);
  const double support = kernel.support();
  if (r2 >= support * support || r2 == 0.0) return out;
  out.active = true;
  const double r = std::sqrt(r2);
  const double dwr = kernel.dw_over_r(r);
  const Vec2 e = dx * (-1.0 / r);
  const RiemannState L{in.rhoi, dot(in.vi, e), in.pi};
  const RiemannState R{in.rhos, dot(in.vs, e), in.ps};
  const double dp_static = 0.5 * (in.rhoi + in.rhos) * dot(in.g_rel, dx);
  const RiemannStar s = solve_riemann(L, R, c0, omega, dp_static);
  // Cavitation (docs/model.md §4): water holds suction down to p_min (about one atmosphere
  // below ambient) and then separates from a receding solid instead of being pulled
  // through it (without any limit, the elastic gate swinging back drew fluid particles
  // through its five-particle-thick skin until the run diverged). Where the limit acts, the
  // star state is that of a cavity at p_min: the fluid's interface velocity follows from
  // the left acoustic wave, p* = p_L + rho_L c0 (U_L - U*), so the continuity term sees
  // the same separation as the force (and never a faster interface than the unlimited U*).
  double p_star = s.p, u_star = s.u;
  if (p_star < p_min) {
    p_star = p_min;
    u_star = std::min(s.u, L.u + std::max(L.p - p_min, 0.0) / (L.rho * c0));
  }
  out.p_star = p_star;
  out.force = (-2.0 * in.Vi * in.Vs * p_star * dwr) * dx +
              contact_barrier_force(dx, r, in.Vi, in.Vs, p_barrier);
  out.drho_term = in.Vs * (L.u - u_star) * (-dwr * r);
  if constexpr (kViscous) {
    const double eta2 = kMorrisEta2 * kernel.h() * kernel.h();
    // Morris et al. 1997 with mu = rho nu on both sides and the mirrored solid velocity.
    const double coef = in.Vi * in.Vs * viscosity * (in.rhoi + in.rhos) * dwr * r2 / (r2 + eta2);
    out.force_viscous = coef * (in.vi - in.vs_noslip);
  }
  return out;
}

}  // namespace slamsph
