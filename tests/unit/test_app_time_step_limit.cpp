// The fluid step (docs/model.md §2 "Fluid time step and limiters"): the acoustic CFL step
// cfl h / (c0 + max|v|) against the acceleration bound acceleration_cfl sqrt(h / max|a|),
// which numerics.acceleration_cfl = 0 switches off; and the per-limiter step counts that
// summary.json reports as "step_limiters" add up to the fluid steps.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app/simulation.h"
#include "app/time_step_limit.h"
#include "core/parallel.h"
#include "io/case_file.h"

using namespace slamsph;

namespace {

FluidParticles two_particles(Vec2 v, Vec2 a) {
  FluidParticles f;
  f.resize(2);
  f.v[1] = v;
  f.a[0] = a;
  return f;
}

}  // namespace

TEST(TimeStepLimit, AcousticCflAgainstAccelerationBound) {
  const Executor exec(1);
  const Kernel k(KernelType::WendlandC2, 0.013);
  StepLimitParams prm;
  prm.cfl = 0.4;
  prm.acceleration_cfl = 0.25;
  prm.c0 = 40.0;
  prm.end_time = 1.0;
  // |v| = 2, |a| = 50: acoustic 0.4 * 0.013 / 42 = 1.238e-4 s; acceleration
  // 0.25 * sqrt(0.013 / 50) = 4.03e-3 s.
  StepLimit lim = choose_time_step(two_particles({0.0, 2.0}, {30.0, 40.0}), {}, k, prm, exec);
  EXPECT_EQ(lim.limiter, StepLimiter::FluidAcousticCfl);
  EXPECT_DOUBLE_EQ(lim.dt, 0.4 * 0.013 / 42.0);
  // |a| = 5e5 (an impact): the acceleration bound 0.25 * sqrt(0.013 / 5e5) = 4.03e-5 s wins.
  const FluidParticles hit = two_particles({0.0, 2.0}, {3.0e5, 4.0e5});
  lim = choose_time_step(hit, {}, k, prm, exec);
  EXPECT_EQ(lim.limiter, StepLimiter::FluidAcceleration);
  EXPECT_DOUBLE_EQ(lim.dt, 0.25 * std::sqrt(0.013 / 5.0e5));
  prm.acceleration_cfl = 0.5;
  EXPECT_DOUBLE_EQ(choose_time_step(hit, {}, k, prm, exec).dt, 0.5 * std::sqrt(0.013 / 5.0e5));
  // Switched off: the acoustic step whatever the acceleration.
  prm.acceleration_cfl = 0.0;
  lim = choose_time_step(hit, {}, k, prm, exec);
  EXPECT_EQ(lim.limiter, StepLimiter::FluidAcousticCfl);
  EXPECT_DOUBLE_EQ(lim.dt, 0.4 * 0.013 / 42.0);
}

TEST(TimeStepLimit, CaseKeyReachesTheStepAndLimitersAreCounted) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/dam_break.toml");
  EXPECT_EQ(cfg.numerics.acceleration_cfl, 0.25);  // the default
  cfg.numerics.dx = 0.04;
  cfg.numerics.end_time = 0.02;
  // A bound this tight sets every step: the key reaches choose_time_step.
  cfg.numerics.acceleration_cfl = 1e-3;
  {
    Simulation sim(cfg, silent_options(1));
    while (sim.time() < cfg.numerics.end_time && sim.steps() < 50) sim.step();
    EXPECT_EQ(sim.last_step_limit().limiter, StepLimiter::FluidAcceleration);
    EXPECT_EQ(sim.steps_limited_by(StepLimiter::FluidAcceleration), sim.steps());
  }
  cfg.numerics.acceleration_cfl = 0.0;
  Simulation sim(cfg, silent_options(1));
  while (sim.time() < cfg.numerics.end_time) sim.step();
  EXPECT_EQ(sim.steps_limited_by(StepLimiter::FluidAcousticCfl), sim.steps());
  EXPECT_EQ(sim.steps_limited_by(StepLimiter::FluidAcceleration), 0);
}
