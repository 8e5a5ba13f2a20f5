// Plastic tension bar, end to end through the body (set-up from a MaterialConfig with
// model j2_linear_hardening, TL-SFPM operators, sub-stepped leapfrog, history committed
// once per sub-step): a free steel bar 0.1 × 0.02 m, dx 4 mm (E 200 GPa, ν 0.3, σ_y
// 250 MPa, H 50 GPa) is pulled at both ends by opposite end loads (first PK stress P on the
// end columns), ramped slowly (20 longitudinal periods, half-cosine) to P_max =
// 1.3 × 2σ_y/√3 (30 % above the perfectly plastic plane-strain limit, so the whole bar
// yields), held, ramped back to zero and held. The strain of the middle half
// (between the columns at L/4 and 3L/4) is compared with the 1D theory of the bar: a
// material point of the same law in plane-strain uniaxial stress (P_xx = load, P_yy = 0,
// F_zz = 1; solved by Newton on F_xx, F_yy), loaded and unloaded along the same path.
//  - the residual plastic elongation after unloading (the permanent set);
//  - the elastic spring-back on unloading, whose small-strain value is exactly
//    P_max (1 − ν²)/E (elastic unloading at σ_yy = 0, ε_zz = 0).
// An SVK bar under the same loads must come back to zero.
// Measured (this test's printout): residual 1.394e-3 vs theory 1.372e-3 (+1.6 %), loaded
// 3.100e-3 vs 3.089e-3, spring-back 1.706e-3 vs 1.717e-3; bounds 5 %. A softer hardening
// (H 10 GPa, P_max 1.1 × limit) is far more sensitive to ringing on the flat plastic branch:
// +78 % permanent set with 10-period linear ramps, +17 % with 40.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "../unit/test_solid_lattices.h"
#include "core/parallel.h"
#include "solid/materials/material_law_choice.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kE = 200e9, kNu = 0.3, kRho = 7800.0, kSy = 250e6, kHard = 50e9;
constexpr double kL = 0.1, kHgt = 0.02, kDx = 0.004;  // 25 x 5 particles
const double kPmax = 1.3 * 2.0 * kSy / std::sqrt(3.0);

ElasticMaterialInput steel(bool plastic) {
  ElasticMaterialInput m;
  m.name = "steel";
  if (plastic) m.model = J2LinearHardeningModel{kSy, kHard};
  m.density = kRho;
  m.youngs_modulus = kE;
  m.poisson_ratio = kNu;
  m.av_alpha = 1.0;
  m.hourglass = 0.1;
  return m;
}

// Load factor in [0, 1] over the four phases (ramp up, hold, ramp down, hold). The ramps
// are half cosines: a load rate that starts and ends at zero excites less ringing than a
// linear ramp, and ringing on the plastic branch leaves extra permanent set.
double load_factor(double t, double T) {
  const double pi = 3.141592653589793;
  if (t < T) return 0.5 * (1.0 - std::cos(pi * t / T));
  if (t < 2 * T) return 1.0;
  if (t < 3 * T) return 0.5 * (1.0 + std::cos(pi * (t - 2 * T) / T));
  return 0.0;
}

struct BarStrains {
  double loaded = 0.0, residual = 0.0;  // engineering strain of the middle half
};

BarStrains run_bar(bool plastic) {
  const int nx = static_cast<int>(std::lround(kL / kDx)), ny = static_cast<int>(kHgt / kDx);
  BodySetup cfg;
  cfg.gravity = false;
  SolidBody b = make_body(box_lattice(nx, ny, kDx), kDx, "tl_sfpm", steel(plastic), cfg);
  const double c_bar = std::sqrt(kE / (kRho * (1 - kNu * kNu)));
  const double T = 20 * 2 * kL / c_bar;  // ramp time: 20 periods of the free-free bar
  const double dt = stable_time_step(b);
  auto middle_strain = [&] {
    double a = 0.0, c = 0.0;
    for (int j = 0; j < ny; ++j) {
      a += b.x[j * nx + nx / 4].x;
      c += b.x[j * nx + 3 * nx / 4].x;
    }
    return (c - a) / ny / ((3 * nx / 4 - nx / 4) * kDx) - 1.0;
  };
  BarStrains out;
  int n_loaded = 0, n_res = 0;
  const Executor exec(1);
  for (double t = 0.0; t < 4 * T; t += dt) {
    // End loads on the first and last columns: P_max H per unit thickness each way.
    const double f = load_factor(t + 0.5 * dt, T) * kPmax * kHgt / ny;
    for (int j = 0; j < ny; ++j) {
      b.f_fluid[j * nx] = {-f, 0.0};
      b.f_fluid[j * nx + nx - 1] = {f, 0.0};
    }
    advance_body(b, t, dt, {}, exec);
    // Average over the last 40 % of each hold (several periods: averages the ringing).
    if (t > 1.6 * T && t < 2 * T) {
      out.loaded += middle_strain();
      ++n_loaded;
    }
    if (t > 3.6 * T) {
      out.residual += middle_strain();
      ++n_res;
    }
  }
  out.loaded /= n_loaded;
  out.residual /= n_res;
  return out;
}

// 1D theory: the same law at one material point in plane-strain uniaxial stress.
BarStrains material_point() {
  const J2LinearHardening law =
      std::get<J2LinearHardening>(make_material_law(J2LinearHardeningModel{kSy, kHard}, kE, kNu));
  std::array<double, J2LinearHardening::kSlots> h{};
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = J2LinearHardening::kHistory[k].initial;
  double fx = 1.0, fy = 1.0;
  auto solve = [&](double P) {  // Newton on (F_xx, F_yy) for (P_xx, P_yy) = (P, 0)
    for (int it = 0; it < 30; ++it) {
      auto eval = [&](double a, double c) {
        auto tmp = h;  // trial evaluation: commits nothing
        const Mat2 S = law.update(Mat2::identity(), Mat2{a, 0.0, 0.0, c}, 0.0, tmp);
        return std::array<double, 2>{S.xx - P, S.yy};
      };
      const auto r = eval(fx, fy);
      if (std::abs(r[0]) + std::abs(r[1]) < 1e-6) break;
      const double e = 1e-8;
      const auto rx = eval(fx + e, fy), ry = eval(fx, fy + e);
      const double j11 = (rx[0] - r[0]) / e, j12 = (ry[0] - r[0]) / e;
      const double j21 = (rx[1] - r[1]) / e, j22 = (ry[1] - r[1]) / e;
      const double d = j11 * j22 - j12 * j21;
      fx -= (r[0] * j22 - r[1] * j12) / d;
      fy -= (j11 * r[1] - j21 * r[0]) / d;
    }
    law.update(Mat2::identity(), Mat2{fx, 0.0, 0.0, fy}, 0.0, h);  // commit once
  };
  BarStrains out;
  const int n = 400;
  for (int k = 1; k <= n; ++k) solve(kPmax * k / n);
  out.loaded = fx - 1.0;
  for (int k = n - 1; k >= 0; --k) solve(kPmax * k / n);
  out.residual = fx - 1.0;
  return out;
}

}  // namespace

TEST(SolidPlasticBar, PermanentSetMatchesTheOneDimensionalTheory) {
  const BarStrains ref = material_point();
  const BarStrains bar = run_bar(true);
  const double springback = kPmax * (1 - kNu * kNu) / kE;
  std::printf(
      "[plastic bar] loaded strain: bar %.4e, theory %.4e; residual: bar %.4e, theory %.4e; "
      "spring-back: bar %.4e, theory %.4e (small strain %.4e)\n",
      bar.loaded, ref.loaded, bar.residual, ref.residual, bar.loaded - bar.residual,
      ref.loaded - ref.residual, springback);
  EXPECT_GT(ref.residual, 0.5 * springback);  // the set is a large, checked effect
  EXPECT_NEAR(ref.loaded - ref.residual, springback, 0.01 * springback);
  EXPECT_NEAR(bar.residual, ref.residual, 0.05 * ref.residual);
  EXPECT_NEAR(bar.loaded, ref.loaded, 0.05 * ref.loaded);
  EXPECT_NEAR(bar.loaded - bar.residual, springback, 0.05 * springback);

  const BarStrains elastic = run_bar(false);
  std::printf("[plastic bar] svk: loaded %.4e, residual %.4e\n", elastic.loaded, elastic.residual);
  EXPECT_LT(std::abs(elastic.residual), 0.02 * elastic.loaded);
}
