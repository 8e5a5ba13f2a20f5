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

#include <cstring>
#include <string>
#include <utility>
#include <vector>

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

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
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

// The kick-drift-kick step's last sweep inside the pass's band tasks, with the contact's terms
// to the water computed before the pass and added there (FsiStepper::step, evaluate_rates'
// `then`; docs/validation.md §6 "Throughput", session 18): every step's water state, rates and
// limit, and the tank's contact forces, bit for bit those of the separate sweep, on 1 and 2
// threads (20 000 particles: the bands and the sweeps split), and 1 and 2 threads alike.
// Broken on purpose (scripts/mutation_check.sh "kick in the pass"): the contact's terms not
// added in the band tasks fails here at the first step.
TEST(FusedSweeps, KickInThePassIsTheSeparateSweep) {
  std::vector<FluidParticles> end_state;
  for (const int threads : {1, 2}) {
    Simulation fused(peer(false), silent_options(threads));
    Simulation apart(peer(false), silent_options(threads));
    apart.set_kick_in_pass(false);
    for (int k = 0; k < 30; ++k) {
      fused.step();
      apart.step();
      ASSERT_EQ(fused.stepper().last_step_limit().dt, apart.stepper().last_step_limit().dt) << k;
      const FluidParticles& a = std::as_const(fused).fluid();
      const FluidParticles& b = std::as_const(apart).fluid();
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_TRUE(same_bits(a.x[i].x, b.x[i].x) && same_bits(a.x[i].y, b.x[i].y))
            << "step " << k << " particle " << i << ", " << threads << " threads";
        ASSERT_TRUE(same_bits(a.v[i].x, b.v[i].x) && same_bits(a.v[i].y, b.v[i].y))
            << "step " << k << " particle " << i << ", " << threads << " threads";
        ASSERT_TRUE(same_bits(a.a[i].x, b.a[i].x) && same_bits(a.a[i].y, b.a[i].y))
            << "step " << k << " particle " << i << ", " << threads << " threads";
        ASSERT_TRUE(same_bits(a.rho[i], b.rho[i]) && same_bits(a.p[i], b.p[i]) &&
                    same_bits(a.drho[i], b.drho[i]))
            << "step " << k << " particle " << i << ", " << threads << " threads";
      }
      const ContactParticles& ca = fused.stepper().system().contact;
      const ContactParticles& cb = apart.stepper().system().contact;
      ASSERT_EQ(ca.size(), cb.size());
      for (std::size_t s = 0; s < ca.size(); ++s)
        ASSERT_TRUE(same_bits(ca.force[s].x, cb.force[s].x) &&
                    same_bits(ca.force[s].y, cb.force[s].y))
            << "step " << k << " contact " << s;
    }
    end_state.push_back(std::as_const(fused).fluid());
  }
  for (std::size_t i = 0; i < end_state[0].size(); ++i)
    ASSERT_TRUE(same_bits(end_state[0].v[i].x, end_state[1].v[i].x) &&
                same_bits(end_state[0].v[i].y, end_state[1].v[i].y) &&
                same_bits(end_state[0].rho[i], end_state[1].rho[i]))
        << "1 against 2 threads, particle " << i;
}
