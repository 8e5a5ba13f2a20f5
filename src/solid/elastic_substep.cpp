#include "solid/elastic_substep.h"

#include <algorithm>
#include <span>
#include <utility>
#include <variant>

#include "core/parallel.h"
#include "solid/artificial_viscosity.h"
#include "solid/eulerian_failed_interaction.h"
#include "solid/hourglass_control.h"
#include "solid/stress_update.h"

namespace slamsph {
namespace {

// kHourglass / kViscous: the material's hourglass control and artificial viscosity are on
// (fixed per call, so the pair loops carry no test for them).
template <class Law, bool kHourglass, bool kViscous>
void substeps_with(const Law& law, SolidBody& body, int steps, double h, Vec2 g,
                   const Executor& exec) {
  const std::size_t n = body.size();
  const SolidTopology& topo = body.topology;
  const SolidMaterial& mat = body.material;
  SubstepWorkspace& w = body.substep;
  w.resize(n, topo.pairs.index.size());
  if (body.eulerian.active) {
    w.P_kin.resize(n);
    body.eulerian.stress_map.assign(n, Mat2{});  // intact particles keep 0
  }
  body.f_av.resize(n);
  body.f_hg.resize(n);
  const double alpha = mat.hourglass;
  const double c = mat.sound_speed, av_alpha = mat.av_alpha, av_beta = mat.av_beta;
  const double hh = 0.5 * h;
  // Failed particles interact in the current configuration (eulerian_failed_interaction.h);
  // false for every body with no failed particle, whose loop is then the one below.
  const bool eulerian = body.eulerian.active;
  const std::uint32_t* const start = topo.pairs.start.data();
  const std::uint32_t* const index = topo.pairs.index.data();
  const std::uint32_t* const reverse = topo.pair_reverse.data();
  const Vec2* const grad0 = topo.grad0.data();
  // Work of the sub-step whose half-step velocities are vh (spec §3 energy bookkeeping):
  // force at level n+1 times the synchronised velocity, external force over the drift.
  // A moving clamp's reaction on its particle is −(f_int + f_ext) (the particle does not
  // accelerate); its power at the clamp's constant velocity is the clamps' work.
  auto account = [&](std::span<const Vec2> vh) {
    double diss = 0.0, hg = 0.0, ext = 0.0, grip = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      diss -= dot(body.f_av[i], body.v[i]);
      hg -= dot(body.f_hg[i], body.v[i]);
      ext += dot(w.fext[i], vh[i]);
      if (body.clamped[i]) grip -= dot(body.f_int[i] + w.fext[i], body.clamp_velocity[i]);
    }
    body.dissipated += h * diss;
    body.hourglass_work += h * hg;
    body.external_work += h * ext;
    body.clamp_work += h * grip;
  };
  // First half kick and drift of particle i from v and a into (vh, x).
  auto kick_drift = [&](std::size_t i, std::span<const Vec2> x, std::span<Vec2> vh_out,
                        std::span<Vec2> x_out) {
    if (body.clamped[i]) {  // held fixed (x = X) or moved at the clamp's velocity
      vh_out[i] = body.clamp_velocity[i];
      x_out[i] = x[i] + h * vh_out[i];
      return;
    }
    vh_out[i] = body.v[i] + hh * body.a[i];
    x_out[i] = x[i] + h * vh_out[i];
  };

  const int threads = exec.threads_for(n, kSubstepParticlesPerThread);
  bool swapped = false;  // the current positions are in w.x_next
  exec.run_team(threads, [&](const Team& team) {
    std::span<Vec2> x = body.x, xn = w.x_next, vh = w.vhalf, vhn = w.vhalf_next;
    const auto [b, e] = team.share(n);
    for (std::size_t i = b; i < e; ++i) {
      w.upper[i] = start[i + 1];
      for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) {
        const std::uint32_t j = index[k];
        if (j > i && w.upper[i] == start[i + 1]) w.upper[i] = k;
        w.X_ij[k] = body.X[j] - body.X[i];
        w.g_rev[k] = grad0[reverse[k]];
        if constexpr (kHourglass) w.kappa[k] = hourglass_pair_stiffness(body, topo, alpha, i, j, k);
        if constexpr (kViscous) {
          w.viscous_weight[k] = viscous_pair_weight(body, topo, i, k);
          // The same expressions as viscous_force_on (artificial_viscosity.h).
          w.pair_h[k] = 0.5 * (topo.h[i] + topo.h[j]);
          w.pair_rho0[k] = 0.5 * (body.rho0[i] + body.rho0[j]);
        }
      }
      w.fext[i] = body.f_fluid[i] + body.m[i] * g;
      body.a[i] = body.clamped[i] ? Vec2{} : (body.f_int[i] + w.fext[i]) / body.m[i];
      kick_drift(i, x, vh, x);
    }
    team.barrier();
    for (int step = 0; step < steps; ++step) {
      if (eulerian) {  // current pairs of the switched particles at the drifted positions
        if (team.leader()) build_eulerian_pairs(body, x);
        team.barrier();
      }
      // Pass 1: F and Ḟ, the viscous pair terms (each pair once, from its lower particle:
      // they depend on x and v½ only), the law's committing update, stress power, hourglass
      // moment.
      for (std::size_t i = b; i < e; ++i) {
        Mat2 F, Fdot;
        // A switched particle has no total-Lagrangian pairs left (its loops below are empty):
        // its F comes from its current neighbours.
        const Vec2 xi = x[i], vi = vh[i];
        const std::uint32_t k0 = start[i], ku = w.upper[i], k1 = start[i + 1];
        for (std::uint32_t k = k0; k < ku; ++k) {
          const std::uint32_t j = index[k];
          F += outer(x[j] - xi, grad0[k]);
          Fdot += outer(vh[j] - vi, grad0[k]);
        }
        for (std::uint32_t k = ku; k < k1; ++k) {
          const std::uint32_t j = index[k];
          const Vec2 xj = x[j], vj = vh[j];
          F += outer(xj - xi, grad0[k]);
          Fdot += outer(vj - vi, grad0[k]);
          if constexpr (kViscous) {
            // viscous_force_on's pair term for i; for j it is the exact negative (x_ji =
            // −x_ij and v_ji = −v_ij bit for bit, Π and |c| symmetric), the heat the same.
            const Vec2 xij = xi - xj, vij = vi - vj;
            const double pi =
                monaghan_pi(vij, xij, w.pair_h[k], w.pair_rho0[k], c, av_alpha, av_beta);
            Vec2 f;
            double q = 0.0;
            if (pi != 0.0) {
              const double s = pi * w.viscous_weight[k] / norm(xij);
              f = s * xij;
              q = -0.5 * s * dot(xij, vij);
            }
            const std::uint32_t rk = reverse[k];
            w.f_visc[k] = f;
            w.f_visc[rk] = -f;
            w.q_visc[k] = q;
            w.q_visc[rk] = q;
          }
        }
        // The material's F and Ḟ: the kinematic ones above (the hourglass control below
        // keeps the kinematic F) times the map C that keeps F continuous across a switch's
        // topology rebuild (SolidBody::F_rebase); a switched particle's from its current
        // neighbours.
        Mat2 Fm = F, K;
        const bool switched = eulerian && body.eulerian.switched[i];
        if (eulerian) {
          if (switched) {
            eulerian_motion(body, x, vh, h, i, Fm, Fdot, K);
          } else {
            Fm = F * body.F_rebase[i];
            Fdot = Fdot * body.F_rebase[i];
          }
        }
        const Mat2 F_old = body.F[i], P_old = body.P[i];
        body.F[i] = Fm;
        const Mat2 P = commit_stress_at(law, body.history, F_old, Fm, h, i);
        body.P[i] = P;
        if (eulerian) w.P_kin[i] = body.kinematic_P(i);
        if (switched) body.eulerian.stress_map[i] = eulerian_stress_map(body, i, K);
        // de/dt = P : Ḟ / ρ0 with P trapezoidal over the sub-step (spec §3).
        w.stress_power[i] = ddot(0.5 * (P_old + P), Fdot) / body.rho0[i];
        if constexpr (kHourglass) {
          // hourglass_moment (hourglass_control.h) with the stored X_ij and κ_ij.
          Mat2 Gi;
          for (std::uint32_t k = k0; k < k1; ++k) {
            const Vec2 Xij = w.X_ij[k];
            const Vec2 keps = w.kappa[k] * (F * Xij - (x[index[k]] - xi));
            w.keps[k] = keps;
            Gi += outer(keps, Xij);
          }
          w.G[i] = Gi;
        }
      }
      if (team.leader() && step > 0) account(vhn);  // the previous sub-step's v½
      team.barrier();
      // Pass 2: forces (stress_force_on, viscous_force_on and hourglass_force_on in one loop
      // over i's pairs, each sum in its own order), second half kick, internal energy; next
      // kick and drift.
      const bool more = step + 1 < steps;
      // The stress of the TL pair force: P, or P Cᵀ after an Eulerian switch (tl_pair_force.h).
      const Mat2* const Pt = eulerian ? w.P_kin.data() : body.P.data();
      for (std::size_t i = b; i < e; ++i) {
        Vec2 fs, fav, grad;
        double heat = 0.0;
        const Mat2 Pi = body.V0[i] * Pt[i];
        const Mat2 Gi = kHourglass ? w.G[i] : Mat2{};
        for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) {
          const std::uint32_t j = index[k];
          const Vec2 gk = grad0[k], gr = w.g_rev[k];
          fs += Pi * gk;
          fs -= body.V0[j] * (Pt[j] * gr);
          if constexpr (kViscous) {
            fav += w.f_visc[k];
            heat += w.q_visc[k];
          }
          if constexpr (kHourglass) {
            grad += w.G[j] * gr;
            grad -= Gi * gk;
            grad += w.keps[k];
            grad -= w.keps[reverse[k]];
          }
        }
        if (eulerian) {
          Vec2 fse, fve;
          eulerian_force_on(body, x, vh, body.eulerian.stress_map, i, fse, fve, heat);
          fs += fse;
          fav += fve;
        }
        const Vec2 fhg = kHourglass ? -grad : Vec2{};
        body.f_av[i] = fav;
        body.f_hg[i] = fhg;
        body.f_int[i] = fs + fav + fhg;
        body.a[i] = body.clamped[i] ? Vec2{} : (body.f_int[i] + w.fext[i]) / body.m[i];
        body.v[i] = body.clamped[i] ? body.clamp_velocity[i] : vh[i] + hh * body.a[i];
        body.e[i] += h * (w.stress_power[i] + heat / body.m[i]);
        if (more) kick_drift(i, x, vhn, xn);
      }
      team.barrier();
      if (more) {
        std::swap(x, xn);
        std::swap(vh, vhn);
        if (team.leader()) swapped = !swapped;
      }
    }
    if (team.leader() && steps > 0) account(vh);
  });
  if (swapped) std::swap(body.x, w.x_next);
  body.history.updates += static_cast<std::uint64_t>(steps);
}

template <class Law>
void substeps_dispatch(const Law& law, SolidBody& body, int steps, double h, Vec2 g,
                       const Executor& exec) {
  const SolidMaterial& mat = body.material;
  const bool hourglass = mat.hourglass != 0.0;
  const bool viscous = !(mat.av_alpha == 0.0 && mat.av_beta == 0.0);
  if (hourglass && viscous)
    substeps_with<Law, true, true>(law, body, steps, h, g, exec);
  else if (hourglass)
    substeps_with<Law, true, false>(law, body, steps, h, g, exec);
  else if (viscous)
    substeps_with<Law, false, true>(law, body, steps, h, g, exec);
  else
    substeps_with<Law, false, false>(law, body, steps, h, g, exec);
}

}  // namespace

void run_elastic_substeps(SolidBody& body, int steps, double h, Vec2 g, const Executor& exec) {
  std::visit([&](const auto& law) { substeps_dispatch(law, body, steps, h, g, exec); },
             body.material.law);
}

}  // namespace slamsph
