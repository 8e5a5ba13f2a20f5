// Reduced wedge entry (issue 10 item 1; docs/validation.md "Wedge entry: polygon face
// fill"): the rigid 30-degree wedge of cases/wedge_constant_speed.toml at a constant 2 m/s,
// half-beam / dx = 10 (dx = 10 mm), with both polygon fills. Wedge theory at constant speed
// gives a force linear in tau = t - t0; over tau = 3-15 ms the rms deviation from a linear
// fit, relative to the mean force, is 0.027 with fill = "faces" and 0.128 with the Cartesian
// staircase (scripts/wedge_fill_ripple.sh, same numbers). F(15 ms)/(rho V^3 tau) from the
// fit is 15.7 (faces) against Wagner's flat-plate k = pi (pi / (2 tan beta))^2 = 23.25.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

using namespace slamsph;

namespace {

struct Ripple {
  double rms = 0.0;    // rms(F - fit) / mean(F) over the window
  double k_end = 0.0;  // fitted F(tau_b) / (rho V^3 tau_b)
};

Ripple run_wedge(PolygonFill fill) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/wedge_constant_speed.toml");
  const double dx = 0.01, V = 2.0, ta = 0.003, tb = 0.015;
  rescale_resolution(cfg, dx);
  EXPECT_EQ(cfg.bodies[1].name, "wedge");
  const double ya = 0.4 + 3.0 * dx, yk = ya + 0.1 * std::tan(std::numbers::pi / 6.0),
               yt = ya + 0.12;
  cfg.bodies[1].shape.vertices = {{0.4, ya}, {0.5, yk}, {0.5, yt}, {0.3, yt}, {0.3, yk}};
  cfg.bodies[1].shape.fill = fill;
  const double t0 = 3.0 * dx / V;  // geometric contact
  cfg.numerics.end_time = t0 + tb;
  Simulation sim(cfg, silent_options(1));
  std::vector<double> x, y;
  while (sim.time() < cfg.numerics.end_time) {
    sim.step();
    const double tau = sim.time() - t0;
    if (tau >= ta && tau <= tb) {
      x.push_back(tau);
      y.push_back(sim.body_load(1).total.y);
    }
  }
  const double n = static_cast<double>(x.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i] / n, my += y[i] / n;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
  const double b = sxy / sxx, a = my - b * mx;
  double ss = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) ss += (y[i] - a - b * x[i]) * (y[i] - a - b * x[i]);
  return {std::sqrt(ss / n) / my, (a + b * tb) / (1000.0 * V * V * V * tb)};
}

}  // namespace

TEST(WedgeEntry, FaceFillRemovesTheStaircaseRipple) {
  const Ripple faces = run_wedge(PolygonFill::Faces), cart = run_wedge(PolygonFill::Cartesian);
  const double k_wagner =
      std::numbers::pi * std::pow(std::numbers::pi / (2.0 * std::tan(std::numbers::pi / 6.0)), 2);
  std::printf(
      "wedge 30 deg, half-beam/dx = 10: ripple faces %.4f cartesian %.4f; F/(rho V^3 tau) "
      "at 15 ms faces %.3g cartesian %.3g (Wagner %.4g)\n",
      faces.rms, cart.rms, faces.k_end, cart.k_end, k_wagner);
  EXPECT_LT(faces.rms, 0.04);
  EXPECT_GT(cart.rms, 0.08);
  EXPECT_NEAR(faces.k_end / 15.72, 1.0, 0.05);
  EXPECT_GT(faces.k_end / k_wagner, 0.55);
  EXPECT_LT(faces.k_end / k_wagner, 1.0);
}
