// Still water (validation README §3): water 0.5 m deep in a tank, started hydrostatic.
// Bottom pressure within 2 % of rho g (H - y_probe) (measured +0.5 %). The target
// for spurious speeds, 1 % of sqrt(g H), is NOT met: the low-dissipation GSPH lets an
// odd–even shear mode grow from the side walls (docs/validation.md, "Still water"); the
// largest particle speed over 0.5–1 s is 4.5–5 % of sqrt(gH) at this resolution. The
// bound below guards that figure against regressions (the original growth without the
// static-state term was similar; a broken wall gives tens of per cent).
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
  const double expected = rho * g * (H - 0.01);
  RecordProperty("p_bottom_Pa", std::to_string(p_bottom));
  RecordProperty("vmax_over_sqrt_gH", std::to_string(vmax_late / std::sqrt(g * H)));
  std::printf(
      "bottom pressure %.1f Pa (expected %.1f, error %.2f %%), peak speed %.3g m/s = %.3f %% of "
      "sqrt(gH)\n",
      p_bottom, expected, 100 * (p_bottom / expected - 1), vmax_late,
      100 * vmax_late / std::sqrt(g * H));
  EXPECT_NEAR(p_bottom / expected, 1.0, 0.02);
  EXPECT_LT(vmax_late, 0.06 * std::sqrt(g * H));
  EXPECT_EQ(sim.leaked_particles(), 0);
}
