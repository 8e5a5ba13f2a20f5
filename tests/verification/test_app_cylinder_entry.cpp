// Reduced paper case (§4.1; docs/validation.md §3): the shipped elastic cylinder entry at
// dx = 10 mm (D/dx = 20), starting 3 dx above the surface at the free-fall speed that gives
// 2.33 m/s at the surface, reported like the full case: t0 = the geometric contact time,
// Cs = F/(ρ V(t)² R) against s(t)/D from the body's actual path (io/entry_series.h).
// Bands come from the resolution study of this case (scripts/validate_cylinder.sh, h = 1.38
// dx, 1 thread; docs/validation.md §3), not from a theory:
//   dx [mm]                      10      5       2.5
//   V(t0) [m/s]                  2.270   2.302   2.316
//   mean Cs over s/D 0.05-0.25   1.9876  1.9357  1.8442   (not yet monotone: GCI 15 %)
//   peak Cs                      5.000   5.229   4.572    (an acoustic event)
// The study does not converge far enough to give a converged value with a small
// uncertainty, so the bands hold the dx = 10 mm values within 2-3 %, narrower than the
// change per halving of dx (3-5 % for the mean, 5-13 % for the peak): a broken contact
// (force halved, no Riemann dissipation, no (g - a) term, a flipped static term, doubled
// continuity) moves them by more (scripts/mutation_check.sh).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"
#include "io/entry_series.h"

using namespace slamsph;

TEST(CylinderEntry, ReducedPaperCaseMatchesItsResolutionStudy) {
  CaseConfig cfg =
      load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/elastic_cylinder_entry.toml");
  const double dx = 0.01, V = 2.33, R = 0.1, rho = 1000.0, surface = 0.4, g = 9.81;
  rescale_resolution(cfg, dx);
  ASSERT_EQ(cfg.bodies[1].name, "cylinder");
  // 3 dx above the surface (more than the kernel support 2h = 2.76 dx), as the shipped case.
  cfg.bodies[1].shape.centre.y = surface + R + 3 * dx;
  cfg.bodies[1].velocity = {0.0, -std::sqrt(V * V - 2 * g * 3 * dx)};
  cfg.numerics.end_time = 0.04;  // contact at ~13 ms; s/D 0.25 at ~38 ms
  const double h = cfg.numerics.h_over_dx * dx;
  Simulation sim(cfg, silent_options(1));
  const std::size_t cyl = 1;
  const SolidBody& b = sim.bodies()[cyl];
  double m = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) m += b.m[i];
  std::vector<double> t, f, y, vy;
  double max_before_overlap = 0.0;
  auto record = [&] {
    double py = 0.0, my = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) py += b.m[i] * b.v[i].y, my += b.m[i] * b.x[i].y;
    t.push_back(sim.time());
    f.push_back(sim.body_load(cyl).total.y);
    y.push_back(my / m);
    vy.push_back(py / m);
    // The lowest particle row sits dx/2 inside the surface, the top water row dx/2 below
    // it: the kernels first overlap at a gap of 2h − dx.
    if (surface - (y.back() - R) < -(2 * h - dx) - 1e-3)
      max_before_overlap = std::max(max_before_overlap, std::abs(f.back()));
  };
  record();
  while (sim.time() < cfg.numerics.end_time) {
    sim.step();
    record();
  }
  const EntrySeries s = entry_series(t, f, t, y, vy, surface, R, rho);
  std::size_t ipk = 0;
  for (std::size_t k = 1; k < s.f.size(); ++k)
    if (s.f[k] > s.f[ipk]) ipk = k;
  const WindowMean late = mean_cs(s, 0.05, 0.25);
  std::printf(
      "t0 %.3f ms, V(t0) %.4f m/s; peak %.0f N/m at t - t0 %.2f ms, s/D %.4f, Cs %.3f; mean Cs "
      "s/D 0.05-0.25 %.4f (%zu samples); |F| before overlap %.3g; leaked %ld\n",
      1e3 * s.t0, s.speed_at_contact, s.f[ipk], 1e3 * s.t[ipk], s.sd[ipk], s.cs[ipk], late.value,
      late.samples, max_before_overlap, sim.leaked_particles());
  EXPECT_EQ(max_before_overlap, 0.0);  // no force across the gap before the kernels overlap
  // The kernel-range force acts from a gap of 2h − dx: 2.6 % of the speed is lost by t0.
  EXPECT_NEAR(s.speed_at_contact / 2.2715, 1.0, 0.002);  // per-step path (2.2698 from 1 ms rows)
  EXPECT_NEAR(late.value / 1.9876, 1.0, 0.02);
  EXPECT_NEAR(s.cs[ipk] / 5.000, 1.0, 0.03);
  EXPECT_GT(s.sd[ipk], 0.0);  // the peak is the slam after contact, not the approach
  EXPECT_LT(s.sd[ipk], 0.05);
  EXPECT_EQ(sim.leaked_particles(), 0);
  // The water decelerates the cylinder: by the end its speed is below free fall by more
  // than half the impulse / mass.
  double impulse = 0.0;
  for (std::size_t k = 0; k + 1 < t.size(); ++k)
    impulse += 0.5 * (f[k] + f[k + 1]) * (t[k + 1] - t[k]);
  const double free_fall = -cfg.bodies[1].velocity.y + g * t.back();
  EXPECT_GT(free_fall - (-vy.back()), 0.5 * impulse / m);
}
