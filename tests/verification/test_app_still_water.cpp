// Still water (validation README §3): water 0.5 m deep in a tank, started hydrostatic.
// Bottom pressure within 2 % of rho g (H - y_probe) and peak speed below 1 % of sqrt(gH)
// (issue #2). The case uses h = 1.38 dx, where the square lattice is stable under
// pressure (core/lattice_stability.h); at the paper's 1.3 dx a zig-zag mode grows at
// ~14 /s and saturates at ~5 % of sqrt(gH) (docs/model.md, "Lattice stability"), which the
// second test pins down so that the analysis and the solver stay in step.
#include <gtest/gtest.h>

#include <cmath>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

using namespace slamsph;

TEST(StillWater, StaysHydrostaticAndAtRest) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/still_water.toml");
  rescale_resolution(cfg, 0.02);
  cfg.numerics.end_time = 1.0;
  cfg.output.probes[0].position = {0.5, 0.01};  // half a spacing above the floor
  Simulation sim(cfg, silent_options(2));
  const double g = 9.81, H = 0.5, rho = 1000.0;
  double vmax_late = 0.0;
  while (sim.time() < cfg.numerics.end_time) {
    sim.step();
    if (sim.time() > 0.5) {
      for (const Vec2& v : sim.fluid().v) vmax_late = std::max(vmax_late, norm(v));
    }
  }
  const double p_bottom = sim.probe_value(0);
  double vmax_now = 0.0;
  for (const Vec2& v : sim.fluid().v) vmax_now = std::max(vmax_now, norm(v));
  EXPECT_DOUBLE_EQ(sim.probe_value(2), vmax_now);  // the case's max_speed probe
  const double expected = rho * g * (H - 0.01);
  RecordProperty("p_bottom_Pa", std::to_string(p_bottom));
  RecordProperty("vmax_over_sqrt_gH", std::to_string(vmax_late / std::sqrt(g * H)));
  std::printf(
      "bottom pressure %.1f Pa (expected %.1f, error %.2f %%), peak speed %.3g m/s = %.3f %% of "
      "sqrt(gH)\n",
      p_bottom, expected, 100 * (p_bottom / expected - 1), vmax_late,
      100 * vmax_late / std::sqrt(g * H));
  EXPECT_NEAR(p_bottom / expected, 1.0, 0.02);
  EXPECT_LT(vmax_late, 0.01 * std::sqrt(g * H));
  EXPECT_EQ(sim.leaked_particles(), 0);
}

// The instability the analysis predicts is real: at h = 1.3 dx the peak speed grows at a
// rate of the predicted size (19.5 /s at mid-depth pressure, 27.6 /s at the bottom;
// measured 13.6 /s over 0.25-0.4 s: the mode starts at the walls and the free surface,
// where the pressure is lower, and is beginning to saturate by 0.4 s).
TEST(StillWater, SquareLatticeAt13DxIsUnstableAsPredicted) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/still_water.toml");
  rescale_resolution(cfg, 0.02);
  cfg.numerics.h_over_dx = 1.3;
  for (BodyConfig& b : cfg.bodies) b.h_over_dx = 1.3;  // the tank walls too
  cfg.numerics.end_time = 0.45;
  Simulation sim(cfg, silent_options(2));
  const double sqrt_gH = std::sqrt(9.81 * 0.5);
  auto vmax = [&] {
    double m = 0.0;
    for (const Vec2& v : sim.fluid().v) m = std::max(m, norm(v));
    return m;
  };
  // Growth between 0.25 s and 0.4 s, after the start-up transient and before saturation.
  while (sim.time() < 0.25) sim.step();
  const double v1 = vmax();
  while (sim.time() < 0.4) sim.step();
  const double v2 = vmax();
  const double rate = std::log(v2 / v1) / 0.15;
  std::printf("zig-zag growth %.1f /s (%.3f %% -> %.3f %% of sqrt(gH))\n", rate, 100 * v1 / sqrt_gH,
              100 * v2 / sqrt_gH);
  EXPECT_GT(rate, 8.0);
  EXPECT_LT(rate, 30.0);
}
