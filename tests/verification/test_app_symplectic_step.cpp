// numerics.fluid_integrator = "symplectic" (docs/model.md §5, app/fsi_stepper.cpp
// step_symplectic): the density split around the velocity step is a leapfrog for the acoustic
// pair rho <-> v, so still water holds at an acoustic CFL of 0.5 where the kick-drift-kick
// step (a predictor-corrector whose amplification exceeds 1, docs/model.md §2) diverges, and
// the dam-break front at CFL 0.5 follows the standard step at 0.25.
// Broken on purpose: the continuity pass evaluated before the velocity step (at the old
// velocity; the split's order lost) made both fail: still-water peak speed 21 % of sqrt(gH)
// (bound 1 %), bottom pressure -7.6 %, dam-break front -1.9 % (bound 0.5 %).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "app/simulation.h"
#include "core/error.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

using namespace slamsph;

namespace {

CaseConfig still_water(bool symplectic, double cfl) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/still_water.toml");
  rescale_resolution(cfg, 0.02);  // 1 250 water particles
  cfg.numerics.cfl = cfl;
  cfg.numerics.end_time = 0.5;
  cfg.numerics.fluid_integrator =
      symplectic ? FluidIntegrator::Symplectic : FluidIntegrator::KickDriftKick;
  cfg.output.probes[0].position = {0.5, 0.01};  // half a spacing above the floor
  return cfg;
}

// Integral of Cs d(s/D) over [a, b] of a sampled Cs(s/D) (trapezoids, as
// test_app_slamming_constant_speed.cpp).
double integral(const std::vector<double>& sd, const std::vector<double>& cs, double a, double b) {
  double acc = 0.0;
  for (std::size_t k = 0; k + 1 < sd.size(); ++k) {
    const double lo = std::max(sd[k], a), hi = std::min(sd[k + 1], b);
    if (hi <= lo) continue;
    const double w = sd[k + 1] - sd[k];
    const double fa = cs[k] + (cs[k + 1] - cs[k]) * (lo - sd[k]) / w;
    const double fb = cs[k] + (cs[k + 1] - cs[k]) * (hi - sd[k]) / w;
    acc += 0.5 * (fa + fb) * (hi - lo);
  }
  return acc;
}

double max_speed(const Simulation& sim) {
  double m = 0.0;
  for (const Vec2& v : sim.fluid().v) m = std::max(m, norm(v));
  return m;
}

}  // namespace

TEST(SymplecticStep, StillWaterHoldsAtCfl05WhereKickDriftKickDiverges) {
  const double g = 9.81, H = 0.5, rho = 1000.0, sqrt_gH = std::sqrt(g * H);
  {
    Simulation kdk(still_water(false, 0.5), silent_options(1));
    double t_fail = -1.0;
    try {
      while (kdk.time() < 0.5) kdk.step();
    } catch (const DivergenceError&) {
      t_fail = kdk.time();
    }
    std::printf("kick-drift-kick at CFL 0.5: diverged at t = %.4f s\n", t_fail);
    EXPECT_GT(t_fail, 0.0) << "the standard step held at CFL 0.5: the test no longer shows "
                              "what the symplectic step adds";
  }
  Simulation sym(still_water(true, 0.5), silent_options(1));
  double vmax_late = 0.0;
  while (sym.time() < 0.5) {
    sym.step();
    if (sym.time() > 0.25) vmax_late = std::max(vmax_late, max_speed(sym));
  }
  const double p_bottom = sym.probe_value(0), expected = rho * g * (H - 0.01);
  std::printf(
      "symplectic at CFL 0.5: %ld steps, bottom p %.1f Pa (%.2f %%), peak speed %.3f %% "
      "of sqrt(gH)\n",
      sym.steps(), p_bottom, 100 * (p_bottom / expected - 1), 100 * vmax_late / sqrt_gH);
  EXPECT_NEAR(p_bottom / expected, 1.0, 0.02);
  EXPECT_LT(vmax_late, 0.01 * sqrt_gH);
  EXPECT_EQ(sym.leaked_particles(), 0);
}

TEST(SymplecticStep, DamBreakFrontAtCfl05FollowsStandardStep) {
  auto run = [](bool symplectic, double cfl, long& steps) {
    CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/dam_break.toml");
    rescale_resolution(cfg, 0.02);
    cfg.numerics.end_time = 0.3;  // T = 1.9: the front at x = 1.4 a
    cfg.numerics.cfl = cfl;
    cfg.numerics.fluid_integrator =
        symplectic ? FluidIntegrator::Symplectic : FluidIntegrator::KickDriftKick;
    Simulation sim(cfg, silent_options(1));
    while (sim.time() < cfg.numerics.end_time) sim.step();
    steps = sim.steps();
    return sim.probe_value(0);  // surge_front
  };
  long n_kdk = 0, n_sym = 0;
  const double kdk = run(false, 0.25, n_kdk), sym = run(true, 0.5, n_sym);
  std::printf(
      "front at 0.3 s: kick-drift-kick CFL 0.25 %.6f m (%ld steps), symplectic CFL 0.5 "
      "%.6f m (%ld steps), %.3f %%\n",
      kdk, n_kdk, sym, n_sym, 100 * (sym / kdk - 1));
  EXPECT_GT(kdk, 0.6);  // the water has run out
  EXPECT_NEAR(sym / kdk, 1.0, 0.005);
  EXPECT_LT(n_sym, 0.55 * n_kdk);
}

// A prescribed body (the constant-speed cylinder of SlammingConstantSpeed at D/dx = 20):
// moved to mid-step for the momentum pass, its slamming impulses and peak at CFL 0.5 follow the
// standard step at 0.25. The symplectic step's force is that of t_n+1/2 and is sampled there.
TEST(SymplecticStep, ConstantSpeedCylinderImpulsesFollowStandardStep) {
  const double dx = 0.01, V = 2.33, D = 0.2, R = 0.1, t0 = 3.0 * dx / V;
  struct Result {
    double late, early, peak;
    long steps;
  };
  auto run = [&](bool symplectic, double cfl) {
    CaseConfig cfg =
        load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/cylinder_constant_speed.toml");
    rescale_resolution(cfg, dx);
    cfg.bodies[1].shape.centre.y = 0.7 + 3.0 * dx;
    cfg.numerics.end_time = t0 + 0.3 * D / V;
    cfg.numerics.cfl = cfl;
    cfg.numerics.fluid_integrator =
        symplectic ? FluidIntegrator::Symplectic : FluidIntegrator::KickDriftKick;
    Simulation sim(cfg, silent_options(1));
    std::vector<double> sd, cs;
    while (sim.time() < cfg.numerics.end_time) {
      const double t_prev = sim.time();
      sim.step();
      const double t = symplectic ? 0.5 * (t_prev + sim.time()) : sim.time();
      sd.push_back(V * (t - t0) / D);
      cs.push_back(sim.body_load(1).total.y / (1000.0 * V * V * R));
    }
    Result r{integral(sd, cs, 0.1, 0.25), integral(sd, cs, 0.02, 0.1), 0.0, sim.steps()};
    for (double c : cs) r.peak = std::max(r.peak, c);
    EXPECT_EQ(sim.leaked_particles(), 0);
    return r;
  };
  const Result kdk = run(false, 0.25), sym = run(true, 0.5);
  std::printf(
      "impulse 0.1-0.25 / 0.02-0.1 / peak Cs / steps: kick-drift-kick CFL 0.25 %.4f / "
      "%.4f / %.3f / %ld, symplectic CFL 0.5 %.4f / %.4f / %.3f / %ld (%+.2f / %+.2f / "
      "%+.2f %%)\n",
      kdk.late, kdk.early, kdk.peak, kdk.steps, sym.late, sym.early, sym.peak, sym.steps,
      100 * (sym.late / kdk.late - 1), 100 * (sym.early / kdk.early - 1),
      100 * (sym.peak / kdk.peak - 1));
  EXPECT_NEAR(sym.late / kdk.late, 1.0, 0.005);
  EXPECT_NEAR(sym.early / kdk.early, 1.0, 0.005);
  EXPECT_NEAR(sym.peak / kdk.peak, 1.0, 0.01);
}
