// The integrator's last sweep also finds the next step's limit (max |v|², max |a|²) and the
// state check's verdict, its drift sweeps the lists' displacement (app/fsi_stepper.cpp,
// FsiStepper::last_sweep / drift_sweep; docs/validation.md §6 "Throughput", session 17).
// Each step's Δt must be the one a separate sweep over the particles gives
// (choose_time_step without the maxima found), bit for bit, on 1 and 2 threads, for both
// integrators; and a run whose particles were changed from outside between two steps (here
// through Simulation::fluid()) must not use what the last sweep found before the change.
// Broken on purpose (scripts/mutation_check.sh "fused sweeps"): the maxima taken from v_half
// instead of the new v fails StepLimitIsTheSeparateSweeps (Δt 5.18652e-05 against
// 5.18465e-05 at the first step); the drift's displacement taken as zero fails
// ListsHoldAfterEveryStep (t = 0.021 s); the state test dropped from the last sweep fails
// Divergence.FluidLeavingTheDomainExitsThreeAndKeepsOutputs (tests/regression).
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "app/simulation.h"
#include "app/time_step_limit.h"
#include "core/parallel.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

using namespace slamsph;

namespace {

CaseConfig peer(bool symplectic) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/bench/dam_break_peer.toml");
  rescale_resolution(cfg, 0.01);  // 20 000 water particles: the sweeps split on 2 threads
  cfg.numerics.end_time = 1.0;
  if (symplectic) {
    cfg.numerics.fluid_integrator = FluidIntegrator::Symplectic;
    cfg.numerics.cfl = 0.6;
  }
  return cfg;
}

// Δt of the next step as the fluid criteria give it from a sweep of their own.
StepLimit separate(const Simulation& sim, const Executor& exec) {
  const FsiStepper& st = sim.stepper();
  const FsiParams& p = st.params();
  const StepLimitParams sp{p.cfl, p.acceleration_cfl, st.system().eos.c0, p.end_time, false};
  return choose_time_step(st.system().fluid, {}, st.system().kernel_f, sp, exec);
}

}  // namespace

TEST(FusedSweeps, StepLimitIsTheSeparateSweeps) {
  for (const bool symplectic : {false, true})
    for (const int threads : {1, 2}) {
      Simulation sim(peer(symplectic), silent_options(threads));
      const Executor exec(1);
      for (int k = 0; k < 60; ++k) {
        const StepLimit want = separate(sim, exec);
        sim.step();
        const StepLimit& got = sim.stepper().last_step_limit();
        ASSERT_TRUE(limited_by_fluid(got.limiter));
        ASSERT_EQ(got.dt, want.dt) << "step " << k << (symplectic ? " symplectic" : " kdk") << ", "
                                   << threads << " threads";
        ASSERT_EQ(got.limiter, want.limiter) << k;
      }
    }
}

TEST(FusedSweeps, ParticlesChangedBetweenStepsAreSweptAgain) {
  Simulation sim(peer(false), silent_options(2));
  for (int k = 0; k < 5; ++k) sim.step();
  // The non-const access makes the stepper forget the last sweep's maxima: the next Δt
  // follows the new speed.
  FluidParticles& f = sim.fluid();
  f.v[17] = {40.0, 0.0};
  const StepLimit want = separate(sim, Executor(1));
  sim.step();
  EXPECT_EQ(sim.stepper().last_step_limit().dt, want.dt);
}

// The lists' displacement check uses the maximum the drift sweep found: after every step the
// lists still hold for the water's positions (no particle has moved half the skin since the
// last build), on both integrators, through rebuilds. Broken on purpose: that maximum taken
// as zero (scripts/mutation_check.sh "fused sweeps") fails here at the first step past half
// the skin.
TEST(FusedSweeps, ListsHoldAfterEveryStep) {
  for (const bool symplectic : {false, true}) {
    CaseConfig cfg = peer(symplectic);
    rescale_resolution(cfg, 0.025);  // 3 200 particles: 0.15 s in a few hundred steps
    Simulation sim(cfg, silent_options(2));
    const Executor exec(1);
    while (sim.time() < 0.15) {
      sim.step();
      ASSERT_TRUE(sim.stepper().lists().fluid_within_skin(std::as_const(sim).fluid(), exec))
          << "t = " << sim.time() << (symplectic ? " symplectic" : " kdk");
    }
    EXPECT_GT(sim.stepper().lists().rebuilds(), 2) << symplectic;
  }
}
