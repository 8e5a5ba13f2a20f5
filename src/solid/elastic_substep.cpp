#include "solid/elastic_substep.h"

#include <algorithm>
#include <span>
#include <utility>
#include <variant>

#include "core/parallel.h"
#include "core/simd2.h"
#include "solid/artificial_viscosity.h"
#include "solid/eulerian_failed_interaction.h"
#include "solid/hourglass_control.h"
#include "solid/stress_update.h"

namespace slamsph {
namespace {

// kHourglass / kViscous: the material's hourglass control and artificial viscosity are on;
// kEulerian: body.eulerian.active (fixed per call, so the pair loops carry no test for them).
template <class Law, bool kHourglass, bool kViscous, bool kEulerian>
void substeps_with(const Law& law, SolidBody& body, int steps, double h, Vec2 g,
                   const Executor& exec) {
  const std::size_t n = body.size();
  const SolidTopology& topo = body.topology;
  const SolidMaterial& mat = body.material;
  SubstepWorkspace& w = body.substep;
  const int threads = exec.threads_for(n, kSubstepParticlesPerThread);
  w.resize(n, topo.pairs.index.size(), static_cast<std::size_t>(threads));
  if constexpr (kEulerian) {
    w.vhalf_next.resize(n);
    w.x_next.resize(n);
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
  constexpr bool eulerian = kEulerian;
  const std::uint32_t* const start = topo.pairs.start.data();
  const std::uint32_t* const index = topo.pairs.index.data();
  const std::uint32_t* const reverse = topo.pair_reverse.data();
  const Vec2* const grad0 = topo.grad0.data();
  // Work of the sub-step just completed (spec §3 energy bookkeeping): force at level n+1 times
  // the synchronised velocity, external force over the drift. A moving clamp's reaction on its
  // particle is −(f_int + f_ext) (the particle does not accelerate); its power at the clamp's
  // constant velocity is the clamps' work. The per-particle powers come from pass 2
  // (w.power); summed here serially in particle order, as dot products of the same numbers,
  // so the sums do not depend on the thread count.
  auto account = [&] {
    double diss = 0.0, hg = 0.0, ext = 0.0, grip = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const SubstepPower& p = w.power[i];
      diss -= p.viscous;
      hg -= p.hourglass;
      ext += p.external;
      if (body.clamped[i]) grip -= w.clamp_power[i];
    }
    body.dissipated += h * diss;
    body.hourglass_work += h * hg;
    body.external_work += h * ext;
    body.clamp_work += h * grip;
  };
  // First half kick and drift of particle i from its v and a into (vh, x).
  auto kick_drift = [&](std::size_t i, Vec2 vi, Vec2 ai, std::span<const Vec2> x,
                        std::span<Vec2> vh_out, std::span<Vec2> x_out) {
    if (body.clamped[i]) {  // held fixed (x = X) or moved at the clamp's velocity
      vh_out[i] = body.clamp_velocity[i];
      x_out[i] = x[i] + h * vh_out[i];
      return;
    }
    vh_out[i] = vi + hh * ai;
    x_out[i] = x[i] + h * vh_out[i];
  };

  using simd::hi;
  using simd::lo;
  using simd::v2d;
  bool swapped = false;  // the current positions are in w.x_next
  exec.run_team(threads, [&](const Team& team) {
    // Without an Eulerian switch pass 2 reads no neighbour's x or v½, so its kick and drift
    // update them in place; the Eulerian pair forces read the neighbours' current x and v½,
    // so the next ones go to second buffers, swapped after the pass.
    std::span<Vec2> x = body.x, vh = w.vhalf;
    std::span<Vec2> xn = eulerian ? std::span<Vec2>(w.x_next) : x;
    std::span<Vec2> vhn = eulerian ? std::span<Vec2>(w.vhalf_next) : vh;
    double* const kappa = w.kappa.data();
    Vec2* const keps_k = w.keps.data();
    SubstepViscous* const visc = w.viscous.data();
    const double* const visc_weight = w.viscous_weight.data();
    const std::uint32_t* const upper = w.upper.data();
    const std::uint32_t* const lower = w.lower.data();
    const Vec2* const X = body.X.data();
    double* const stress_power = w.stress_power.data();
    SubstepParticleMats* const mats = w.mats.data();
    // Raw pointers: the compiler then keeps them in registers across the law's call.
    Mat2* const Fb = body.F.data();
    Mat2* const Pb = body.P.data();
    const double* const V0 = body.V0.data();
    const double* const rho0 = body.rho0.data();
    const double* const hp = topo.h.data();
    const double* const m = body.m.data();
    const std::uint8_t* const clamped = body.clamped.data();
    const Vec2* const clamp_v = body.clamp_velocity.data();
    const Vec2* const fext = w.fext.data();
    const Vec2* const gsum = w.gsum.data();
    Vec2* const a = body.a.data();
    Vec2* const v = body.v.data();
    Vec2* const f_int = body.f_int.data();
    Vec2* const f_av = body.f_av.data();
    Vec2* const f_hg = body.f_hg.data();
    double* const energy = body.e.data();
    const auto [b, e] = team.share(n);
    std::uint32_t lower_run = 0;  // slots with j < i in the rows b..i
    bool uniform_share = true;    // h and ρ0 of the share those of particle 0
    for (std::size_t i = b; i < e; ++i) {
      Vec2 gs;
      w.upper[i] = start[i + 1];
      for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) {
        const std::uint32_t j = index[k];
        if (j > i && w.upper[i] == start[i + 1]) w.upper[i] = k;
        if constexpr (kHourglass) kappa[k] = hourglass_pair_stiffness(body, topo, alpha, i, j, k);
        gs += grad0[k];
      }
      lower_run += w.upper[i] - start[i];
      w.lower[i] = lower_run;
      uniform_share = uniform_share && hp[i] == hp[0] && rho0[i] == rho0[0];
      const simd::Cols Pc = simd::cols(Pb[i]);  // the first sub-step's P_old
      simd::store(mats[i].p_c0, Pc.c0);
      simd::store(mats[i].p_c1, Pc.c1);
      w.gsum[i] = gs;
      w.fext[i] = body.f_fluid[i] + body.m[i] * g;
      body.a[i] = body.clamped[i] ? Vec2{} : (body.f_int[i] + w.fext[i]) / body.m[i];
      kick_drift(i, body.v[i], body.a[i], x, vh, x);
    }
    w.share_info[static_cast<std::size_t>(team.rank())] = {lower_run, uniform_share};
    team.barrier();
    // w.lower[i] from this share's count to the count over rows 0..i: add the lower slots of
    // the shares before it (contiguous in rank order). Only this thread reads its own entries
    // before the next barrier, the others after pass 1.
    std::uint32_t lower_before = 0;
    for (int t = 0; t < team.rank(); ++t)
      lower_before += w.share_info[static_cast<std::size_t>(t)].lower;
    // With one h and one ρ0 (every body built from one spacing and one material) the pair
    // values 0.5 (h_i + h_j) and 0.5 (ρ0_i + ρ0_j) are h and ρ0 exactly: no gathers.
    bool uniform = n > 0;
    for (int t = 0; t < team.size(); ++t)
      uniform = uniform && w.share_info[static_cast<std::size_t>(t)].uniform;
    const double h_all = n > 0 ? hp[0] : 0.0, rho0_all = n > 0 ? rho0[0] : 0.0;
    for (std::size_t i = b; i < e; ++i) {
      w.lower[i] += lower_before;
      if constexpr (kViscous)  // the same expressions as viscous_force_on (artificial_viscosity.h)
        for (std::uint32_t k = upper[i]; k < start[i + 1]; ++k)
          w.viscous_weight[k - w.lower[i]] = viscous_pair_weight(body, topo, i, k);
    }
    for (int step = 0; step < steps; ++step) {
      if constexpr (eulerian) {  // current pairs of the switched particles at the drifted positions
        if (team.leader()) build_eulerian_pairs(body, x);
        team.barrier();
      }
      // Pass 1: F and Ḟ, the viscous pair terms, the law's committing update, stress power,
      // the internal energy, hourglass moment. Two-lane arithmetic (core/simd2.h) with the
      // rounding of the Vec2 / Mat2 forms.
      for (std::size_t i = b; i < e; ++i) {
        simd::Cols Fc, Fdc;
        // A switched particle has no total-Lagrangian pairs left (its loops below are empty):
        // its F comes from its current neighbours.
        const v2d xi = simd::load(x[i]), vi = simd::load(vh[i]);
        const std::uint32_t k0 = start[i], ku = upper[i], k1 = start[i + 1];
        // i's pairs with j > i, once per pair: k − lower[i] in w.viscous (SubstepWorkspace).
        SubstepViscous* const visc_i = visc + (ku - lower[i]);
        const double* const weight_i = visc_weight + (ku - lower[i]);
        for (std::uint32_t k = k0; k < ku; ++k) {
          const v2d gk = simd::load(grad0[k]), gx = lo(gk), gy = hi(gk);
          simd::add_outer(Fc, simd::load(x[index[k]]) - xi, gx, gy);
          simd::add_outer(Fdc, simd::load(vh[index[k]]) - vi, gx, gy);
        }
        for (std::uint32_t k = ku; k < k1; ++k) {
          const std::uint32_t j = index[k];
          const v2d xj = simd::load(x[j]), vj = simd::load(vh[j]);
          const v2d gk = simd::load(grad0[k]), gx = lo(gk), gy = hi(gk);
          simd::add_outer(Fc, xj - xi, gx, gy);
          simd::add_outer(Fdc, vj - vi, gx, gy);
          if constexpr (kViscous) {
            // viscous_force_on's pair term for i; for j it is the exact negative (x_ji =
            // −x_ij and v_ji = −v_ij bit for bit, Π, h, ρ0 and |c| symmetric), the heat the
            // same.
            Vec2 xij, vij;
            simd::store(xij, xi - xj);
            simd::store(vij, vi - vj);
            const double hij = uniform ? h_all : 0.5 * (hp[i] + hp[j]);
            const double rhoij = uniform ? rho0_all : 0.5 * (rho0[i] + rho0[j]);
            const double pi = monaghan_pi(vij, xij, hij, rhoij, c, av_alpha, av_beta);
            Vec2 f;
            double q = 0.0;
            if (pi != 0.0) {
              const double s = pi * weight_i[k - ku] / norm(xij);
              f = s * xij;
              q = -0.5 * s * dot(xij, vij);
            }
            visc_i[k - ku] = {f, q};
          }
        }
        const Mat2 F = simd::mat(Fc);
        Mat2 Fdot = simd::mat(Fdc);
        // The material's F and Ḟ: the kinematic ones above (the hourglass control below
        // keeps the kinematic F) times the map C that keeps F continuous across a switch's
        // topology rebuild (SolidBody::F_rebase); a switched particle's from its current
        // neighbours.
        Mat2 Fm = F, K;
        const bool switched = eulerian && body.eulerian.switched[i];
        if constexpr (eulerian) {
          if (switched) {
            eulerian_motion(body, x, vh, h, i, Fm, Fdot, K);
          } else {
            Fm = F * body.F_rebase[i];
            Fdot = Fdot * body.F_rebase[i];
          }
        }
        SubstepParticleMats& mi = mats[i];
        // Without an Eulerian switch P is body state only at the end of the call (copied
        // from mats after the last sub-step): P_old is the one in mats (the previous
        // sub-step's, or the body's at the first).
        const Mat2 F_old = Fb[i];
        const Mat2 P_old = eulerian ? Pb[i] : simd::mat({simd::load(mi.p_c0), simd::load(mi.p_c1)});
        Fb[i] = Fm;
        const Mat2 P = commit_stress_at(law, body.history, F_old, Fm, h, i);
        if constexpr (eulerian) Pb[i] = P;
        if constexpr (eulerian) w.P_kin[i] = body.kinematic_P(i);
        if (switched) body.eulerian.stress_map[i] = eulerian_stress_map(body, i, K);
        // de/dt = P : Ḟ / ρ0 with P trapezoidal over the sub-step (spec §3).
        stress_power[i] = ddot(0.5 * (P_old + P), Fdot) / (uniform ? rho0_all : rho0[i]);
        // The stress of the TL pair force: P, or P Cᵀ after an Eulerian switch
        // (tl_pair_force.h); pass 2 multiplies it by V0 (the rounding of V0 P).
        const simd::Cols Pk = simd::cols(eulerian ? w.P_kin[i] : P);
        simd::store(mi.p_c0, Pk.c0);
        simd::store(mi.p_c1, Pk.c1);
        if constexpr (kHourglass) {
          // hourglass_moment (hourglass_control.h) with the stored X_ij and κ_ij.
          simd::Cols Gi;
          const v2d Xi = simd::load(X[i]);  // hoisted: the compiler cannot (keps_k may alias)
          for (std::uint32_t k = k0; k < k1; ++k) {
            // X_ij as the set-up formed it (hourglass_control.h), from i's and j's X.
            const v2d Xij = simd::load(X[index[k]]) - Xi, Xx = lo(Xij), Xy = hi(Xij);
            const v2d keps =
                simd::splat(kappa[k]) * (simd::mul(Fc, Xx, Xy) - (simd::load(x[index[k]]) - xi));
            simd::store(keps_k[k], keps);
            simd::add_outer(Gi, keps, Xx, Xy);
          }
          simd::store(mi.g_c0, Gi.c0);
          simd::store(mi.g_c1, Gi.c1);
        }
      }
      if (team.leader() && step > 0) account();  // the previous sub-step's
      team.barrier();
      // Pass 2: forces (stress_force_on, viscous_force_on and hourglass_force_on in one loop
      // over i's pairs, each in its own accumulator), second half kick, internal energy; next
      // kick and drift. The pair terms of i's own side, V0_i P_i g_ij and G_i g_ij, are
      // summed as V0_i P_i Σ_j g_ij and G_i Σ_j g_ij (w.gsum, per call): the same forces
      // at a different rounding (tests/unit/test_solid_substep.cpp).
      const bool more = step + 1 < steps;
      for (std::size_t i = b; i < e; ++i) {
        v2d fs{0.0, 0.0}, grad{0.0, 0.0}, fav{0.0, 0.0};
        double heat = 0.0;
        // Pair k's terms but the viscous one, which the two loops below add.
        // g_ji from the reverse slot in j's row (j is near i, so that row is in cache).
        auto stress_hourglass = [&](std::uint32_t k, std::uint32_t j, std::uint32_t kr) {
          const SubstepParticleMats& mj = mats[j];
          const v2d gr = simd::load(grad0[kr]), gx = lo(gr), gy = hi(gr);
          const v2d vj = simd::splat(V0[j]);
          fs += (vj * simd::load(mj.p_c0)) * gx + (vj * simd::load(mj.p_c1)) * gy;
          if constexpr (kHourglass) {
            grad += simd::load(mj.g_c0) * gx + simd::load(mj.g_c1) * gy;
            grad += simd::load(keps_k[k]) - simd::load(keps_k[kr]);
          }
        };
        const std::uint32_t k0 = start[i], ku = upper[i], k1 = start[i + 1];
        for (std::uint32_t k = k0; k < ku; ++k) {
          const std::uint32_t j = index[k], kr = reverse[k];
          stress_hourglass(k, j, kr);
          if constexpr (kViscous) {
            // j < i: the term j stored for the pair (slot kr of j's row), whose force on i is
            // −f (fav − f rounds as fav + (−f)).
            const SubstepViscous& vt = visc[kr - lower[j]];
            fav -= simd::load(vt.f);
            heat += vt.q;
          }
        }
        const SubstepViscous* const visc_i = visc + (ku - lower[i]);
        for (std::uint32_t k = ku; k < k1; ++k) {
          stress_hourglass(k, index[k], reverse[k]);
          if constexpr (kViscous) {
            fav += simd::load(visc_i[k - ku].f);
            heat += visc_i[k - ku].q;
          }
        }
        const SubstepParticleMats& mi = mats[i];
        const v2d gs = simd::load(gsum[i]), gsx = lo(gs), gsy = hi(gs);
        Vec2 fsv, favv, fhg;
        simd::store(favv, fav);
        const v2d v0i = simd::splat(V0[i]);
        simd::store(fsv,
                    (v0i * simd::load(mi.p_c0)) * gsx + (v0i * simd::load(mi.p_c1)) * gsy - fs);
        if constexpr (kHourglass)
          simd::store(fhg, simd::load(mi.g_c0) * gsx + simd::load(mi.g_c1) * gsy - grad);
        if constexpr (eulerian) {
          Vec2 fse, fve;
          eulerian_force_on(body, x, vh, body.eulerian.stress_map, i, fse, fve, heat);
          fsv += fse;
          favv += fve;
        }
        energy[i] += h * (stress_power[i] + heat / m[i]);
        // Forces, acceleration and velocity are body state only at the end of the call (and
        // read by the Eulerian operators): in between they live in registers and w.power.
        const Vec2 fi = fsv + favv + fhg;
        const Vec2 ai = clamped[i] ? Vec2{} : (fi + fext[i]) / m[i];
        const Vec2 vi = clamped[i] ? clamp_v[i] : vh[i] + hh * ai;
        w.power[i] = {dot(favv, vi), dot(fhg, vi), dot(fext[i], vh[i])};
        if (clamped[i]) w.clamp_power[i] = dot(fi + fext[i], clamp_v[i]);
        if (eulerian || !more) {
          f_av[i] = favv;
          f_hg[i] = fhg;
          f_int[i] = fi;
          a[i] = ai;
          v[i] = vi;
        }
        if (more) kick_drift(i, vi, ai, x, vhn, xn);
      }
      team.barrier();
      if (eulerian && more) {
        std::swap(x, xn);
        std::swap(vh, vhn);
        if (team.leader()) swapped = !swapped;
      }
    }
    if (team.leader() && steps > 0) account();
    // Without an Eulerian switch the last P is in mats (this thread's own entries).
    if constexpr (!eulerian)
      if (steps > 0)
        for (std::size_t i = b; i < e; ++i)
          Pb[i] = simd::mat({simd::load(mats[i].p_c0), simd::load(mats[i].p_c1)});
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
  const bool eulerian = body.eulerian.active;
  if (hourglass && viscous)
    eulerian ? substeps_with<Law, true, true, true>(law, body, steps, h, g, exec)
             : substeps_with<Law, true, true, false>(law, body, steps, h, g, exec);
  else if (hourglass)
    eulerian ? substeps_with<Law, true, false, true>(law, body, steps, h, g, exec)
             : substeps_with<Law, true, false, false>(law, body, steps, h, g, exec);
  else if (viscous)
    eulerian ? substeps_with<Law, false, true, true>(law, body, steps, h, g, exec)
             : substeps_with<Law, false, true, false>(law, body, steps, h, g, exec);
  else
    eulerian ? substeps_with<Law, false, false, true>(law, body, steps, h, g, exec)
             : substeps_with<Law, false, false, false>(law, body, steps, h, g, exec);
}

}  // namespace

void run_elastic_substeps(SolidBody& body, int steps, double h, Vec2 g, const Executor& exec) {
  std::visit([&](const auto& law) { substeps_dispatch(law, body, steps, h, g, exec); },
             body.material.law);
}

}  // namespace slamsph
