#include "solid/elastic_substep.h"

#include <algorithm>
#include <span>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "core/parallel.h"
#include "core/simd2.h"
#include "solid/artificial_viscosity.h"
#include "solid/eulerian_failed_interaction.h"
#include "solid/hourglass_control.h"
#include "solid/materials/st_venant_kirchhoff.h"
#include "solid/stress_update.h"
#include "solid/substep_law_lanes.h"
#include "solid/substep_levels.h"
#include "solid/substep_pair_lanes.h"

namespace slamsph {
namespace {

// Wavefront schedule (see substeps_with): levels of at least this many particles (shorter
// tasks cost more to dispatch than they compute), a block of at most kWavefrontMaxBlock
// sub-steps (the power rows hold n × block records) whose working set, ~(2 block + 3)
// levels of kWavefrontBytes each per particle, fits in kWavefrontCache (half of a core's
// 1 MiB L2 on the machines this was measured on).
constexpr std::size_t kWavefrontMinLevel = 16;
constexpr int kWavefrontMaxBlock = 20;
constexpr std::size_t kWavefrontBytes = 750;
constexpr std::size_t kWavefrontCache = 512 * 1024;
// Levels ahead whose lines are requested (fetch in substeps_with), particles ahead in the
// sums of the powers.
constexpr long kPrefetchLevels = 2;
constexpr std::size_t kPrefetchPowers = 32;

// Sub-steps per block of the wavefront schedule for this call, 0 for the two-pass schedule
// (no Eulerian switch is checked by the caller).
int wavefront_block(SolidBody& body, int steps, SubstepSchedule schedule) {
  const std::size_t n = body.size();
  if (schedule == SubstepSchedule::TwoPass || schedule == SubstepSchedule::Lagged || steps < 1 ||
      n == 0)
    return 0;
  const bool forced = schedule == SubstepSchedule::Wavefront;
  if (!forced && (steps < 2 || n < kSubstepWavefrontParticles)) return 0;
  SubstepLevels& lv = body.substep.levels;
  update_substep_levels(body.topology.pairs, kWavefrontMinLevel, lv);
  if (!lv.ok) return 0;
  if (forced) return std::min(steps, kWavefrontMaxBlock);
  const std::size_t window =
      kWavefrontCache / (std::max<std::size_t>(lv.widest, 1) * kWavefrontBytes);
  const int block = std::min(
      {steps, kWavefrontMaxBlock, static_cast<int>(std::min<std::size_t>(window, 1000) / 2) - 1});
  return block >= 2 ? block : 0;
}

// Level bounds B[0..t] of the chunks of a team of t threads for a block of Q phases: equal
// work (Σ 1 + pairs), every bound then moved down by (Q − 1)/2 levels, since each thread but
// the last also finishes the seam above its chunk (~Q² level-phases, ~Q(Q − 1)/2 more than
// the triangle its chunk leaves out). False if a middle chunk is narrower than 2Q levels
// (its two seams would meet) or a chunk is empty.
bool wavefront_bounds(const SubstepLevels& lv, int t, long Q, std::vector<std::size_t>& B) {
  const std::size_t m = lv.levels();
  const double total = lv.work[m];
  B[0] = 0;
  B[static_cast<std::size_t>(t)] = m;
  for (int r = 1; r < t; ++r) {
    const double goal = total * r / t;
    std::size_t l = static_cast<std::size_t>(
        std::lower_bound(lv.work.begin(), lv.work.end(), goal) - lv.work.begin());
    l -= std::min(l, static_cast<std::size_t>((Q - 1) / 2));
    B[static_cast<std::size_t>(r)] = std::max(l, B[static_cast<std::size_t>(r) - 1] + 1);
  }
  for (int r = 0; r < t; ++r) {
    const std::size_t lo = B[static_cast<std::size_t>(r)], hi = B[static_cast<std::size_t>(r) + 1];
    if (hi <= lo) return false;
    if (r > 0 && r + 1 < t && hi - lo < static_cast<std::size_t>(2 * Q)) return false;
  }
  return true;
}

// The lagged sweep of the lanes (substeps_with): pass 2 of a chunk runs this many chunks of
// kSubstepLaneChunk particles (512 particles, ~0.3 MB of what pass 1 wrote) behind pass 1,
// while what pass 1 wrote is in the core's L2 cache. On the 60 000-particle ring (Hilbert
// order) 90 % of the blocks of eight pair with no particle more than 178 past the block's
// end, 95 % 315, 98 % 786 (the others wait for the barrier).
constexpr std::size_t kLagChunks = 8;

// Particles [first, second) of rank r in a team of t in the lagged sweep: bounds on blocks of
// eight, so that no block of the lanes is shared by two threads.
std::pair<std::size_t, std::size_t> lane_share(std::size_t n, int r, int t) {
  auto bound = [&](int q) {
    return q == t ? n
                  : n * static_cast<std::size_t>(q) / static_cast<std::size_t>(t) & ~std::size_t{7};
  };
  return {bound(r), bound(r + 1)};
}

// The ELL layout's blocks and masks (substep_pair_lanes.h) from the pair rows, and its
// arrays sized: block b of particles [8b, 8b + 8) gets as many slots as its longest row.
void ell_layout(const std::uint32_t* start, const std::uint32_t* index, std::size_t n,
                SubstepEll& e) {
  const std::size_t nb = (n + 7) / 8;
  e.off.resize(nb + 1);
  e.off[0] = 0;
  e.mask.clear();
  for (std::size_t b = 0; b < nb; ++b) {
    std::uint32_t deg[8] = {}, slots = 0;
    for (std::size_t l = 0; l < 8 && 8 * b + l < n; ++l) {
      deg[l] = start[8 * b + l + 1] - start[8 * b + l];
      slots = std::max(slots, deg[l]);
    }
    for (std::uint32_t s = 0; s < slots; ++s) {
      std::uint8_t m = 0;
      for (unsigned l = 0; l < 8; ++l)
        if (deg[l] > s) m = static_cast<std::uint8_t>(m | (1u << l));
      e.mask.push_back(m);
    }
    e.off[b + 1] = e.off[b] + 8 * slots;
  }
  const std::size_t total = e.off[nb];
  e.fav.resize(n);
  e.heat.resize(n);
  for (auto* v : {&e.g_x, &e.g_y, &e.X_x, &e.X_y, &e.kappa, &e.vw, &e.h_pair, &e.rho_pair,
                  &e.g_rev_x, &e.g_rev_y, &e.keps_x, &e.keps_y})
    v->resize(total);
  e.j.resize(total);
  e.rev_pos.resize(total);
  // The slots of the last block's lanes past n: partner the block's first particle (the lanes
  // read its row unmasked; in the lagged sweep another thread may write particle 0's row
  // meanwhile, not this block's).
  if (n % 8 != 0)
    for (std::uint32_t p = e.off[nb - 1]; p < total; ++p)
      if (p % 8 >= n % 8) e.j[p] = static_cast<std::int32_t>(8 * (nb - 1));
  // Per block, the lowest and highest particle its particles pair with, itself included.
  e.reach_lo.resize(nb);
  e.reach_hi.resize(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    const std::uint32_t i0 = static_cast<std::uint32_t>(8 * b);
    const std::uint32_t i1 = static_cast<std::uint32_t>(std::min(n, 8 * b + 8));
    std::uint32_t lo = i0, hi = i1 - 1;
    for (std::uint32_t k = start[i0]; k < start[i1]; ++k) {
      lo = std::min(lo, index[k]);
      hi = std::max(hi, index[k]);
    }
    e.reach_lo[b] = lo;
    e.reach_hi[b] = hi;
  }
}

// kHourglass / kViscous: the material's hourglass control and artificial viscosity are on;
// kEulerian: body.eulerian.active (fixed per call, so the pair loops carry no test for them).
// kLanes: the two-pass schedule with the pair loops in lanes (substep_pair_lanes.h), an
// instance of its own, entered from the scalar one.
template <class Law, bool kHourglass, bool kViscous, bool kEulerian, bool kLanes = false>
void substeps_with(const Law& law, SolidBody& body, int steps, double h, Vec2 g,
                   const Executor& exec, SubstepSchedule schedule, SubstepPairLoop loop) {
  const std::size_t n = body.size();
  const SolidTopology& topo = body.topology;
  const SolidMaterial& mat = body.material;
  SubstepWorkspace& w = body.substep;
  w.resize(n, topo.pairs.index.size());
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
  // (w.power); summed serially in particle order (add_power, one particle's step), as dot
  // products of the same numbers, so the sums do not depend on the thread count.
  // `slot`: where particle i's powers are in `power` (the wavefront's rows are in level
  // order), null for i.
  // One particle's step of those sums (the same operations in either schedule).
  auto add_power = [&](SubstepPower & s, const SubstepPower& p, std::size_t i)
      __attribute__((always_inline)) {
    s.viscous -= p.viscous;
    s.hourglass -= p.hourglass;
    s.external += p.external;
    if (body.clamped[i]) s.clamp -= p.clamp;
  };
  auto step_sums = [&](const SubstepPower* power, const std::uint32_t* slot) {
    SubstepPower s{0.0, 0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < n; ++i) {
      if (slot && i + kPrefetchPowers < n) __builtin_prefetch(&power[slot[i + kPrefetchPowers]]);
      add_power(s, power[slot ? slot[i] : i], i);
    }
    return s;
  };
  auto account = [&](const SubstepPower& s) {
    body.dissipated += h * s.viscous;
    body.hourglass_work += h * s.hourglass;
    body.external_work += h * s.external;
    body.clamp_work += h * s.clamp;
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
  const int threads = exec.threads_for(n, kSubstepParticlesPerThread);
  // Both passes' pair loops in eight lanes (two-pass schedule; the set-up then writes the
  // pair records in the ELL layout too, substep_pair_lanes.h) in their own instance: in this
  // one, a function of the scalar loops' size, GCC keeps inlining the law and the small
  // helpers (with both in one function, 7 % more instructions ran in the scalar loops). The
  // lines above are idempotent. Where the lanes apply they are taken before the wavefront
  // (which runs the scalar loops), whatever the body's size, unless the wavefront is forced:
  // on the 60 000-particle ring (BM_RingSubsteps case 2, main's wavefront against the
  // two-pass schedule with the lanes, 14 alternated rounds under quiet.py, medians) 29.8 →
  // 36.0 M particle-steps/s on 2 threads (per-round ratio 1.18, 13 of 14 rounds ≥ 1.11) and
  // 16.2 → 17.0 on 1 thread (1.03, 0.96-1.16); docs/validation.md §6 "Solid sub-step",
  // session 19. Without AVX-512F, with an Eulerian switch or in calls of fewer than
  // kMinLaneSubsteps sub-steps the wavefront rule is unchanged.
  bool lanes_go = false;
  if constexpr (!kEulerian && !kLanes) {
    const bool lanes_wanted = loop == SubstepPairLoop::Lanes ||
                              (loop == SubstepPairLoop::Auto && steps >= kMinLaneSubsteps);
    lanes_go = lanes_wanted && substep_lanes_avx512_available();
  }
  // Sub-steps per block of the wavefront schedule, 0 for the two-pass one (a forced
  // Wavefront keeps it where it applies, the lanes then run only where it falls back).
  const int block = kEulerian || kLanes || (lanes_go && schedule != SubstepSchedule::Wavefront)
                        ? 0
                        : wavefront_block(body, steps, schedule);
  if constexpr (!kEulerian && !kLanes) {
    if (block == 0 && lanes_go) {
      substeps_with<Law, kHourglass, kViscous, false, true>(
          law, body, steps, h, g, exec,
          schedule == SubstepSchedule::Lagged ? schedule : SubstepSchedule::TwoPass, loop);
      return;
    }
  }
  constexpr bool lanes = kLanes;
  // The lanes' lagged sweep (below): forced, or bodies of kSubstepLaggedParticles or more.
  const bool lagged =
      lanes && (schedule == SubstepSchedule::Lagged ||
                (schedule == SubstepSchedule::Auto && n >= kSubstepLaggedParticles));
  // Power rows: one per sub-step of a wavefront block, or, two-pass schedule, one per thread
  // of the team (see there).
  // The lagged sweep of the lanes (below) keeps one more row.
  w.power.resize(n * static_cast<std::size_t>(block > 0 ? block : lagged ? threads + 1 : threads));
  w.step_sums.resize(static_cast<std::size_t>(steps));
  // The lagged sweep works on copies of the body's fields it streams, on the workspace's huge
  // pages (copied in and back per thread share, per call).
  SubstepStage& stage = w.stage;
  if (lagged) stage.resize(n);
  SubstepEll& ell = w.ell;
  if (lanes) ell_layout(start, index, n, ell);
  // Position of slot 0 of particle i in the ELL layout (slot s at + 8 s).
  auto ell_pos = [&](std::size_t i) -> std::uint32_t {
    return ell.off[i >> 3] + static_cast<std::uint32_t>(i & 7);
  };
  bool swapped = false;  // the current positions are in w.x_next
  int team_size = 1;     // two-pass schedule: the team's threads
  exec.run_team(threads, [&](const Team& team) {
    // Without an Eulerian switch pass 2 reads no neighbour's x or v½, so its kick and drift
    // update them in place; the Eulerian pair forces read the neighbours' current x and v½,
    // so the next ones go to second buffers, swapped after the pass.
    std::span<Vec2> x = lagged ? std::span<Vec2>(stage.x) : std::span<Vec2>(body.x);
    std::span<Vec2> vh = w.vhalf;
    std::span<Vec2> xn = eulerian ? std::span<Vec2>(w.x_next) : x;
    std::span<Vec2> vhn = eulerian ? std::span<Vec2>(w.vhalf_next) : vh;
    SubstepPairRef* const ref = w.ref.data();
    SubstepPairRev* const rev = w.rev.data();
    Vec2* const keps_k = w.keps.data();
    SubstepViscous* const visc = w.viscous.data();
    const std::uint32_t* const upper = w.upper.data();
    double* const stress_power = w.stress_power.data();
    SubstepParticleMats* const mats = w.mats.data();
    // Raw pointers: the compiler then keeps them in registers across the law's call.
    Mat2* const Fb = lagged ? stage.F.data() : body.F.data();
    Mat2* const Pb = lagged ? stage.P.data() : body.P.data();
    const double* const V0 = lagged ? stage.V0.data() : body.V0.data();
    const double* const rho0 = lagged ? stage.rho0.data() : body.rho0.data();
    const double* const hp = topo.h.data();
    const double* const m = lagged ? stage.m.data() : body.m.data();
    const std::uint8_t* const clamped = body.clamped.data();
    const Vec2* const clamp_v = body.clamp_velocity.data();
    const Vec2* const fext = w.fext.data();
    const Vec2* const gsum = w.gsum.data();
    Vec2* const a = body.a.data();
    Vec2* const v = body.v.data();
    Vec2* const f_int = body.f_int.data();
    Vec2* const f_av = body.f_av.data();
    Vec2* const f_hg = body.f_hg.data();
    double* const energy = lagged ? stage.e.data() : body.e.data();
    // The per-particle parts of the sub-step, shared by the two schedules below (the same
    // arithmetic per particle in either, so the same bits). setup: the per-call pair records,
    // Σ_j g_ij, the external force, a and the first kick and drift.
    auto setup = [&](std::size_t i) __attribute__((always_inline)) {
      Vec2 gs;
      w.upper[i] = start[i + 1];
      for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) {
        const std::uint32_t j = index[k];
        if (j > i && w.upper[i] == start[i + 1]) w.upper[i] = k;
        SubstepPairRef& r = ref[k];
        r.g = grad0[k];
        r.X = body.X[j] - body.X[i];
        r.kappa = kHourglass ? hourglass_pair_stiffness(body, topo, alpha, i, j, k) : 0.0;
        // The same expressions as viscous_force_on (artificial_viscosity.h).
        r.viscous_weight = kViscous ? viscous_pair_weight(body, topo, i, k) : 0.0;
        rev[k] = {grad0[reverse[k]], j, reverse[k]};
        gs += grad0[k];
      }
      w.gsum[i] = gs;
      if (lanes) {
        const std::uint32_t pi = ell_pos(i);
        const std::uint32_t slots = (ell.off[(i >> 3) + 1] - ell.off[i >> 3]) / 8;
        for (std::uint32_t s = 0; s < slots; ++s) {
          const std::uint32_t p = pi + 8 * s, k = start[i] + s;
          if (k < start[i + 1]) {
            const std::uint32_t j = index[k];
            const SubstepPairRef& r = ref[k];
            ell.g_x[p] = r.g.x;
            ell.g_y[p] = r.g.y;
            ell.X_x[p] = r.X.x;
            ell.X_y[p] = r.X.y;
            ell.kappa[p] = r.kappa;
            ell.vw[p] = r.viscous_weight;
            // monaghan_pi's h and ρ0 as pass 1 forms them.
            ell.h_pair[p] = 0.5 * (topo.h[i] + topo.h[j]);
            ell.rho_pair[p] = 0.5 * (body.rho0[i] + body.rho0[j]);
            ell.g_rev_x[p] = grad0[reverse[k]].x;
            ell.g_rev_y[p] = grad0[reverse[k]].y;
            ell.j[p] = static_cast<std::int32_t>(j);
            ell.rev_pos[p] = static_cast<std::int32_t>(ell_pos(j) + 8 * (reverse[k] - start[j]));
          } else {  // past i's pairs: masked in the lanes, pointing at valid memory
            ell.g_rev_x[p] = ell.g_rev_y[p] = 0.0;
            ell.g_x[p] = ell.g_y[p] = ell.X_x[p] = ell.X_y[p] = ell.kappa[p] = ell.vw[p] = 0.0;
            ell.h_pair[p] = ell.rho_pair[p] = 0.0;
            ell.j[p] = static_cast<std::int32_t>(i);
            ell.rev_pos[p] = static_cast<std::int32_t>(p);
          }
        }
      }
      w.fext[i] = body.f_fluid[i] + body.m[i] * g;
      body.a[i] = body.clamped[i] ? Vec2{} : (body.f_int[i] + w.fext[i]) / body.m[i];
      kick_drift(i, body.v[i], body.a[i], x, vh, x);
    };
    // Pass 1's part after the pair loops (F and Ḟ by columns): the law, the stress power and
    // V0 P.
    auto pass1_law = [&](std::size_t i, const simd::Cols& Fc, const simd::Cols& Fdc)
        __attribute__((always_inline)) {
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
      const Mat2 F_old = Fb[i], P_old = Pb[i];
      Fb[i] = Fm;
      const Mat2 P = commit_stress_at(law, body.history, F_old, Fm, h, i);
      Pb[i] = P;
      if constexpr (eulerian) w.P_kin[i] = body.kinematic_P(i);
      if (switched) body.eulerian.stress_map[i] = eulerian_stress_map(body, i, K);
      // de/dt = P : Ḟ / ρ0 with P trapezoidal over the sub-step (spec §3).
      stress_power[i] = ddot(0.5 * (P_old + P), Fdot) / rho0[i];
      SubstepParticleMats& mi = mats[i];
      // V0 P of the TL pair force: P, or P Cᵀ after an Eulerian switch (tl_pair_force.h).
      const simd::Cols VP = simd::cols(V0[i] * (eulerian ? w.P_kin[i] : P));
      simd::store(mi.vp_c0, VP.c0);
      simd::store(mi.vp_c1, VP.c1);
    };
    // Pass 1: F and Ḟ, the viscous pair terms, the law's committing update, stress power,
    // the internal energy, hourglass moment. Two-lane arithmetic (core/simd2.h) with the
    // rounding of the Vec2 / Mat2 forms.
    auto pass1 = [&](std::size_t i) __attribute__((always_inline)) {
      simd::Cols Fc, Fdc;
      // A switched particle has no total-Lagrangian pairs left (its loops below are empty):
      // its F comes from its current neighbours.
      const v2d xi = simd::load(x[i]), vi = simd::load(vh[i]);
      const std::uint32_t k0 = start[i], ku = upper[i], k1 = start[i + 1];
      for (std::uint32_t k = k0; k < ku; ++k) {
        const SubstepPairRef& r = ref[k];
        const v2d gk = simd::load(r.g), gx = lo(gk), gy = hi(gk);
        simd::add_outer(Fc, simd::load(x[index[k]]) - xi, gx, gy);
        simd::add_outer(Fdc, simd::load(vh[index[k]]) - vi, gx, gy);
      }
      for (std::uint32_t k = ku; k < k1; ++k) {
        const SubstepPairRef& r = ref[k];
        const std::uint32_t j = index[k];
        const v2d xj = simd::load(x[j]), vj = simd::load(vh[j]);
        const v2d gk = simd::load(r.g), gx = lo(gk), gy = hi(gk);
        simd::add_outer(Fc, xj - xi, gx, gy);
        simd::add_outer(Fdc, vj - vi, gx, gy);
        if constexpr (kViscous) {
          // viscous_force_on's pair term for i; for j it is the exact negative (x_ji =
          // −x_ij and v_ji = −v_ij bit for bit, Π, h, ρ0 and |c| symmetric), the heat the
          // same.
          Vec2 xij, vij;
          simd::store(xij, xi - xj);
          simd::store(vij, vi - vj);
          const double pi = monaghan_pi(vij, xij, 0.5 * (hp[i] + hp[j]), 0.5 * (rho0[i] + rho0[j]),
                                        c, av_alpha, av_beta);
          Vec2 f;
          double q = 0.0;
          if (pi != 0.0) {
            const double s = pi * r.viscous_weight / norm(xij);
            f = s * xij;
            q = -0.5 * s * dot(xij, vij);
          }
          visc[k] = {f, q};
          visc[reverse[k]] = {-f, q};
        }
      }
      pass1_law(i, Fc, Fdc);
      if constexpr (kHourglass) {
        // hourglass_moment (hourglass_control.h) with the stored X_ij and κ_ij.
        simd::Cols Gi;
        for (std::uint32_t k = k0; k < k1; ++k) {
          const SubstepPairRef& r = ref[k];
          const v2d Xij = simd::load(r.X), Xx = lo(Xij), Xy = hi(Xij);
          const v2d keps =
              simd::splat(r.kappa) * (simd::mul(Fc, Xx, Xy) - (simd::load(x[index[k]]) - xi));
          simd::store(keps_k[k], keps);
          simd::add_outer(Gi, keps, Xx, Xy);
        }
        simd::store(mats[i].g_c0, Gi.c0);
        simd::store(mats[i].g_c1, Gi.c1);
      }
    };
    // Pass 2: forces (stress_force_on, viscous_force_on and hourglass_force_on in one loop
    // over i's pairs, each in its own accumulator), second half kick, internal energy; next
    // kick and drift (if `more`); i's powers into pw. The pair terms of i's own side,
    // V0_i P_i g_ij and G_i g_ij, are summed as V0_i P_i Σ_j g_ij and G_i Σ_j g_ij (w.gsum,
    // per call): the same forces at a different rounding (tests/unit/test_solid_substep.cpp).
    // The tail after the pair sums (fs, grad, fav, heat: of the scalar loop below or of the
    // lanes).
    auto tail = [&](std::size_t i, bool more, SubstepPower& pw, v2d fs, v2d grad, v2d fav,
                    double heat) __attribute__((always_inline)) {
      const SubstepParticleMats& mi = mats[i];
      const v2d gs = simd::load(gsum[i]), gsx = lo(gs), gsy = hi(gs);
      // The tail in two-lane arithmetic as well (each lane rounds as the Vec2 form below it
      // replaced: fi = (fs + fav) + fhg, a = (fi + fext) / m, v = v½ + (h/2) a, the dots as
      // x·x + y·y), so that a, v, the powers and the kick and drift are formed once each.
      v2d fsv = simd::load(mi.vp_c0) * gsx + simd::load(mi.vp_c1) * gsy - fs;
      v2d fhg{0.0, 0.0};
      if constexpr (kHourglass) fhg = simd::load(mi.g_c0) * gsx + simd::load(mi.g_c1) * gsy - grad;
      if constexpr (eulerian) {
        Vec2 fse, fve;
        eulerian_force_on(body, x, vh, body.eulerian.stress_map, i, fse, fve, heat);
        fsv += simd::load(fse);
        fav += simd::load(fve);
      }
      energy[i] += h * (stress_power[i] + heat / m[i]);
      // Forces, acceleration and velocity are body state only at the end of the call (and
      // read by the Eulerian operators): in between they live in registers and w.power.
      const v2d fi = fsv + fav + fhg;
      const v2d fe = simd::load(fext[i]), vhi = simd::load(vh[i]);
      const bool held = clamped[i];
      const v2d ai = held ? v2d{0.0, 0.0} : (fi + fe) / simd::splat(m[i]);
      const v2d vi = held ? simd::load(clamp_v[i]) : vhi + simd::splat(hh) * ai;
      auto dot2 = [](v2d p) { return p[0] + p[1]; };
      pw = {dot2(fav * vi), dot2(fhg * vi), dot2(fe * vhi), held ? dot2((fi + fe) * vi) : 0.0};
      if (eulerian || !more) {
        simd::store(f_av[i], fav);
        simd::store(f_hg[i], fhg);
        simd::store(f_int[i], fi);
        simd::store(a[i], ai);
        simd::store(v[i], vi);
      }
      if (more) {
        // kick_drift: a clamped particle at the clamp's velocity (vi), others v½ = v + (h/2) a.
        const v2d vn = held ? vi : vi + simd::splat(hh) * ai;
        simd::store(vhn[i], vn);
        simd::store(xn[i], simd::load(x[i]) + simd::splat(h) * vn);
      }
    };
    auto pass2 = [&](std::size_t i, bool more, SubstepPower& pw) __attribute__((always_inline)) {
      v2d fs{0.0, 0.0}, grad{0.0, 0.0}, fav{0.0, 0.0};
      double heat = 0.0;
      for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) {
        const SubstepPairRev& r = rev[k];
        const SubstepParticleMats& mj = mats[r.j];
        const v2d gr = simd::load(r.g_rev), gx = lo(gr), gy = hi(gr);
        fs += simd::load(mj.vp_c0) * gx + simd::load(mj.vp_c1) * gy;
        if constexpr (kViscous) {
          fav += simd::load(visc[k].f);
          heat += visc[k].q;
        }
        if constexpr (kHourglass) {
          grad += simd::load(mj.g_c0) * gx + simd::load(mj.g_c1) * gy;
          grad += simd::load(keps_k[k]) - simd::load(keps_k[r.reverse]);
        }
      }
      tail(i, more, pw, fs, grad, fav, heat);
    };
    // Pass 2 of particles [i0, i1) in lanes: the pair sums of a chunk, then the tails.
    const SubstepLaneData lane_data{
        ell.off.data(),     ell.mask.data(),   ell.g_rev_x.data(),
        ell.g_rev_y.data(), ell.j.data(),      ell.rev_pos.data(),
        ell.keps_x.data(),  ell.keps_y.data(), reinterpret_cast<const double*>(mats),
        kHourglass};
    SubstepLaneSums sums;
    // Pass 1 of particles [i0, i1) in lanes: the pair loops of a chunk, then per particle the
    // law, the stress power, V0 P and G.
    const SubstepLane1Data lane1_data{ell.off.data(),
                                      ell.mask.data(),
                                      ell.g_x.data(),
                                      ell.g_y.data(),
                                      ell.X_x.data(),
                                      ell.X_y.data(),
                                      ell.kappa.data(),
                                      ell.vw.data(),
                                      ell.h_pair.data(),
                                      ell.rho_pair.data(),
                                      ell.j.data(),
                                      ell.rev_pos.data(),
                                      reinterpret_cast<const double*>(x.data()),
                                      reinterpret_cast<const double*>(vh.data()),
                                      c,
                                      av_alpha,
                                      av_beta,
                                      ell.keps_x.data(),
                                      ell.keps_y.data(),
                                      kHourglass,
                                      kViscous};
    SubstepLane1Sums sums1;
    // SVK: the law, the stress power and V0 P in the lanes too (substep_law_lanes.h, session
    // 19); other laws per particle (pass1_law).
    constexpr bool svk_lanes = std::is_same_v<Law, StVenantKirchhoff> && !kEulerian;
    SubstepSvkLaneData svk_data{0.0,
                                0.0,
                                V0,
                                rho0,
                                reinterpret_cast<double*>(Fb),
                                reinterpret_cast<double*>(Pb),
                                stress_power,
                                reinterpret_cast<double*>(mats)};
    if constexpr (svk_lanes) {
      svk_data.lambda = law.parameters().lambda;
      svk_data.mu = law.parameters().mu;
    }
    auto pass1_lanes = [&](std::size_t base, std::size_t i0, std::size_t i1) {
      substep_lanes_avx512_pass1(lane1_data, base, i0, i1, sums1);
      if constexpr (svk_lanes) substep_lanes_avx512_svk(svk_data, base, i0, i1, sums1);
      for (std::size_t i = i0; i < i1; ++i) {
        const std::size_t o = i - base;
        if constexpr (!svk_lanes) {
          // Columns: c0 = (xx, yx), c1 = (xy, yy).
          const simd::Cols Fc{v2d{sums1.F[0][o], sums1.F[2][o]}, v2d{sums1.F[1][o], sums1.F[3][o]}};
          const simd::Cols Fdc{v2d{sums1.Fd[0][o], sums1.Fd[2][o]},
                               v2d{sums1.Fd[1][o], sums1.Fd[3][o]}};
          pass1_law(i, Fc, Fdc);
        }
        if constexpr (kViscous) {
          ell.fav[i] = Vec2{sums1.fav_x[o], sums1.fav_y[o]};
          ell.heat[i] = sums1.heat[o];
        }
        if constexpr (kHourglass) {
          mats[i].g_c0 = Vec2{sums1.G[0][o], sums1.G[2][o]};
          mats[i].g_c1 = Vec2{sums1.G[1][o], sums1.G[3][o]};
        }
      }
    };
    auto pass2_lanes = [&](std::size_t base, std::size_t i0, std::size_t i1, bool more,
                           SubstepPower* row) {
      substep_lanes_avx512_pass2(lane_data, base, i0, i1, sums);
      for (std::size_t i = i0; i < i1; ++i) {
        const std::size_t o = i - base;
        // The viscous sums come from pass 1's lanes (zero without viscosity).
        tail(i, more, row[i], v2d{sums.fs_x[o], sums.fs_y[o]}, v2d{sums.grad_x[o], sums.grad_y[o]},
             kViscous ? simd::load(ell.fav[i]) : v2d{0.0, 0.0}, kViscous ? ell.heat[i] : 0.0);
      }
    };
    // The lanes' schedule (session 20): per sub-step one sweep over the team's share, pass 1
    // chunk by chunk and pass 2 of each chunk kLagChunks chunks behind it, for the blocks of
    // eight whose pairs all lie in the share and in the chunks pass 1 has done (the others,
    // a few per cent, after a barrier), so that pass 2 reads what pass 1 wrote (V0 P, G, κ ε,
    // the viscous sums, x and v½) from the core's cache instead of memory. Pass 2 of a
    // particle needs pass 1 of its neighbours (their V0 P, G and κ ε) and overwrites its x and
    // v½, which their pass 1 reads, so it may run exactly when theirs is done; nothing reads
    // its results before the next sub-step's pass 1, after the second barrier. The powers'
    // chain in particle order (see the two-pass schedule below) is one sub-step later here:
    // thread r continues that of sub-step s − 1 − r during sub-step s, so t + 1 rows.
    auto lagged_sweep = [&](const Team& team) {
      const int rank = team.rank(), t = team.size();
      if (team.leader()) team_size = t;
      const auto [b, e] = lane_share(n, rank, t);
      for (std::size_t i = b; i < e; ++i) {
        stage.x[i] = body.x[i];
        stage.F[i] = body.F[i];
        stage.P[i] = body.P[i];
        stage.e[i] = body.e[i];
        stage.m[i] = body.m[i];
        stage.V0[i] = body.V0[i];
        stage.rho0[i] = body.rho0[i];
      }
      for (std::size_t i = b; i < e; ++i) setup(i);
      team.barrier();
      const std::size_t rows = static_cast<std::size_t>(t) + 1;
      const std::size_t lag = kLagChunks * kSubstepLaneChunk;
      const std::uint32_t* const reach_lo = ell.reach_lo.data();
      const std::uint32_t* const reach_hi = ell.reach_hi.data();
      // Block q (its first particle) is done in the sweep: its pairs lie in [b, the end of
      // pass 1 when the sweep reaches it).
      auto in_sweep = [&](std::size_t q) {
        const std::size_t frontier =
            std::min(e, q - (q - b) % kSubstepLaneChunk + lag + kSubstepLaneChunk);
        return reach_lo[q >> 3] >= b && reach_hi[q >> 3] < frontier;
      };
      for (int step = 0; step < steps; ++step) {
        const bool more = step + 1 < steps;
        SubstepPower* const row = w.power.data() + static_cast<std::size_t>(step) % rows * n;
        const int s = step - 1 - rank;  // the sub-step whose chain this thread continues
        const SubstepPower* const sum_row =
            s >= 0 ? w.power.data() + static_cast<std::size_t>(s) % rows * n : nullptr;
        SubstepPower acc{0.0, 0.0, 0.0, 0.0};
        if (s >= 0 && rank > 0) acc = w.step_sums[static_cast<std::size_t>(s)];
        // Pass 2 of the chunk at c0 (runs of blocks done in the sweep), then the chain.
        auto pass2_chunk = [&](std::size_t c0) {
          const std::size_t c1 = std::min(e, c0 + kSubstepLaneChunk);
          std::size_t run = c0;
          for (std::size_t q = c0; q < c1; q += 8)
            if (!in_sweep(q)) {
              if (run < q) pass2_lanes(run, run, q, more, row);
              run = q + 8;
            }
          if (run < c1) pass2_lanes(run, run, c1, more, row);
          if (sum_row)
            for (std::size_t i = c0; i < c1; ++i) add_power(acc, sum_row[i], i);
        };
        std::size_t c2 = b;  // the next chunk of pass 2
        for (std::size_t c = b; c < e; c += kSubstepLaneChunk) {
          pass1_lanes(c, c, std::min(e, c + kSubstepLaneChunk));
          if (c - b >= lag) {
            pass2_chunk(c2);
            c2 += kSubstepLaneChunk;
          }
        }
        for (; c2 < e; c2 += kSubstepLaneChunk) pass2_chunk(c2);
        team.barrier();
        // The blocks left out of the sweep, consecutive ones together (up to a chunk).
        for (std::size_t q = b; q < e;) {
          if (in_sweep(q)) {
            q += 8;
            continue;
          }
          std::size_t q1 = std::min(e, q + 8);
          while (q1 < e && q1 - q < kSubstepLaneChunk && !in_sweep(q1)) q1 = std::min(e, q1 + 8);
          pass2_lanes(q, q, q1, more, row);
          q = q1;
        }
        if (s >= 0) w.step_sums[static_cast<std::size_t>(s)] = acc;
        team.barrier();
      }
      for (std::size_t i = b; i < e; ++i) {  // the share's own entries, after the last barrier
        body.x[i] = stage.x[i];
        body.F[i] = stage.F[i];
        body.P[i] = stage.P[i];
        body.e[i] = stage.e[i];
      }
    };
    if (lagged) {
      lagged_sweep(team);
      return;
    }
    if (block == 0) {
      // Two passes over the team's share per sub-step, a barrier after each. The sums of the
      // powers run in particle order, a serial chain of n adds per sub-step; they are folded
      // into pass 2's loop, each thread adding its own share's records (in its cache) to the
      // chain that the thread before it has carried to its share's start: thread r continues
      // the chain of sub-step s − r during pass 2 of s, from the carry w.step_sums[s − r] left
      // by thread r − 1 (at pass 2 of s − 1, before the barrier), reading row (s − r) mod t of
      // the powers (t: the team's threads; row s mod t is written at s). What the team has
      // not reached by the last sub-step (thread r's last r sub-steps) is finished after the
      // region. Until session 16 the leader summed the whole row beside its pass
      // 1, reading the other threads' records while they waited at the barrier.
      const auto [b, e] = team.share(n);
      const int rank = team.rank(), t = team.size();
      if (team.leader()) team_size = t;
      for (std::size_t i = b; i < e; ++i) setup(i);
      team.barrier();
      // kLanes: both passes' pair loops in the lanes, chunk by chunk (pass 2: then the
      // chunk's tails and `after`, in particle order).
      auto sub_steps = [&]() {
        auto pass2_share = [&](bool more, SubstepPower* row, auto&& after)
            __attribute__((always_inline)) {
          if constexpr (kLanes) {
            for (std::size_t c = b & ~std::size_t{7}; c < e; c += kSubstepLaneChunk) {
              const std::size_t i0 = std::max(b, c), i1 = std::min(e, c + kSubstepLaneChunk);
              pass2_lanes(c, i0, i1, more, row);
              for (std::size_t i = i0; i < i1; ++i) after(i);
            }
          } else {
            for (std::size_t i = b; i < e; ++i) {
              pass2(i, more, row[i]);
              after(i);
            }
          }
        };
        for (int step = 0; step < steps; ++step) {
          // The current pairs of the switched particles at the drifted positions.
          if constexpr (eulerian) {
            if (team.leader()) build_eulerian_pairs(body, x);
            team.barrier();
          }
          if constexpr (kLanes) {
            for (std::size_t c = b & ~std::size_t{7}; c < e; c += kSubstepLaneChunk)
              pass1_lanes(c, std::max(b, c), std::min(e, c + kSubstepLaneChunk));
          } else {
            for (std::size_t i = b; i < e; ++i) pass1(i);
          }
          team.barrier();
          const bool more = step + 1 < steps;
          SubstepPower* const row = w.power.data() + static_cast<std::size_t>(step % t) * n;
          const int s = step - rank;  // the sub-step whose chain this thread continues
          if (s >= 0) {
            const SubstepPower* const sum_row =
                w.power.data() + static_cast<std::size_t>(s % t) * n;
            SubstepPower& carry = w.step_sums[static_cast<std::size_t>(s)];
            SubstepPower acc = rank == 0 ? SubstepPower{0.0, 0.0, 0.0, 0.0} : carry;
            pass2_share(more, row, [&](std::size_t i) { add_power(acc, sum_row[i], i); });
            carry = acc;
          } else {
            pass2_share(more, row, [](std::size_t) {});
          }
          team.barrier();
          if (eulerian && more) {
            std::swap(x, xn);
            std::swap(vh, vhn);
            if (team.leader()) swapped = !swapped;
          }
        }
      };
      sub_steps();
      return;
    }
    if constexpr (!kLanes) {
      // Wavefront schedule (substep_levels.h; docs/validation.md "Solid sub-step"): the
      // sub-steps in blocks of `block`, each block a sequence of Q phases (the set-up in the
      // first block, then pass 1 and pass 2 of each sub-step). Phase q of level l needs phase
      // q - 1 of levels l - 1, l and l + 1 (pass 1 reads the neighbours' x and v½ of the last
      // pass 2; pass 2 reads their V0 P, G, κ ε and viscous terms of pass 1 and overwrites x
      // and v½ in place, which those neighbours' pass 1 has read) and nothing else, so phase q
      // of level l may run once phase q - 1 of levels l - 1 .. l + 1 is done and before phase
      // q + 1 of any of them. Each thread runs the tasks (l, q) of its chunk of levels
      // [lo, hi) that depend on its chunk only (l + q < hi unless the last chunk, l − q ≥ lo
      // unless the first), in order of l + q then q: at any moment the working set is ~Q
      // levels, which stay in the core's cache over the block's sub-steps instead of the whole
      // body being streamed twice per sub-step. After a barrier each thread but the last
      // finishes the seam at its chunk's upper end (levels [hi − q, hi + q) of phase q), which
      // needs both chunks. Each particle's arithmetic is that of the two-pass schedule; the
      // powers of the energy bookkeeping go to one row per sub-step and are summed in particle
      // order after the block, so nothing depends on the schedule or the thread count.
      const std::uint32_t* const order = w.levels.order.data();
      const std::uint32_t* const lstart = w.levels.start.data();
      const long m_lv = static_cast<long>(w.levels.levels());
      const int rank = team.rank(), t = team.size();
      std::vector<std::size_t> B(static_cast<std::size_t>(t) + 1);
      for (int s0 = 0; s0 < steps; s0 += block) {
        const int s1 = std::min(steps, s0 + block);
        const int first = s0 == 0 ? 1 : 0;  // the set-up is phase 0 of the first block
        const long Q = 2 * (s1 - s0) + first;
        auto run = [&](long l, long q) __attribute__((always_inline)) {
          const std::uint32_t* p = order + lstart[l];
          const std::uint32_t* const pe = order + lstart[l + 1];
          if (q < first) {
            for (; p != pe; ++p) setup(*p);
            return;
          }
          const long qq = q - first;
          const int step = s0 + static_cast<int>(qq / 2);
          if (qq % 2 == 0) {
            for (; p != pe; ++p) pass1(*p);
            return;
          }
          const bool more = step + 1 < steps;
          SubstepPower* const row = w.power.data() + static_cast<std::size_t>(step - s0) * n;
          for (; p != pe; ++p) pass2(*p, more, row[p - order]);
        };
        if (!wavefront_bounds(w.levels, t, Q, B)) {
          // A chunk too narrow for its seams (a short body on several threads): phase by phase,
          // each thread a contiguous share of the levels, a barrier after each phase.
          const long lo = m_lv * rank / t, hi = m_lv * (rank + 1) / t;
          for (long q = 0; q < Q; ++q) {
            for (long l = lo; l < hi; ++l) run(l, q);
            team.barrier();
          }
        } else {
          // Level l's data is read from memory for the block's first phase of l, in an order
          // the hardware prefetchers do not follow (each level is ~2 × layers runs of the stored
          // order): the lines are requested ahead.
          auto fetch = [&](long l) {
            auto lines = [](const void* b, const void* e) {
              for (const char* c = static_cast<const char*>(b); c < static_cast<const char*>(e);
                   c += 64)
                __builtin_prefetch(c);
            };
            for (const std::uint32_t* p = order + lstart[l]; p != order + lstart[l + 1]; ++p) {
              const std::uint32_t i = *p, k0 = start[i], k1 = start[i + 1];
              __builtin_prefetch(&x[i]);
              __builtin_prefetch(&vh[i]);
              __builtin_prefetch(&Fb[i]);
              __builtin_prefetch(&Pb[i]);
              __builtin_prefetch(&mats[i]);
              __builtin_prefetch(&mats[i].g_c1);
              __builtin_prefetch(&stress_power[i]);
              __builtin_prefetch(&energy[i]);
              __builtin_prefetch(&gsum[i]);
              __builtin_prefetch(&fext[i]);
              __builtin_prefetch(&m[i]);
              __builtin_prefetch(&V0[i]);
              __builtin_prefetch(&rho0[i]);
              __builtin_prefetch(&hp[i]);
              __builtin_prefetch(&upper[i]);
              __builtin_prefetch(&start[i]);
              for (const auto& hv : body.history.values) __builtin_prefetch(&hv[i]);
              lines(ref + k0, ref + k1);
              lines(rev + k0, rev + k1);
              lines(keps_k + k0, keps_k + k1);
              lines(visc + k0, visc + k1);
              lines(index + k0, index + k1);
            }
          };
          const long lo = static_cast<long>(B[rank]), hi = static_cast<long>(B[rank + 1]);
          const bool left = rank > 0, right = rank + 1 < t;
          const long T_end = right ? hi : hi + Q - 1;
          for (long T = lo; T < T_end; ++T) {
            if (T + kPrefetchLevels < hi) fetch(T + kPrefetchLevels);
            long qmax = std::min(Q - 1, left ? (T - lo) / 2 : T - lo);
            for (long q = std::max(0L, T - hi + 1); q <= qmax; ++q) run(T - q, q);
          }
          team.barrier();
          if (right)
            for (long q = 1; q < Q; ++q)
              for (long l = std::max(0L, hi - q); l < std::min(m_lv, hi + q); ++l) run(l, q);
          team.barrier();
        }
        // The block's powers summed in particle order, its sub-steps shared among the threads.
        const int nb = s1 - s0;
        for (int k = nb * rank / t; k < nb * (rank + 1) / t; ++k)
          w.step_sums[static_cast<std::size_t>(s0 + k)] =
              step_sums(w.power.data() + static_cast<std::size_t>(k) * n, w.levels.slot.data());
        if (s1 < steps) team.barrier();  // before the next block overwrites the rows
      }
    }
  });
  if (lagged) {
    // The lagged sweep's chains the team did not reach: sub-step s, thread r's share for
    // s + 1 + r ≥ steps (row s mod (t + 1)), in order of s, then r.
    const int t = team_size;
    const std::size_t rows = static_cast<std::size_t>(t) + 1;
    for (int s = std::max(0, steps - t); s < steps; ++s) {
      SubstepPower& acc = w.step_sums[static_cast<std::size_t>(s)];
      const int r0 = std::max(0, steps - 1 - s);
      if (r0 == 0) acc = SubstepPower{0.0, 0.0, 0.0, 0.0};
      const SubstepPower* const row = w.power.data() + static_cast<std::size_t>(s) % rows * n;
      for (int r = r0; r < t; ++r) {
        const auto [i0, i1] = lane_share(n, r, t);
        for (std::size_t i = i0; i < i1; ++i) add_power(acc, row[i], i);
      }
    }
  } else if (block == 0) {
    // The two-pass schedule's chains the team did not reach: sub-step s, thread r's share
    // for s + r ≥ steps (row s mod t still holds s's powers), in order of s, then r.
    const int t = team_size;
    for (int s = std::max(0, steps - t + 1); s < steps; ++s) {
      SubstepPower& acc = w.step_sums[static_cast<std::size_t>(s)];
      const SubstepPower* const row = w.power.data() + static_cast<std::size_t>(s % t) * n;
      for (int r = steps - s; r < t; ++r) {
        const std::size_t i0 = n * static_cast<std::size_t>(r) / static_cast<std::size_t>(t);
        const std::size_t i1 = n * static_cast<std::size_t>(r + 1) / static_cast<std::size_t>(t);
        for (std::size_t i = i0; i < i1; ++i) add_power(acc, row[i], i);
      }
    }
  }
  for (int s = 0; s < steps; ++s)  // the sums of the sub-steps, in order
    account(w.step_sums[static_cast<std::size_t>(s)]);
  if (swapped) std::swap(body.x, w.x_next);
  body.history.updates += static_cast<std::uint64_t>(steps);
}

template <class Law>
void substeps_dispatch(const Law& law, SolidBody& body, int steps, double h, Vec2 g,
                       const Executor& exec, SubstepSchedule schedule, SubstepPairLoop loop) {
  const SolidMaterial& mat = body.material;
  const bool hourglass = mat.hourglass != 0.0;
  const bool viscous = !(mat.av_alpha == 0.0 && mat.av_beta == 0.0);
  const bool eulerian = body.eulerian.active;
  if (hourglass && viscous)
    eulerian ? substeps_with<Law, true, true, true>(law, body, steps, h, g, exec, schedule, loop)
             : substeps_with<Law, true, true, false>(law, body, steps, h, g, exec, schedule, loop);
  else if (hourglass)
    eulerian ? substeps_with<Law, true, false, true>(law, body, steps, h, g, exec, schedule, loop)
             : substeps_with<Law, true, false, false>(law, body, steps, h, g, exec, schedule, loop);
  else if (viscous)
    eulerian ? substeps_with<Law, false, true, true>(law, body, steps, h, g, exec, schedule, loop)
             : substeps_with<Law, false, true, false>(law, body, steps, h, g, exec, schedule, loop);
  else
    eulerian
        ? substeps_with<Law, false, false, true>(law, body, steps, h, g, exec, schedule, loop)
        : substeps_with<Law, false, false, false>(law, body, steps, h, g, exec, schedule, loop);
}

}  // namespace

void run_elastic_substeps(SolidBody& body, int steps, double h, Vec2 g, const Executor& exec,
                          SubstepSchedule schedule, SubstepPairLoop loop) {
  std::visit(
      [&](const auto& law) { substeps_dispatch(law, body, steps, h, g, exec, schedule, loop); },
      body.material.law);
}

}  // namespace slamsph
