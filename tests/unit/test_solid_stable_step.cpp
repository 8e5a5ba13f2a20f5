// The solid stable step at smoothing lengths above 1.3 dx and artificial viscosities above 1
// (solid/body_dynamics.h, docs/model.md §3 "Solid stable step"). TL-SFPM's stress waves are
// set by the nearest-neighbour spacing dx, not by h, while the artificial viscosity's damping
// grows with α h: a step proportional to h let a thin aluminium skin at h = 1.5 dx (the
// water's h advised next to fine bodies, app/setup_warnings.cpp) diverge in its first fluid
// step. Here a free three-layer aluminium strip with random particle velocities (every mode
// excited, the fastest ones included) is advanced at the default solid CFL: an unstable step
// makes the fastest mode grow geometrically, a stable one keeps every speed below the start.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/parallel.h"
#include "solid/body_dynamics.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.001;  // the shipped 3-layer skin's spacing (3 mm / 3)

ElasticMaterialInput aluminium(double av_alpha) {
  ElasticMaterialInput m;
  m.name = "aluminium";
  m.density = 2700.0;
  m.youngs_modulus = 67.5e9;
  m.poisson_ratio = 0.34;
  m.av_alpha = av_alpha;
  m.hourglass = 0.1;
  return m;
}

// A 40 × 3 strip at h = h_over_dx · dx, solid CFL 0.5 (the default).
SolidBody strip(double h_over_dx, double av_alpha, const std::string& scheme = "tl_sfpm") {
  const ElasticMaterialInput mat = aluminium(av_alpha);
  SolidBody b;
  b.X = box_lattice(40, 3, kDx);
  b.x = b.X;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.V0.push_back(kDx * kDx);
    b.rho0.push_back(mat.density);
    b.m.push_back(mat.density * kDx * kDx);
  }
  BodySetup cfg;
  cfg.name = "strip";
  cfg.kind = BodyKind::Elastic;
  cfg.scheme = solid_scheme_from_name(scheme).value();
  cfg.dx = kDx;
  cfg.h_over_dx = h_over_dx;
  cfg.solid_cfl = 0.5;
  cfg.material = mat;
  setup_body(b, cfg);
  return b;
}

double max_speed(const SolidBody& b) {
  double v = 0.0;
  for (const Vec2& p : b.v) v = std::max(v, std::isfinite(norm(p)) ? norm(p) : 1e300);
  return v;
}

// Max speed over the start's after 400 sub-steps from random velocities (1 mm/s).
double speed_growth(SolidBody b) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  for (Vec2& v : b.v) v = Vec2{u(gen), u(gen)};
  refresh_internal_forces(b, Executor(1));
  const double v0 = max_speed(b);
  const double dt = 40.0 * stable_time_step(b) * (1.0 - 1e-9);  // 40 sub-steps per call
  for (int s = 0; s < 10; ++s) {
    try {
      advance_body(b, s * dt, dt, {}, Executor(1));
    } catch (const std::exception&) {
      return 1e300;  // the sub-step count blew up with the speeds
    }
    EXPECT_EQ(b.last_substeps, 40);
  }
  return max_speed(b) / v0;
}

TEST(SolidStableStep, ThinStripStaysBoundedAtLargerSmoothingLengths) {
  // On the step proportional to h these grew 1e300-fold (h = 1.5, 2.0 dx) within the 400
  // sub-steps; 1.3 dx and α = 1 is the calibrated point, unchanged.
  for (double hdx : {1.3, 1.5, 2.0, 3.0}) {
    const double g = speed_growth(strip(hdx, 1.0));
    std::printf("h = %.1f dx, alpha = 1: max speed %.3g of the start\n", hdx, g);
    EXPECT_LT(g, 1.0) << "h_over_dx = " << hdx;
  }
}

TEST(SolidStableStep, ThinStripStaysBoundedAtStrongerArtificialViscosity) {
  // α = 2 (spec §3: α ≈ 1-2) at h = 1.3 dx grew without bound on the step that ignored α.
  for (double alpha : {2.0, 3.0}) {
    const double g = speed_growth(strip(1.3, alpha));
    std::printf("h = 1.3 dx, alpha = %.0f: max speed %.3g of the start\n", alpha, g);
    EXPECT_LT(g, 1.0) << "av_alpha = " << alpha;
  }
}

TEST(SolidStableStep, LengthIsHUpToTheCalibratedPoint) {
  // Bit for bit the step of h for h <= 1.3 dx and α <= 1 (every shipped case at 1.3 keeps its
  // sub-steps); above, ℓ = min(1.3 dx, (1.3 dx)² / (α h)).
  const double c = strip(1.3, 1.0).material.sound_speed * std::sqrt(1.1);
  for (double hdx : {1.0, 1.2, 1.3})
    for (double alpha : {0.0, 0.5, 1.0})
      EXPECT_EQ(stable_time_step(strip(hdx, alpha)),
                0.5 * Kernel(KernelType::WendlandC2, hdx * kDx).h() / c)
          << hdx << " " << alpha;
  const double hc = 1.3 * kDx;
  EXPECT_NEAR(stable_time_step(strip(1.5, 1.0)), 0.5 * hc * hc / (1.5 * kDx) / c, 1e-20);
  EXPECT_NEAR(stable_time_step(strip(1.3, 2.0)), 0.5 * hc / 2.0 / c, 1e-20);
  EXPECT_NEAR(stable_time_step(strip(2.0, 0.0)), 0.5 * hc / c, 1e-20);
  // TLSPH spreads its gradient over the kernel: h sets its waves, only α > 1 shortens it.
  EXPECT_EQ(stable_time_step(strip(1.5, 1.0, "tlsph")),
            0.5 * Kernel(KernelType::WendlandC2, 1.5 * kDx).h() / c);
  EXPECT_NEAR(stable_time_step(strip(1.5, 2.0, "tlsph")), 0.5 * 1.5 * kDx / 2.0 / c, 1e-20);
}

}  // namespace
