#include "app/fsi_stepper.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/parallel.h"
#include "coupling/contact_rates.h"
#include "coupling/leak_counter.h"
#include "coupling/virtual_pressure.h"
#include "coupling/wall_acceleration.h"
#include "fluid/gsph_fluid_rates.h"
#include "fluid/kick_lanes.h"
#include "solid/elastic_substep.h"

namespace slamsph {

FsiStepper::FsiStepper(const FsiParams& params, FsiSystem system, const Executor& exec)
    : prm_(params),
      sys_(std::move(system)),
      exec_(exec),
      dual_(params.dual_time_stepping, params.fluid_force_correction) {
  const double skin = prm_.neighbour_skin * sys_.kernel_c.support();
  lists_ =
      std::make_unique<InteractionLists>(sys_.kernel_f.support(), sys_.kernel_c.support(), skin);
  loads_.assign(sys_.bodies.size(), BodyLoad{});
  averages_.assign(sys_.bodies.size(), SubstepAverage{});
  received_.assign(sys_.bodies.size(), Vec2{});
  PhaseTimes setup;  // the initial rates are set-up, not a step's phases
  PhaseClock clock;
  evaluate_rates(clock, setup);
  fixed_gathered_ = false;  // the first step's advance zeroes a fixed body's v and a
}

// The order of the operators is documented in the header; do not reorder.
bool FsiStepper::evaluate_rates(PhaseClock& clock, PhaseTimes& t, RatePass pass,
                                bool fluid_pass_done, const AfterFluidPass* then) {
  FluidParticles& fluid = sys_.fluid;
  ContactParticles& contact = sys_.contact;
  bool fused = false;
  // A failed set that grew re-plans the ghosts around it (coupling/failure_zone_ghosts.h):
  // the contact set changes size, so the fluid–contact lists are rebuilt.
  const bool replanned = replan_around_failures(sys_.layout, sys_.bodies);
  if (replanned) init_contact_particles(contact, sys_.layout);
  // A fixed body's entries, once gathered inside a step, hold until a re-plan: most of the
  // contact set of a tank case is its walls (gather_body_state).
  gather_body_state(contact, sys_.layout, sys_.bodies, !fixed_gathered_ || replanned);
  fixed_gathered_ = true;
  if (replanned || fixed_contact_.size() != contact.size()) {
    fixed_contact_.resize(contact.size());
    for (std::size_t c = 0; c < contact.size(); ++c)
      fixed_contact_[c] = sys_.bodies[contact.body[c]].kind == BodyKind::RigidFixed;
  }
  for (std::size_t b = 0; b < sys_.bodies.size(); ++b)
    apply_substep_average(contact, sys_.layout, b, averages_[b]);
  for (std::size_t b = 0; b < sys_.bodies.size(); ++b)
    apply_wall_acceleration(contact, sys_.layout, b, sys_.bodies[b], prm_.wall_acceleration);
  clock.lap(t.contact);
  // A rebuild reorders the fluid and its pairs: a water pass done beside the bodies' sub-steps
  // on the old lists is done again (its sums would come in another order).
  const bool rebuilt = lists_->update(fluid, contact, exec_, replanned, found_.fluid_d2);
  found_.fluid_d2 = -1.0;  // for these positions and these lists only
  if (rebuilt && fluid_pass_done) {
    fluid_pass_done = false;
    ++beside_redone_;
  }
  clock.lap(t.neighbour_lists);
  const ContactParams cp{sys_.eos.c0,
                         prm_.limiter_omega,
                         prm_.viscosity,
                         prm_.gravity,
                         prm_.cavitation_pressure,
                         prm_.hydrostatic_correction,
                         prm_.contact_barrier ? sys_.eos.stiffness() : 0.0};
  if (fluid.size() > 0) {
    // Step 3; the fixed entries' part was done beside the sub-steps if the pass was. An
    // eligible advance done in turn is charged that part's time too (BesideChoice compares
    // like with like).
    double fixed_seconds = 0.0;
    if (fluid_pass_done && fixed_virtual_beside_) {
      virtual_state(VirtualSubset::Moving);
    } else if (pending_) {
      const auto start = std::chrono::steady_clock::now();
      virtual_state(VirtualSubset::Fixed);
      fixed_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      virtual_state(VirtualSubset::Moving);
    } else {
      virtual_state(VirtualSubset::All);
    }
    fixed_virtual_beside_ = false;
    // Steps 5 and 6 read the water's x, v, rho, p, which step 4 does not write, and write only
    // the contact set and their own terms: before step 4 when `then` changes v, rho, p in it.
    fused = then != nullptr && !fluid_pass_done && pass == RatePass::Both;
    if (fused) contact_before_pass(cp);
    clock.lap(t.contact);
    const auto start = std::chrono::steady_clock::now();
    if (!fluid_pass_done) fluid_pass(pass, fused ? then : nullptr);
    if (pending_) {
      pending_->record(
          pending_beside_,
          pending_seconds_ + fixed_seconds +
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      pending_ = nullptr;
    }
    clock.lap(t.fluid_rates);
    if (!fused) {
      add_contact_to_fluid(fluid, contact, lists_->fc(), sys_.kernel_c, cp, exec_, pass,
                           &contact_pairs_);
      if (pass != RatePass::Continuity)  // the pair forces just computed, each pair once
        compute_contact_reaction(contact, fluid, lists_->cf(), sys_.kernel_c, cp, exec_,
                                 &contact_pairs_, &lists_->cf_in_fc());
    }
    // The flags belong to the end-of-step positions (the momentum pass sees mid-step ones).
    if (pass != RatePass::Momentum)
      leaked_ = update_leak_flags(fluid, contact, lists_->fc(), exec_);
  }
  if (pass == RatePass::Continuity) {  // the bodies keep the force of the momentum pass
    clock.lap(t.contact);
    return fused;
  }
  scatter_contact_forces(contact, sys_.layout, sys_.bodies);
  for (std::size_t b = 0; b < sys_.bodies.size(); ++b) {
    BodyLoad load;
    for (const Vec2& f : sys_.bodies[b].f_fluid) load.total += f;
    loads_[b] = load;
  }
  // Summed in a register over each run of one body's contact particles, in the same order
  // as one at a time through loads_ (that was a store-to-load chain: 2 % of the main
  // thread's samples in the 3 200-particle dam break on 2 threads, all of it serial).
  for (std::size_t c = 0; c < contact.size();) {
    const auto b = contact.body[c];
    Vec2 viscous = loads_[b].viscous;
    for (; c < contact.size() && contact.body[c] == b; ++c) viscous += contact.force_viscous[c];
    loads_[b].viscous = viscous;
  }
  clock.lap(t.contact);
  return fused;
}

void FsiStepper::contact_before_pass(const ContactParams& cp) {
  FluidParticles& fluid = sys_.fluid;
  if (contact_a_.size() != fluid.size()) {
    contact_a_.assign(fluid.size(), Vec2{-0.0, -0.0});
    contact_drho_.assign(fluid.size(), -0.0);
  }
  // add_contact_to_fluid adds to a and drho of the particles with contact partners: here to
  // the -0 entries of the side arrays (the last sweep in step 4 sets them back to -0).
  fluid.a.swap(contact_a_);
  fluid.drho.swap(contact_drho_);
  add_contact_to_fluid(fluid, sys_.contact, lists_->fc(), sys_.kernel_c, cp, exec_, RatePass::Both,
                       &contact_pairs_);
  fluid.a.swap(contact_a_);
  fluid.drho.swap(contact_drho_);
  compute_contact_reaction(sys_.contact, fluid, lists_->cf(), sys_.kernel_c, cp, exec_,
                           &contact_pairs_, &lists_->cf_in_fc());
}

void FsiStepper::virtual_state(VirtualSubset subset) {
  compute_virtual_state(sys_.contact, sys_.fluid, lists_->cf(), sys_.kernel_c, sys_.eos,
                        prm_.gravity, exec_, subset, &fixed_contact_);
}

void FsiStepper::fluid_pass(RatePass pass, const AfterFluidPass* then) {
  const GsphParams gp{sys_.eos.c0, prm_.limiter_omega, prm_.viscosity, prm_.gravity,
                      prm_.hydrostatic_correction};
  if (then) band_maxima_.assign(std::max<std::size_t>(lists_->ff().bands(), 1), {});
  compute_gsph_fluid_rates(sys_.fluid, lists_->ff(), sys_.kernel_f, gp, exec_, pass, PairLoop::Auto,
                           then);
}

bool FsiStepper::bodies_beside_fluid_pass() const {
  const std::size_t nf = sys_.fluid.size();
  if (exec_.threads() < 2 || nf == 0 || dual_.bodies_share_step(nf)) return false;
  bool elastic = false;
  for (const SolidBody& b : sys_.bodies) {
    if (!b.is_elastic()) continue;
    if (exec_.threads_for(b.size(), kSubstepParticlesPerThread) > 1) return false;
    elastic = true;
  }
  return elastic;
}

bool FsiStepper::advance_bodies(double t, double dt, RatePass next) {
  const std::size_t nf = sys_.fluid.size();
  const bool subcycled = !dual_.bodies_share_step(nf);
  const bool average = prm_.substep_average && subcycled;
  auto bodies = [&] {
    for (std::size_t b = 0; b < sys_.bodies.size(); ++b)
      if (average && sys_.bodies[b].is_elastic()) averages_[b].begin(sys_.bodies[b]);
    solid_substeps_ += dual_.advance(sys_.bodies, t, dt, prm_.gravity, subcycled, exec_);
  };
  const bool eligible = bodies_beside_fluid_pass();
  BesideChoice& choice = beside_choice_[static_cast<std::size_t>(next)];
  // Beside only on lists that will hold for the water (its displacement is checked only then,
  // not in every eligible advance).
  const bool beside =
      eligible &&
      (beside_schedule_ == BesideSchedule::Measured ? choice.beside()
                                                    : beside_schedule_ == BesideSchedule::Always) &&
      lists_->fluid_within_skin(sys_.fluid, exec_, found_.fluid_d2);
  beside_advances_ += beside;
  const auto start = std::chrono::steady_clock::now();
  // The fixed entries' virtual state beside as well, once they are gathered (header comment).
  const bool fixed_beside = beside && fixed_gathered_ &&
                            fixed_contact_.size() == sys_.contact.size() && sys_.fluid.size() > 0;
  if (beside)
    exec_.concurrently(bodies, [&] {
      fluid_pass(next);
      if (fixed_beside) virtual_state(VirtualSubset::Fixed);
    });
  else
    bodies();
  fixed_virtual_beside_ = fixed_beside;
  // The pass still to come in evaluate_rates() completes the measurement (BesideChoice).
  pending_ = eligible ? &choice : nullptr;
  pending_beside_ = beside;
  pending_seconds_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // A body that blew up during its sub-steps is reported here, as a divergence with the
  // particle, before the neighbour rebuild in evaluate_rates() meets non-finite positions.
  check_bodies(t + dt);
  for (std::size_t b = 0; b < sys_.bodies.size(); ++b)
    if (average && sys_.bodies[b].is_elastic()) averages_[b].end(sys_.bodies[b], dt);
  return beside;
}

namespace {

// The state check's test of fluid particle i (FsiStepper::check_state): x, v or rho not
// finite, or x outside the domain. Without branches (|q| <= max is false for NaN and ±inf,
// as std::isfinite; the domain's comparisons as written), so that it costs the integrator's
// last sweep no more than its loads.
inline bool bad_fluid(Vec2 x, Vec2 v, double rho, const Box& d) {
  constexpr double big = std::numeric_limits<double>::max();
  const bool finite = (std::abs(x.x) <= big) & (std::abs(x.y) <= big) & (std::abs(v.x) <= big) &
                      (std::abs(v.y) <= big) & (std::abs(rho) <= big);
  const bool outside = (x.x < d.min.x) | (x.x > d.max.x) | (x.y < d.min.y) | (x.y > d.max.y);
  return !finite | outside;
}

// The water's arrays as raw pointers, for the integrator's sweeps to capture by value (with
// a copy of the equation of state): in Executor::maxima_of's copy of the sweep they stay in
// registers, where through the vectors (and a referenced TaitEos, whose doubles a store to
// rho or p may alias) they were loaded again, and stiffness() divided again, per particle.
// The same operations on the same values: the same bits.
struct FluidView {
  Vec2 *x, *v, *a, *v_half;
  double *rho, *drho, *rho_half, *p;
};
FluidView view(FluidParticles& f) {
  return {f.x.data(),   f.v.data(),    f.a.data(),        f.v_half.data(),
          f.rho.data(), f.drho.data(), f.rho_half.data(), f.p.data()};
}

// What the last sweep finds at particle i after its update: |v|², |a|² (the next step's
// limit) and 1 if check_state() rejects it.
inline std::array<double, 3> findings(const FluidView& w, std::size_t i, const Box& d) {
  return {norm2(w.v[i]), norm2(w.a[i]), bad_fluid(w.x[i], w.v[i], w.rho[i], d) ? 1.0 : 0.0};
}

}  // namespace

// Each particle's own operations run as in a sweep of their own (the same bits); the two
// operators folded in only read what `update` has just written, and the next step's limit
// reads v and a, which nothing writes between this sweep and the next step() when the
// absorbing zone is off (end_step; the recorder and the checkpoints only read).
template <class Update>
double FsiStepper::last_sweep(Update&& update) {
  FluidParticles& f = sys_.fluid;
  if (prm_.absorbing_zone.active()) {  // it changes v and rho after this sweep
    exec_.for_each(f.size(), update, Executor::kMinParallelCheap);
    return -1.0;
  }
  const Box d = prm_.domain;
  const FluidView w = view(f);
  const std::array<double, 3> m = exec_.maxima_of<3>(
      f.size(),
      [=](std::size_t i) {
        update(i);
        return findings(w, i, d);
      },
      0.0, Executor::kMinParallelCheap);
  found_.maxima = true;
  found_.next_maxima = {m[0], m[1]};
  return m[2];
}

// The lists' displacement check (InteractionLists::update) reads x and the positions of the
// last build: here x is in a register already. No rebuild can come between this sweep and
// the evaluation that uses it (the bodies' advance does not move the water).
template <class Update>
void FsiStepper::drift_sweep(Update&& update) {
  FluidParticles& f = sys_.fluid;
  const std::vector<Vec2>& ref = lists_->fluid_reference();
  if (ref.size() != f.size()) {
    exec_.for_each(f.size(), update, Executor::kMinParallelCheap);
    found_.fluid_d2 = -1.0;
    return;
  }
  const Vec2* const x0 = ref.data();
  const Vec2* const x = f.x.data();
  found_.fluid_d2 = exec_.maxima_of<1>(
      f.size(),
      [=](std::size_t i) {
        update(i);
        return std::array<double, 1>{norm2(x[i] - x0[i])};
      },
      0.0, Executor::kMinParallelCheap)[0];
}

void FsiStepper::step() {
  FluidParticles& f = sys_.fluid;
  PhaseTimes& t = times_;
  PhaseClock clock;
  const StepLimitParams sp{prm_.cfl, prm_.acceleration_cfl, sys_.eos.c0, prm_.end_time,
                           dual_.bodies_share_step(f.size())};
  limit_ = choose_time_step(f, sys_.bodies, sys_.kernel_f, sp, exec_,
                            found_.maxima ? &found_.next_maxima : nullptr);
  found_.maxima = false;
  ++limiter_steps_[static_cast<std::size_t>(limit_.limiter)];
  clock.lap(t.step_limit);
  const double dt = limit_.dt;
  if (!(dt >= prm_.dt_floor)) {
    std::ostringstream os;
    os << "time step " << dt << " s fell below numerics.dt_floor = " << prm_.dt_floor
       << " s at t = " << time_ << " s; limiting criterion: " << describe_limit();
    if (limited_by_fluid(limit_.limiter) && f.size() > 0) {
      std::size_t worst = 0;
      double best = -1.0;
      const bool acc = limit_.limiter == StepLimiter::FluidAcceleration;
      for (std::size_t i = 0; i < f.size(); ++i) {
        const double q = norm2(acc ? f.a[i] : f.v[i]);
        if (q > best) best = q, worst = i;
      }
      os << "; fluid particle " << f.id[worst] << " has |" << (acc ? "a" : "v")
         << "| = " << std::sqrt(best);
    }
    throw DivergenceError(os.str());
  }
  if (prm_.fluid_integrator == FluidIntegrator::Symplectic) {
    step_symplectic(dt, clock, t);
    return;
  }
  const TaitEos eos = sys_.eos;
  const double hdt = 0.5 * dt;
  FluidView w = view(f);
  const auto drift = [=](std::size_t i) {
    w.v_half[i] = w.v[i] + hdt * w.a[i];
    w.rho_half[i] = w.rho[i] + hdt * w.drho[i];
    w.x[i] += dt * w.v_half[i];
    w.v[i] = w.v_half[i] + hdt * w.a[i];  // predicted, for the velocity-dependent rates
    w.rho[i] = w.rho_half[i] + hdt * w.drho[i];
    w.p[i] = eos.pressure(w.rho[i]);
  };
  // Both half kicks in eight lanes for the Tait exponent 7 where the CPU has them
  // (fluid/kick_lanes.h: the scalar sweeps were bound by their divisions rho / rho0).
  const bool lanes = kick_in_pass_ && eos.gamma == 7.0 && kick_lanes_avx512_available();
  const std::vector<Vec2>& ref = lists_->fluid_reference();
  if (lanes && ref.size() == f.size()) {
    // drift_sweep in groups of kGroup particles, each through the lanes and its tail in turn:
    // the same maximum (exact in any order).
    constexpr std::size_t kGroup = 64;
    const std::size_t n = f.size();
    KickLaneData k{w.v_half, w.rho_half, w.a,      w.drho,          w.x,        w.v, w.rho,
                   w.p,      hdt,        eos.rho0, eos.stiffness(), prm_.domain};
    k.dt = dt;
    k.x0 = ref.data();
    const Vec2* const x0 = ref.data();
    found_.fluid_d2 = exec_.maxima_of<1>(
        (n + kGroup - 1) / kGroup,
        [=](std::size_t g) {
          const std::size_t b = g * kGroup, e = std::min(n, b + kGroup);
          double m[3] = {0.0, 0.0, 0.0};
          std::size_t i = kick_lanes_avx512(k, true, static_cast<std::uint32_t>(b),
                                            static_cast<std::uint32_t>(e), m);
          for (; i < e; ++i) {
            drift(i);
            const double d2 = norm2(w.x[i] - x0[i]);
            if (d2 > m[0]) m[0] = d2;
          }
          return std::array<double, 1>{m[0]};
        },
        0.0, Executor::kMinParallelCheap / kGroup)[0];
  } else {
    drift_sweep(drift);
  }
  clock.lap(t.fluid_integration);
  const bool fluid_done = advance_bodies(time_, dt, RatePass::Both);
  time_ += dt;
  clock.lap(t.solid_substeps);
  const auto kick = [eos, hdt](const FluidView& w, std::size_t i) {
    w.v[i] = w.v_half[i] + hdt * w.a[i];
    w.rho[i] = w.rho_half[i] + hdt * w.drho[i];
    w.p[i] = eos.pressure(w.rho[i]);
  };
  // The last sweep inside step 4's band tasks (evaluate_rates' `then`), on bands the pass has
  // just left in the cache: the contact's terms (computed before the pass, contact_before_pass)
  // added to a and drho in their place, after the pass's own finish, then the kick, the state
  // test and the maxima, each particle's operations those of the separate operators in their
  // order (the same bits). Not with the absorbing zone (it changes v and rho after the sweep).
  // For the Tait exponent 7 the kick runs in eight lanes where the CPU has them (kick_lanes.h;
  // the separate sweep was bound by its divisions rho / rho0), the band's tail in turn.
  AfterFluidPass in_pass;
  if (kick_in_pass_ && !prm_.absorbing_zone.active())
    in_pass = [this, kick, eos, hdt, lanes](std::size_t begin, std::size_t end, std::size_t slot) {
      const FluidView w = view(sys_.fluid);
      const NeighbourList& fc = lists_->fc();
      const Box d = prm_.domain;
      if (fc.start.size() == sys_.fluid.size() + 1) {
        const std::uint32_t* const fs = fc.start.data();
        Vec2* const ca = contact_a_.data();
        double* const cd = contact_drho_.data();
        for (std::size_t i = begin; i < end; ++i) {
          if (fs[i] == fs[i + 1]) continue;
          w.a[i] += ca[i];  // add_contact_to_fluid's additions, then -0 again
          w.drho[i] += cd[i];
          ca[i] = Vec2{-0.0, -0.0};
          cd[i] = -0.0;
        }
      }
      std::array<double, 3> m{0.0, 0.0, 0.0};
      std::size_t i = begin;
      if (lanes) {
        const KickLaneData k{w.v_half, w.rho_half, w.a,      w.drho,          w.x, w.v, w.rho,
                             w.p,      hdt,        eos.rho0, eos.stiffness(), d};
        i = kick_lanes_avx512(k, false, static_cast<std::uint32_t>(begin),
                              static_cast<std::uint32_t>(end), m.data());
      }
      for (; i < end; ++i) {
        kick(w, i);
        const std::array<double, 3> q = findings(w, i, d);
        for (std::size_t k = 0; k < 3; ++k)
          if (q[k] > m[k]) m[k] = q[k];  // Executor::maxima_of's comparison
      }
      band_maxima_[slot] = m;
    };
  const bool kicked =
      evaluate_rates(clock, t, RatePass::Both, fluid_done, in_pass ? &in_pass : nullptr);
  dual_.correct(sys_.bodies, dt);
  for (std::size_t b = 0; b < sys_.bodies.size(); ++b) received_[b] += dual_.received(b);
  clock.lap(t.solid_substeps);
  double bad = 0.0;
  if (kicked) {  // the maxima over the bands, as last_sweep's over its shares
    std::array<double, 3> m{0.0, 0.0, 0.0};
    for (const std::array<double, 3>& q : band_maxima_)
      for (std::size_t k = 0; k < 3; ++k)
        if (q[k] > m[k]) m[k] = q[k];
    found_.maxima = true;
    found_.next_maxima = {m[0], m[1]};
    bad = m[2];
  } else if (lanes && !prm_.absorbing_zone.active()) {
    // The last sweep in lanes, in groups as the drift (step 4 ran beside the bodies).
    w = view(f);  // a neighbour rebuild permutes the arrays
    constexpr std::size_t kGroup = 64;
    const std::size_t n = f.size();
    const KickLaneData k{w.v_half, w.rho_half, w.a,      w.drho,          w.x,        w.v, w.rho,
                         w.p,      hdt,        eos.rho0, eos.stiffness(), prm_.domain};
    const Box d = prm_.domain;
    const std::array<double, 3> m = exec_.maxima_of<3>(
        (n + kGroup - 1) / kGroup,
        [=](std::size_t g) {
          const std::size_t b = g * kGroup, e = std::min(n, b + kGroup);
          std::array<double, 3> q{0.0, 0.0, 0.0};
          std::size_t i = kick_lanes_avx512(k, false, static_cast<std::uint32_t>(b),
                                            static_cast<std::uint32_t>(e), q.data());
          for (; i < e; ++i) {
            kick(w, i);
            const std::array<double, 3> r = findings(w, i, d);
            for (std::size_t c = 0; c < 3; ++c)
              if (r[c] > q[c]) q[c] = r[c];
          }
          return q;
        },
        0.0, Executor::kMinParallelCheap / kGroup);
    found_.maxima = true;
    found_.next_maxima = {m[0], m[1]};
    bad = m[2];
  } else {
    w = view(f);  // a neighbour rebuild permutes the arrays
    bad = last_sweep([=](std::size_t i) { kick(w, i); });
  }
  clock.lap(t.fluid_integration);
  end_step(dt, clock, t, bad);
}

void FsiStepper::end_step(double dt, PhaseClock& clock, PhaseTimes& t, double fluid_bad) {
  // Acoustic damping near the chosen tank walls, over the whole step (absorbing_zone.h).
  zone_momentum_ += apply_absorbing_zone(sys_.fluid, prm_.absorbing_zone, sys_.eos, dt, exec_);
  ++steps_;
  check_state(fluid_bad);
  clock.lap(t.checks_and_zone);
}

// Position Verlet with the density split around the velocity step (header; docs/model.md §5):
//   rho_n+1/2 = rho_n + dt/2 drho_n,  p = Tait(rho_n+1/2),  x_n+1/2 = x_n + dt/2 v_n;
//   momentum pass at (x_n+1/2, v_n, p_n+1/2): a;  v_n+1 = v_n + dt a,  x_n+1 = x_n+1/2 + dt/2
//   v_n+1; continuity pass at (x_n+1, v_n+1, p_n+1/2): drho_n+1;  rho_n+1 = rho_n+1/2 + dt/2
//   drho_n+1.
// drho_n+1 is also the first half step of the next step. For the acoustic pair rho <-> v this
// is a leapfrog (each half of the pair advanced with the other's newest value), amplification
// 1 up to omega dt = 2, where the kick-drift-kick step's predictor grows at every step size.
// The bodies take the step in two halves around the momentum pass (app/dual_time_stepping.h):
// over [t_n, t_n+1/2] holding the force F_n-1/2 of the last momentum pass, then the
// correction dt/2 (F_n+1/2 - F_n-1/2) (the kick, or what numerics.fluid_force_correction
// says), then over [t_n+1/2, t_n+1] holding F_n+1/2. Each body so receives dt F_n+1/2 over
// the step, exactly what the water gave up (the momentum balance closes); for a body without
// sub-steps it is a velocity step with the mid-step force. Each pass sees the water and the
// bodies at the same time: the momentum pass at t_n+1/2 (the sub-step averages of that half),
// the continuity pass at t_n+1.
void FsiStepper::step_symplectic(double dt, PhaseClock& clock, PhaseTimes& t) {
  FluidParticles& f = sys_.fluid;
  const TaitEos eos = sys_.eos;
  const double hdt = 0.5 * dt;
  FluidView w = view(f);
  drift_sweep([=](std::size_t i) {
    w.rho[i] += hdt * w.drho[i];
    w.p[i] = eos.pressure(w.rho[i]);
    w.x[i] += hdt * w.v[i];
  });
  clock.lap(t.fluid_integration);
  bool fluid_done = advance_bodies(time_, hdt, RatePass::Momentum);
  clock.lap(t.solid_substeps);
  evaluate_rates(clock, t, RatePass::Momentum, fluid_done);
  dual_.correct(sys_.bodies, dt);  // dt/2 (F_n+1/2 - F_n-1/2): the first half's correction
  for (std::size_t b = 0; b < sys_.bodies.size(); ++b) received_[b] += dual_.received(b);
  clock.lap(t.solid_substeps);
  w = view(f);
  drift_sweep([=](std::size_t i) {
    w.v[i] += dt * w.a[i];
    w.x[i] += hdt * w.v[i];
  });
  clock.lap(t.fluid_integration);
  fluid_done = advance_bodies(time_ + hdt, hdt, RatePass::Continuity);
  for (std::size_t b = 0; b < sys_.bodies.size(); ++b) received_[b] += dual_.received(b);
  time_ += dt;
  clock.lap(t.solid_substeps);
  evaluate_rates(clock, t, RatePass::Continuity, fluid_done);
  w = view(f);  // a neighbour rebuild permutes the arrays
  const double bad = last_sweep([=](std::size_t i) {
    w.rho[i] += hdt * w.drho[i];
    w.p[i] = eos.pressure(w.rho[i]);
  });
  clock.lap(t.fluid_integration);
  end_step(dt, clock, t, bad);
}

void FsiStepper::check_state(double fluid_bad) const {
  const FluidParticles& fluid = sys_.fluid;
  const Box& d = prm_.domain;
  // The first bad particle in index order names the divergence, whoever found that one is bad.
  const double any =
      fluid_bad >= 0.0
          ? fluid_bad
          : exec_.max_of(
                fluid.size(),
                [&](std::size_t i) {
                  return bad_fluid(fluid.x[i], fluid.v[i], fluid.rho[i], d) ? 1.0 : 0.0;
                },
                0.0, Executor::kMinParallelCheap);
  if (any > 0.0) {
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      if (!bad_fluid(fluid.x[i], fluid.v[i], fluid.rho[i], d)) continue;
      std::ostringstream os;
      const Vec2 x = fluid.x[i];
      const bool finite = std::isfinite(x.x) && std::isfinite(x.y);
      os << "fluid particle " << fluid.id[i] << " at t = " << time_ << " s: ";
      if (!finite || !std::isfinite(fluid.v[i].x) || !std::isfinite(fluid.v[i].y))
        os << "position/velocity is not finite";
      else if (!std::isfinite(fluid.rho[i]))
        os << "density is not finite";
      else
        os << "left the domain at (" << x.x << ", " << x.y << ") m with velocity (" << fluid.v[i].x
           << ", " << fluid.v[i].y << ") m/s";
      os << "; last step " << limit_.dt << " s limited by " << describe_limit();
      throw DivergenceError(os.str());
    }
  }
  check_bodies(time_);
}

void FsiStepper::check_bodies(double time) const {
  const Box& d = prm_.domain;
  for (const SolidBody& b : sys_.bodies) {
    // A fixed body never moves (advance_rigid keeps x and zeroes v): checked in the first
    // step, which a resumed run's checkpoint has passed. Tanks are most body particles.
    if (b.kind == BodyKind::RigidFixed && steps_ > 0) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const Vec2 x = b.x[i];
      if (std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(b.v[i].x) &&
          std::isfinite(b.v[i].y) && inside(d, x))
        continue;
      std::ostringstream os;
      os << "body '" << b.name << "' particle " << i << " at t = " << time << " s: "
         << (std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(b.v[i].x) &&
                     std::isfinite(b.v[i].y)
                 ? "left the domain"
                 : "position/velocity is not finite")
         << " at (" << x.x << ", " << x.y << ") m with velocity (" << b.v[i].x << ", " << b.v[i].y
         << ") m/s; last step " << limit_.dt << " s limited by " << describe_limit();
      throw DivergenceError(os.str());
    }
  }
}

}  // namespace slamsph
