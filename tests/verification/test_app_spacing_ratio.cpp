// Water coarser than the structure (issue 10 item 2; docs/model.md §4, "Bodies finer than the
// water"): a body r = 2-8 times finer than the water, reduced runs.
//  - the rigid cylinder at constant speed (cases/cylinder_constant_speed.toml at D/dx = 20):
//    the impulse over s/D 0.02-0.25 does not depend on r = 1, 2, 4 within 1 % (the full
//    comparison at D/dx = 40 with r = 8 is scripts/validate_spacing_ratio.sh: there r >= 2
//    is 2.3-3.1 % above r = 1 and within 0.8 % among themselves; docs/model.md §4);
//  - a rigid skin two body layers thick, 1/4 and 1/8 of the water's spacing, holding water
//    at hydrostatic pressure on one side (dry or shallower water on the other): no leak;
//  - still water in a tank whose walls are 2 and 4 times finer than the water stays at rest;
//  - a free body 4 times finer than the water hitting water conserves momentum to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

using namespace slamsph;

namespace {

// Integral of Cs d(s/D) over [a, b] of a sampled Cs(s/D) (trapezoids, linear in between).
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

struct SlamResult {
  double impulse = 0.0, peak = 0.0;
  long leaked = 0;
};

// cases/cylinder_constant_speed.toml at D/dx = 20 with the cylinder r times finer, through
// the case key body[1].spacing_ratio.
SlamResult slam(int r) {
  const double dx = 0.01, V = 2.33, D = 0.2, R = 0.1;
  CaseConfig cfg =
      load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/cylinder_constant_speed.toml",
                {"numerics.dx=0.01", "body[1].spacing_ratio=" + std::to_string(r),
                 "body[1].shape.centre=[0.6, 0.73]"});
  EXPECT_DOUBLE_EQ(cfg.bodies[1].dx, dx / r);
  const double t0 = 3.0 * dx / V;  // lowest point 3 dx above the surface
  cfg.numerics.end_time = t0 + 0.26 * D / V;
  Simulation sim(cfg, silent_options(1));
  std::vector<double> sd, cs;
  while (sim.time() < cfg.numerics.end_time) {
    sim.step();
    sd.push_back(V * (sim.time() - t0) / D);
    cs.push_back(sim.body_load(1).total.y / (1000.0 * V * V * R));
  }
  SlamResult out;
  out.impulse = integral(sd, cs, 0.02, 0.25);
  for (double c : cs) out.peak = std::max(out.peak, c);
  out.leaked = sim.leaked_particles();
  return out;
}

}  // namespace

TEST(SpacingRatio, CylinderSlammingImpulseDoesNotDependOnTheRatio) {
  // Measured (D/dx = 20): impulse 0.54255, 0.54476, 0.54586 at r = 1, 2, 4 (+0.41 %, +0.61 %;
  // r = 8: +0.67 %), peak Cs 5.022, 5.014, 5.010.
  const SlamResult r1 = slam(1);
  for (int r : {2, 4}) {
    const SlamResult rr = slam(r);
    std::printf("r = %d: impulse s/D 0.02-0.25 %.5f (r = 1: %.5f, %+.2f %%), peak Cs %.3f (%.3f)\n",
                r, rr.impulse, r1.impulse, 100 * (rr.impulse / r1.impulse - 1), rr.peak, r1.peak);
    EXPECT_NEAR(rr.impulse / r1.impulse, 1.0, 0.01) << "r = " << r;
    EXPECT_NEAR(rr.peak / r1.peak, 1.0, 0.01) << "r = " << r;
    EXPECT_EQ(rr.leaked, 0);
  }
  EXPECT_NEAR(r1.impulse, 0.5426, 0.005);  // the case itself did not change
}

namespace {

// Water 0.2 m deep left of a vertical rigid skin of two layers at dx / r (dx = 0.01 m), in a
// tank 0.31 m wide; optionally water 0.1 m deep right of it.
std::string skin_case(int r, bool wet_right, double end_time) {
  const double t = 2.0 * 0.01 / r;  // skin thickness
  const std::string x1 = std::to_string(0.2 + t);
  std::string c = R"(
schema_version = 1
name = "thin_skin"
[numerics]
dx = 0.01
end_time = )" + std::to_string(end_time) +
                  R"(
[numerics.domain]
min = [-0.1, -0.1]
max = [0.5, 0.5]
[fluid]
density = 1000.0
sound_speed = 20.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.2, 0.2]
)";
  if (wet_right) c += "[[fluid.block]]\nmin = [" + x1 + ", 0.0]\nmax = [0.31, 0.1]\n";
  c += R"(
[[body]]
name = "tank"
kind = "rigid_fixed"
[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [0.31, 0.35]
[[body]]
name = "skin"
kind = "rigid_fixed"
spacing_ratio = )" +
       std::to_string(r) + R"(
[body.shape]
type = "rectangle"
min = [0.2, 0.0]
max = [)" +
       x1 +
       R"(, 0.3]
)";
  return c;
}

}  // namespace

TEST(SpacingRatio, ThinSkinDoesNotLeakUnderPressure) {
  for (int r : {4, 8})
    for (bool wet : {false, true}) {
      const double end = 0.2;
      Simulation sim(parse_case_string(skin_case(r, wet, end), "thin_skin.toml"),
                     silent_options(1));
      const double face = 0.2, back = 0.2 + 2.0 * 0.01 / r;
      std::int64_t left_count = 0;  // ids are given block by block: left block first
      for (std::size_t i = 0; i < sim.fluid().size(); ++i) left_count += sim.fluid().x[i].x < face;
      while (sim.time() < end) sim.step();
      long wrong_side = 0;
      for (std::size_t i = 0; i < sim.fluid().size(); ++i) {
        const double x = sim.fluid().x[i].x;
        wrong_side += sim.fluid().id[i] < left_count ? x > face : x < back;
      }
      const double h2 = wet ? 0.01 : 0.0;  // right depth squared
      const double thrust = 1000 * 9.81 * (0.04 - h2) / 2;
      std::printf("r = %d, %s: leaked %ld, on the wrong side %ld, skin force %.1f N/m (%.1f)\n", r,
                  wet ? "water on both sides" : "dry behind", sim.leaked_particles(), wrong_side,
                  sim.body_load(1).total.x, thrust);
      EXPECT_EQ(sim.leaked_particles(), 0) << "r = " << r << (wet ? " wet" : " dry");
      EXPECT_EQ(wrong_side, 0) << "r = " << r << (wet ? " wet" : " dry");
      // The skin holds the water: the hydrostatic thrust within 20 % (a 0.2 s run still
      // rings acoustically; the 0.5 s runs in the notes are within 8 %).
      EXPECT_NEAR(sim.body_load(1).total.x / thrust, 1.0, 0.2) << "r = " << r;
    }
}

TEST(SpacingRatio, StillWaterAgainstFineWallsStaysAtRest) {
  // cases/still_water.toml reduced (dx = 0.02, water 0.5 m wide and 0.3 m deep, 0.6 s) with
  // the tank r = 1, 2, 4 times finer than the water (4 r layers: the same wall thickness),
  // at h = 1.5 dx. Measured peak speed after 0.3 s: 0.59, 1.92, 2.14 % of sqrt(gH) (r = 8:
  // 2.23 %): next to a wall finer than the water, sum V grad W over the water's lattice and
  // the wall's no longer cancels exactly (tests/unit/test_coupling_spacing_ratio.cpp), and
  // the first water rows settle closer to the wall. At the validation cases' h = 1.38 dx the
  // square lattice, marginally stable there (docs/model.md §2), is destabilised by it: 0.44,
  // 3.7, 17.6, 32 % at r = 1, 2, 3, 4 (docs/model.md §4, "Bodies finer than the water").
  const double g = 9.81, H = 0.3, rho = 1000.0, weight = rho * g * H * 0.5;
  for (int r : {1, 2, 4}) {
    CaseConfig cfg = load_case(
        std::string(SLAMSPH_SOURCE_DIR) + "/cases/still_water.toml",
        {"numerics.dx=0.02", "numerics.h_over_dx=1.5", "body[0].spacing_ratio=" + std::to_string(r),
         "body[0].shape.layers=" + std::to_string(4 * r), "body[0].shape.max=[0.5, 0.5]",
         "fluid.block[0].max=[0.5, 0.3]", "numerics.end_time=0.6",
         "output.probe[1].position=[0.25, 0.15]"});
    Simulation sim(cfg, silent_options(1));
    double vmax_late = 0.0, floor_force = 0.0;
    long n = 0;
    while (sim.time() < cfg.numerics.end_time) {
      sim.step();
      if (sim.time() > 0.3) {
        for (const Vec2& v : sim.fluid().v) vmax_late = std::max(vmax_late, norm(v));
        floor_force -= sim.body_load(0).total.y;
        ++n;
      }
    }
    floor_force /= static_cast<double>(n);
    const double p_mid = rho * g * 0.15;
    std::printf(
        "r = %d: mid-depth pressure %.1f Pa (%+.2f %%), tank force %.1f N/m (weight %+.2f %%), "
        "peak speed after 0.3 s %.3f %% of sqrt(gH), leaked %ld\n",
        r, sim.probe_value(1), 100 * (sim.probe_value(1) / p_mid - 1), floor_force,
        100 * (floor_force / weight - 1), 100 * vmax_late / std::sqrt(g * H),
        sim.leaked_particles());
    // The weight is carried (within 0.5 %), but the mid-depth pressure reads 4.3-4.6 % low at
    // r = 2, 4 (0.5 % at r = 1): a known deficit of the fine-wall contact (docs/model.md §4).
    EXPECT_NEAR(sim.probe_value(1) / p_mid, 1.0, r == 1 ? 0.02 : 0.06) << "r = " << r;
    EXPECT_NEAR(floor_force / weight, 1.0, 0.01) << "r = " << r;
    EXPECT_LT(vmax_late, 0.03 * std::sqrt(g * H)) << "r = " << r;
    EXPECT_EQ(sim.leaked_particles(), 0) << "r = " << r;
  }
}

TEST(SpacingRatio, FineFreeBodyImpactConservesMomentum) {
  // A free disc (R = 0.06 m) four times finer than the water enters a free water block at
  // 2 m/s, no gravity, no walls (as Coupling.RigidBodyImpactConservesMomentumToRoundOff):
  // total momentum of water and disc is conserved to round-off through the impact.
  for (const char* kind : {"rigid_free", "elastic"}) {
    const std::string text = std::string(R"(
schema_version = 1
name = "impact"
[numerics]
dx = 0.01
end_time = 0.03
gravity = [0.0, 0.0]
[numerics.domain]
min = [-0.5, -0.5]
max = [1.0, 1.0]
[fluid]
density = 1000.0
sound_speed = 30.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.4, 0.2]
[materials.rubber]
density = 1100.0
youngs_modulus = 1.2e7
poisson_ratio = 0.4
[[body]]
name = "disc"
kind = ")") + kind + R"("
material = "rubber"
spacing_ratio = 4
velocity = [0.0, -2.0]
[body.shape]
type = "disc"
centre = [0.2, 0.26]
radius = 0.06
)";
    Simulation sim(parse_case_string(text, "impact.toml"), silent_options(1));
    const Vec2 p0 = sim.total_momentum();
    double max_force = 0.0, scale = 0.0;
    while (sim.time() < 0.03) {
      sim.step();
      max_force = std::max(max_force, norm(sim.body_load(0).total));
    }
    for (std::size_t i = 0; i < sim.fluid().size(); ++i)
      scale += sim.fluid().m[i] * norm(sim.fluid().v[i]);
    for (const SolidBody& b : sim.bodies())
      for (std::size_t i = 0; i < b.size(); ++i) scale += b.m[i] * norm(b.v[i]);
    const Vec2 dp = sim.total_momentum() - p0;
    std::printf(
        "%s, r = 4: momentum change (%.3g, %.3g) kg m/s per m over %ld steps, scale %.3g, "
        "relative %.2g; peak force %.0f N/m\n",
        kind, dp.x, dp.y, sim.steps(), scale, norm(dp) / scale, max_force);
    EXPECT_GT(max_force, 500.0) << kind;
    EXPECT_LT(norm(dp), 1e-10 * scale) << kind;
  }
}

namespace {

// A rigid two-layer skin (1.5 mm spacing, r = 4) across a 0.24 m tank of water (dx = 6 mm,
// h = 1.3 dx, c0 = 65 m/s, the fuselage cases' water) pulled up at `pull` m/s: the water
// under it is in tension, as under the rebounding skin_cylinder keel (-23 kPa there).
std::string piston_case(double pull) {
  const std::string v = std::to_string(pull);
  return R"(
schema_version = 1
name = "piston"
[numerics]
dx = 0.006
h_over_dx = 1.3
end_time = 0.01
gravity = [0.0, -9.81]
[numerics.domain]
min = [-0.1, -0.1]
max = [0.4, 0.5]
[fluid]
density = 1000.0
sound_speed = 65.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.24, 0.12]
[[body]]
name = "tank"
kind = "rigid_fixed"
[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [0.24, 0.3]
[[body]]
name = "skin"
kind = "rigid_prescribed"
spacing_ratio = 4
motion = [[0.0, 0.0, )" +
         v + R"(]]
[body.shape]
type = "rectangle"
min = [0.0, 0.1205]
max = [0.24, 0.1235]
)";
}

}  // namespace

TEST(SpacingRatio, WaterUnderTensionIsNotPulledIntoAFineSkin) {
  // The first water row starts 3.75 mm below the skin's lower layer; every other particle of
  // it is moved `shift` towards the skin, as the lattice noise of the h = 1.3 dx water does
  // under the keel. Under tension the contact is anti-restoring (docs/model.md §4, "Short-range
  // barrier"): without the barrier the shifted particles are drawn into the skin.
  struct Run {
    bool barrier;
    double pull;
  };
  for (const Run run : {Run{false, 0.0}, Run{false, 0.6}, Run{true, 0.6}}) {
    const bool barrier = run.barrier;
    CaseConfig cfg = parse_case_string(piston_case(run.pull), "piston.toml");
    cfg.fluid.contact_barrier = barrier;
    Simulation sim(cfg, silent_options(1));
    FluidParticles& f = sim.fluid();
    long shifted = 0;
    for (std::size_t i = 0; i < f.size(); ++i)
      if (f.x[i].y > 0.114 && static_cast<long>(std::lround(f.x[i].x / 0.006)) % 2 == 0) {
        f.x[i].y += 0.002;
        ++shifted;
      }
    double min_gap = 1.0;
    while (sim.time() < cfg.numerics.end_time) {
      sim.step();
      const double skin_bottom = sim.bodies()[1].x[0].y;
      for (std::size_t i = 0; i < f.size(); ++i)
        min_gap = std::min(min_gap, skin_bottom - f.x[i].y);
    }
    std::printf(
        "barrier %s, pull %.1f m/s: %ld shifted, leaked %ld, closest water below the skin's lower "
        "layer %.2f mm\n",
        barrier ? "on" : "off", run.pull, shifted, sim.leaked_particles(), 1e3 * min_gap);
    if (barrier) {
      EXPECT_EQ(sim.leaked_particles(), 0);
      EXPECT_GT(min_gap, 0.9e-3);  // stays outside the skin's lower face (0.75 mm)
    } else if (run.pull > 0.0) {
      EXPECT_GT(sim.leaked_particles(), 0) << "the defect the barrier removes is no longer shown";
    }
  }
}
