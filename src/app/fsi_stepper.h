// The fluid–structure stepper: advances water, bodies and their contact by one fluid step.
//
// Time integration (spec §2 "a second-order integrator"): kick–drift–kick leapfrog for the
// fluid with one fused rate evaluation per step,
//   v+ = v + dt/2 a_n,  rho+ = rho + dt/2 drho_n,  x_n+1 = x_n + dt v+,
//   rates a_n+1, drho_n+1 evaluated at (x_n+1, v+ + dt/2 a_n, rho+ + dt/2 drho_n),
//   v_n+1 = v+ + dt/2 a_n+1,  rho_n+1 = rho+ + dt/2 drho_n+1.
// Bodies advance over the same [t_n, t_n+1] with the fluid force of the last evaluation
// held constant and are then corrected for the new force (app/dual_time_stepping.h).
// numerics.fluid_integrator = "symplectic" (fluid/fluid_integrator_kind.h)
// instead splits the density around a velocity step, with a momentum pass at mid-step and a
// continuity pass at the new velocity (step_symplectic in the .cpp, docs/model.md §5).
//
// One rate evaluation runs these operators in this order (each needs the previous):
//   1. gather_body_state         bodies → contact set (x, v, a, volume, normal)
//   2. InteractionLists::update  Verlet lists; may reorder the fluid
//   3. compute_virtual_state     virtual pressure/density of wetted solid particles (§4)
//   4. compute_gsph_fluid_rates  fluid–fluid GSPH pass (§2); it ZEROES then fills a, drho,
//                                so it must precede every other contribution to them
//   5. add_contact_to_fluid      contact Riemann terms added to the fluid's a, drho (§4)
//   6. compute_contact_reaction  the equal and opposite force on each contact particle
//   7. update_leak_flags         fluid particles found inside a solid (leak counter)
//   8. scatter_contact_forces    contact force → body.f_fluid (ghosts → their parent)
//   9. body loads                total and viscous fluid force per body
// In the kick-drift-kick step (without an absorbing zone, step 4 not run beside the bodies)
// steps 5 and 6 run before step 4 — they read the water's x, v, rho, p, which step 4 does not
// write — with step 5's terms held aside (contact_before_pass), and the step's last sweep
// (the second half kick, the state test, the next limit's maxima) runs in step 4's band tasks
// on each band as soon as the pass has finished it (AfterFluidPass), adding step 5's terms
// first: per particle the same operations in the same order as 4, 5 and the separate sweep.
// Step 4 reads only the water (x, v, rho, p and the fluid–fluid pairs), which the bodies'
// sub-steps do not touch: on two threads, when every sub-cycled elastic body is small enough
// to take its sub-steps on one thread anyway (Executor::threads_for with
// kSubstepParticlesPerThread, solid/elastic_substep.h), step 4 runs beside those sub-steps on
// the other thread (Executor::concurrently), once the water has taken its part of the step,
// when this run's timings say it is faster (app/beside_choice.h): the second thread then no
// longer waits while a small body sub-cycles. Larger bodies keep both
// threads for their sub-steps (the 2 500-particle skin: the same wall time either way, the
// sub-steps on one thread outlasting the pass; docs/validation.md §6 "Threads", session 16).
// Step 3 for the contact entries of rigid_fixed bodies (a tank's walls and their ghosts, most
// of a tank case's contact set) reads those entries, which stay as first gathered, and the
// water: it runs beside the sub-steps too, after the water's pass, and step 3 then fills only
// the moving bodies' entries. A neighbour rebuild in step 2 (which reorders the water) discards
// both and steps 3 and 4 run in their place; so the sums, and the results, are those of the
// serial order on any thread count.
#pragma once
#include <array>
#include <memory>
#include <vector>

#include "app/beside_choice.h"
#include "app/dual_time_stepping.h"
#include "app/phase_times.h"
#include "app/time_step_limit.h"
#include "core/box.h"
#include "core/kernel.h"
#include "coupling/contact_layout.h"
#include "coupling/contact_particles.h"
#include "coupling/contact_rates.h"
#include "coupling/force_correction_kind.h"
#include "coupling/interaction_lists.h"
#include "coupling/substep_average.h"
#include "coupling/virtual_pressure.h"
#include "coupling/wall_acceleration_kind.h"
#include "fluid/absorbing_zone.h"
#include "fluid/fluid_integrator_kind.h"
#include "fluid/fluid_particles.h"
#include "fluid/gsph_fluid_rates.h"
#include "fluid/tait_eos.h"
#include "solid/solid_body.h"

namespace slamsph {

class Executor;

// Physics parameters of the coupled step (the case builder fills them from the case).
struct FsiParams {
  Vec2 gravity;                    // [m/s^2]
  double cfl = 0.25;               // fluid acoustic CFL [-]
  double acceleration_cfl = 0.25;  // acceleration bound factor, 0: off [-] (time_step_limit.h)
  double dt_floor = 1e-9;          // a step below this is divergence [s]
  // Kick-drift-kick or the symplectic split (fluid/fluid_integrator_kind.h, docs/model.md §5).
  FluidIntegrator fluid_integrator = FluidIntegrator::KickDriftKick;
  double end_time = 0.0;           // [s] (only for the step of a case where nothing moves)
  bool dual_time_stepping = true;  // sub-cycle bodies inside a fluid step (spec §6)
  // How sub-cycled elastic bodies receive dt/2 (F_n+1 - F_n) (coupling/fluid_force_correction.h).
  FluidForceCorrection fluid_force_correction = FluidForceCorrection::Kick;
  Box domain;                  // a particle leaving it is divergence [m]
  double limiter_omega = 3.0;  // low-dissipation limiter ω (spec §2) [-]
  double viscosity = 0.0;      // kinematic viscosity [m^2/s]
  // Lowest contact star pressure before the water separates (docs/model.md §4) [Pa].
  double cavitation_pressure = -101325.0;
  bool hydrostatic_correction = true;  // static state in the Riemann U* (docs/model.md §2)
  // Short-range fluid-solid barrier at the water's stiffness (docs/model.md §4).
  bool contact_barrier = true;
  // The fluid sees sub-cycled bodies' velocity and acceleration averaged over the fluid step
  // (coupling/substep_average.h) instead of those of the last sub-step.
  bool substep_average = true;
  // Which acceleration of elastic bodies the contact's static term uses
  // (coupling/wall_acceleration_kind.h).
  WallAcceleration wall_acceleration = WallAcceleration::BodyMean;
  double neighbour_skin = 0.2;   // Verlet skin as a fraction of the contact support [-]
  AbsorbingZone absorbing_zone;  // damping bands along tank walls (inactive by default)
};

// The particle sets and their kernels, as the case builder lays them out.
struct FsiSystem {
  Kernel kernel_f;  // fluid–fluid
  Kernel kernel_c;  // fluid–solid contact: the larger h of fluid and bodies
  TaitEos eos;
  FluidParticles fluid;
  std::vector<SolidBody> bodies;
  ContactLayout layout;
  ContactParticles contact;
};

struct BodyLoad {
  Vec2 total;    // fluid force on the body [N/m]
  Vec2 viscous;  // its viscous part [N/m]
};

class FsiStepper {
 public:
  // Evaluates the rates of the initial state (the first half kick needs them).
  FsiStepper(const FsiParams& params, FsiSystem system, const Executor& exec);

  // One fluid step with the bodies advanced inside it. Throws DivergenceError.
  void step();

  double time() const { return time_; }
  long steps() const { return steps_; }
  long solid_substeps() const { return solid_substeps_; }
  long leaked_particles() const { return leaked_; }
  const StepLimit& last_step_limit() const { return limit_; }
  std::string describe_limit() const { return describe(limit_, sys_.bodies); }
  // How many steps each criterion set since t = 0 (summary.json "step_limiters").
  long steps_limited_by(StepLimiter l) const { return limiter_steps_[static_cast<std::size_t>(l)]; }
  BodyLoad body_load(std::size_t b) const { return loads_[b]; }
  // The time the body loads belong to: the step's end, or with the symplectic step its
  // middle t_n+1/2, where the momentum pass computed them (docs/model.md §5; forces.csv).
  double load_time() const {
    return prm_.fluid_integrator == FluidIntegrator::Symplectic ? time_ - 0.5 * limit_.dt : time_;
  }
  const std::vector<BodyLoad>& body_loads() const { return loads_; }
  // Momentum balance (README "Momentum balance"), both accumulated since t = 0: the fluid
  // impulse body b received as its integrator applied it (app/dual_time_stepping.h), and the
  // momentum change the absorbing zone made to the water, Σ m Δv (fluid/absorbing_zone.h)
  // [N s/m].
  Vec2 body_fluid_impulse(std::size_t b) const { return received_[b]; }
  Vec2 absorbing_zone_momentum() const { return zone_momentum_; }
  // Wall time of each phase over the steps this object took (app/phase_times.h); not
  // checkpointed: a resumed run reports its own segment.
  const PhaseTimes& phase_times() const { return times_; }
  const FsiParams& params() const { return prm_; }
  void set_beside_schedule(BesideSchedule s) { beside_schedule_ = s; }
  // Whether the kick-drift-kick step's last sweep may run in step 4's band tasks and both
  // half kicks in lanes (step(); default on); off: the separate scalar sweeps, which the
  // tests compare with, bit for bit.
  void set_kick_in_pass(bool on) { kick_in_pass_ = on; }
  // Advances that ran beside the water's pass, and of those the ones whose pass a neighbour
  // rebuild discarded (done again in turn).
  long beside_advances() const { return beside_advances_; }
  long beside_passes_redone() const { return beside_redone_; }
  void set_end_time(double t) { prm_.end_time = t; }

  const FsiSystem& system() const { return sys_; }
  // Whoever may change the particles or the lists (a checkpoint's restore, tests) makes the
  // stepper forget what its sweeps found about them (found_).
  FsiSystem& system() {
    found_ = {};
    return sys_;
  }
  const InteractionLists& lists() const { return *lists_; }
  InteractionLists& lists() {
    found_ = {};
    return *lists_;
  }

  // The stepper's own state besides the particle sets (checkpoints, app/checkpoint.h):
  // f(name, value&) per counter; the body loads of the last evaluation through
  // body_loads()/restore_loads(). The step limit is recomputed by every step.
  template <class Self, class F>
  static void visit_state(Self& s, F&& f) {
    f("time", s.time_);
    f("steps", s.steps_);
    f("solid_substeps", s.solid_substeps_);
    f("limiter_steps", s.limiter_steps_);
    f("leaked_particles", s.leaked_);
    f("body_fluid_impulse", s.received_);
    f("absorbing_zone_momentum", s.zone_momentum_);
  }
  void restore_loads(std::vector<BodyLoad> loads) { loads_ = std::move(loads); }

 private:
  // `pass` (fluid_integrator_kind.h): Continuity leaves the bodies' fluid force and loads as
  // the last momentum pass set them; Momentum leaves the leak flags.
  // fluid_pass_done: step 4 was done beside the bodies (advance_bodies) for these lists.
  // then: the integrator's last sweep, to run in step 4's band tasks (AfterFluidPass) when
  // step 4 runs here with RatePass::Both; steps 5 and 6 then run before step 4, their
  // additions to the water's a and drho held in contact_a_ / contact_drho_ and added by
  // `then` in their place (fuse_kick). Returns whether `then` ran.
  bool evaluate_rates(PhaseClock& clock, PhaseTimes& t, RatePass pass = RatePass::Both,
                      bool fluid_pass_done = false, const AfterFluidPass* then = nullptr);
  void step_symplectic(double dt, PhaseClock& clock, PhaseTimes& t);
  // Step 4 of the rate evaluation: the water–water GSPH pass.
  void fluid_pass(RatePass pass, const AfterFluidPass* then = nullptr);
  // Steps 5 and 6 before step 4 (evaluate_rates' `then`): the contact's additions to a and
  // drho go to contact_a_ / contact_drho_, whose entries are -0 but for the water particles
  // with contact partners (x + -0 = x for every x: those entries are exactly the added terms).
  void contact_before_pass(const ContactParams& cp);
  // Step 3 for the contact entries `subset` names (fixed_contact_).
  void virtual_state(VirtualSubset subset);
  // Whether advance_bodies() may run the water's pass beside the bodies (header comment):
  // two threads, water, and sub-cycled elastic bodies all on one-thread teams.
  bool bodies_beside_fluid_pass() const;
  // Advances every body over [t, t + dt] holding its fluid force (the step, or a half of the
  // symplectic step), with the sub-step averages of that interval, and checks the bodies;
  // perhaps with the water pass `next` of the following evaluation beside it: returns
  // whether it ran (pass it on to evaluate_rates).
  bool advance_bodies(double t, double dt, RatePass next);
  // Both steps' end: the absorbing zone over the step, the step count, the state check.
  // fluid_bad: whether the last sweep found a fluid particle check_state() rejects, or
  // negative to have check_state() look.
  void end_step(double dt, PhaseClock& clock, PhaseTimes& t, double fluid_bad = -1.0);
  void check_state(double fluid_bad = -1.0) const;
  // The integrator's last sweep of a step: v, rho, p by `update(i)`, and, unless the
  // absorbing zone changes v and rho after it, the state check's test and the next step
  // limit's maxima over the same particles (found_). Returns fluid_bad for end_step().
  template <class Update>
  double last_sweep(Update&& update);
  // A drift sweep: x by `update(i)`, and the lists' displacement max |x - x at the build|²
  // (found_.fluid_d2).
  template <class Update>
  void drift_sweep(Update&& update);
  // Every body particle finite and inside the domain at `time`; else DivergenceError.
  void check_bodies(double time) const;

  // What the integrator's sweeps found on their way (Executor::maxima_of), for the next
  // operator that would otherwise sweep the particles again for it; each is used once and
  // describes the particles as they are then (nothing writes x, v, a between; system() and
  // lists() forget them). Maxima are exact in any order: the bits are those of the separate
  // sweeps (docs/validation.md §6 "Throughput", session 17).
  struct Found {
    bool maxima = false;  // next_maxima holds the maxima of the current v and a
    FluidMaxima next_maxima;
    double fluid_d2 = -1.0;  // the lists' fluid displacement, or negative: unknown
  };

  FsiParams prm_;
  FsiSystem sys_;
  Found found_;
  const Executor& exec_;
  std::unique_ptr<InteractionLists> lists_;
  DualTimeStepping dual_;
  std::vector<BodyLoad> loads_;
  std::vector<SubstepAverage> averages_;  // per body
  ContactPairForces contact_pairs_;       // kept by the fluid's contact sum for the reaction
  // The contact's terms to the water computed before step 4 (contact_before_pass), and the
  // last sweep's maxima per band of step 4 (max |v|², max |a|², bad), when it ran there.
  std::vector<Vec2> contact_a_;
  std::vector<double> contact_drho_;
  std::vector<std::array<double, 3>> band_maxima_;
  StepLimit limit_;
  double time_ = 0.0;
  long steps_ = 0;
  long solid_substeps_ = 0;
  std::vector<long> limiter_steps_ = std::vector<long>(kStepLimiterCount, 0);  // per StepLimiter
  long leaked_ = 0;
  // The contact entries of rigid_fixed bodies hold their gathered state (evaluate_rates).
  bool fixed_gathered_ = false;
  // Per contact entry: 1 if its body is rigid_fixed (the entries step 3 may fill beside the
  // sub-steps), and whether advance_bodies() did so for the coming evaluation.
  std::vector<std::uint8_t> fixed_contact_;
  bool fixed_virtual_beside_ = false;
  std::vector<Vec2> received_;  // per body, see body_fluid_impulse()
  Vec2 zone_momentum_;
  PhaseTimes times_;
  // Per RatePass (the pass that runs beside): in turn or beside, by the times measured.
  std::array<BesideChoice, 3> beside_choice_;
  BesideChoice* pending_ = nullptr;  // an eligible advance whose pass is still to come
  bool pending_beside_ = false;
  double pending_seconds_ = 0.0;  // its wall seconds so far
  BesideSchedule beside_schedule_ = BesideSchedule::Measured;
  bool kick_in_pass_ = true;
  long beside_advances_ = 0, beside_redone_ = 0;
};

}  // namespace slamsph
