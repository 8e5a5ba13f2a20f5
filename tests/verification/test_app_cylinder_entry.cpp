// Reduced elastic-cylinder water entry (paper §4.1; validation README §1) at dx = 10 mm,
// the first 30 ms. Fails if the coupling is broken: force sign, a missing pressure term,
// a leak, a body that does not decelerate. Bands come from the full-resolution runs
// (scripts/validate_cylinder.sh; docs/validation.md): at dx = 5 mm the peak is within a
// few per cent of Campbell–Weynberg (2796 N/m); at this resolution it is +6.7 %.
#include <gtest/gtest.h>

#include <cmath>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"
#include "io/reference_curves.h"

using namespace slamsph;

TEST(CylinderEntry, ReducedRunFollowsCampbellWeynberg) {
  CaseConfig cfg =
      load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/elastic_cylinder_entry.toml");
  rescale_resolution(cfg, 0.01);
  cfg.numerics.end_time = 0.03;
  Simulation sim(cfg, silent_options(1));
  const std::size_t cyl = 1;
  ASSERT_EQ(sim.bodies()[cyl].name, "cylinder");
  const double V = 2.33, R = 0.1, rho = 1000.0;
  std::vector<double> t{0.0}, fy{sim.body_load(cyl).total.y};
  double impulse = 0.0;
  while (sim.time() < cfg.numerics.end_time) {
    const double t0 = sim.time(), f0 = sim.body_load(cyl).total.y;
    sim.step();
    t.push_back(sim.time());
    fy.push_back(sim.body_load(cyl).total.y);
    if (sim.time() <= 0.02) impulse += 0.5 * (f0 + fy.back()) * (sim.time() - t0);
  }
  const Peak peak = find_peak(t, fy);
  // Campbell–Weynberg impulse over the first 20 ms and mean force for s/D in [0.05, 0.25]
  // (before the tank-bottom acoustic echo returns at 2 x 0.4 m / c0 = 27 ms).
  double cw_impulse = 0.0, cw_mean = 0.0, sim_mean = 0.0;
  const int n = 2000;
  for (int k = 0; k < n; ++k) {
    const double tk = (k + 0.5) * 0.02 / n;
    cw_impulse +=
        slamming_force(SlammingTheory::CampbellWeynberg, V * tk / (2 * R), rho, V, R) * 0.02 / n;
  }
  const double ta = 0.05 * 2 * R / V, tb = 0.25 * 2 * R / V;
  for (int k = 0; k < n; ++k) {
    const double tk = ta + (k + 0.5) * (tb - ta) / n;
    cw_mean += slamming_force(SlammingTheory::CampbellWeynberg, V * tk / (2 * R), rho, V, R) / n;
    sim_mean += interpolate(t, fy, tk) / n;
  }
  const double cw_peak = slamming_force(SlammingTheory::CampbellWeynberg, 0.0, rho, V, R);
  std::printf(
      "peak %.0f N/m at %.2f ms (CW %.0f: %+.1f %%); impulse 0-20 ms %.3f N s/m (CW %.3f: %+.1f "
      "%%); mean s/D 0.05-0.25 %.0f N/m (CW %.0f: %+.1f %%); leaked %ld\n",
      peak.value, 1e3 * peak.time, cw_peak, 100 * (peak.value / cw_peak - 1), impulse, cw_impulse,
      100 * (impulse / cw_impulse - 1), sim_mean, cw_mean, 100 * (sim_mean / cw_mean - 1),
      sim.leaked_particles());
  EXPECT_NEAR(peak.value / cw_peak, 1.0, 0.15);
  EXPECT_LT(peak.time, 0.005);  // the peak is the initial slam
  EXPECT_NEAR(impulse / cw_impulse, 1.0, 0.20);
  EXPECT_NEAR(sim_mean / cw_mean, 1.0, 0.25);
  EXPECT_EQ(sim.leaked_particles(), 0);
  // The water decelerates the cylinder: its mean vertical velocity exceeds free fall by
  // about impulse / mass.
  const SolidBody& b = sim.bodies()[cyl];
  double m = 0.0, p = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) m += b.m[i], p += b.m[i] * b.v[i].y;
  const double vy = p / m, free_fall = -V - 9.81 * sim.time();
  EXPECT_GT(vy - free_fall, 0.5 * impulse / m);
}
