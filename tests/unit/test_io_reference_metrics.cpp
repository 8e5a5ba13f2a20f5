// Validation metrics on synthetic series with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "io/reference_curves.h"

namespace slamsph {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(IoReferenceMetrics, FindPeak) {
  std::vector<double> t, v;
  for (int i = 0; i <= 100; ++i) {
    t.push_back(0.01 * i);
    v.push_back(std::sin(std::numbers::pi * t.back()));  // max 1 at t = 0.5 (i = 50)
  }
  v[10] = kNaN;
  const Peak p = find_peak(t, v);
  EXPECT_EQ(p.index, 50u);
  EXPECT_DOUBLE_EQ(p.time, 0.5);
  EXPECT_DOUBLE_EQ(p.value, 1.0);
  v[70] = -3.0;
  EXPECT_EQ(find_peak(t, v).index, 50u);
  const Peak a = find_peak(t, v, /*absolute=*/true);
  EXPECT_EQ(a.index, 70u);
  EXPECT_DOUBLE_EQ(a.value, -3.0);
  EXPECT_THROW(find_peak({}, {}), std::invalid_argument);
  EXPECT_THROW(find_peak({0.0}, {kNaN}), std::invalid_argument);
  EXPECT_THROW(find_peak({0.0, 1.0}, {1.0}), std::invalid_argument);
}

TEST(IoReferenceMetrics, RelativeErrorAndInterpolation) {
  EXPECT_NEAR(relative_error(2863.1, 2796.0), 0.024, 1e-4);
  EXPECT_NEAR(relative_error(-1.1, -1.0), -0.1, 1e-12);  // sign of (sim − ref)
  const std::vector<double> t{0, 1, 3}, v{0, 2, 10};
  EXPECT_DOUBLE_EQ(interpolate(t, v, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(interpolate(t, v, 2.0), 6.0);
  EXPECT_DOUBLE_EQ(interpolate(t, v, 3.0), 10.0);
  EXPECT_DOUBLE_EQ(interpolate(t, v, 0.0), 0.0);
  EXPECT_TRUE(std::isnan(interpolate(t, v, -0.1)));
  EXPECT_TRUE(std::isnan(interpolate(t, v, 3.1)));
}

// F(t) = factor × von Kármán (linear in t, so interpolation is exact) from t_contact on.
void vk_series(const SlammingCase& c, double factor, double t_end, std::vector<double>& t,
               std::vector<double>& f) {
  t.clear();
  f.clear();
  for (double tt = 0.0; tt <= t_end + 1e-12; tt += 1e-4) {
    t.push_back(tt);
    const double sd = std::max(0.0, c.velocity * (tt - c.t_contact) / (2 * c.radius));
    f.push_back(factor *
                slamming_force(SlammingTheory::VonKarman, sd, c.density, c.velocity, c.radius));
  }
}

TEST(IoReferenceMetrics, SlammingHistoryErrorKnownAnswers) {
  const SlammingCase c{1000.0, 2.33, 0.1, 0.002};
  std::vector<double> t, f;
  vk_series(c, 1.0, 0.04, t, f);
  SeriesError e = slamming_history_error(t, f, SlammingTheory::VonKarman, c);
  EXPECT_EQ(e.samples, 51u);
  EXPECT_LT(e.rms, 1e-9);
  EXPECT_LT(e.max_abs, 1e-9);

  vk_series(c, 1.2, 0.04, t, f);  // uniformly 20 % high
  e = slamming_history_error(t, f, SlammingTheory::VonKarman, c);
  EXPECT_NEAR(e.rms, 0.2, 1e-9);
  EXPECT_NEAR(e.max_abs, 0.2, 1e-9);

  // Series ending at s/D = 0.175 covers 26 of the 51 points (0.05, 0.055, ..., 0.175).
  vk_series(c, 1.2, c.t_contact + 0.175 * 0.2 / 2.33 + 1e-4, t, f);
  e = slamming_history_error(t, f, SlammingTheory::VonKarman, c);
  EXPECT_EQ(e.samples, 26u);
  EXPECT_NEAR(e.rms, 0.2, 1e-9);

  // von Kármán against Campbell–Weynberg at s/D 0.2 and 0.3 (closed form; README §1 table:
  // 1023 vs 642 N/m and 682 vs 507 N/m).
  vk_series(c, 1.0, 0.04, t, f);
  e = slamming_history_error(t, f, SlammingTheory::CampbellWeynberg, c, 0.2, 0.3, 2);
  const double r2 = std::numbers::pi * 0.6 / (5.15 / 4.8 + 0.11) - 1.0;   // 0.5935
  const double r3 = std::numbers::pi * 0.4 / (5.15 / 6.7 + 0.165) - 1.0;  // 0.3459
  EXPECT_NEAR(r2, 1023.0 / 642.0 - 1.0, 2e-3);
  EXPECT_NEAR(r3, 682.0 / 507.0 - 1.0, 2e-3);
  EXPECT_EQ(e.samples, 2u);
  EXPECT_NEAR(e.max_abs, r2, 1e-9);
  EXPECT_NEAR(e.at, 0.2, 1e-12);
  EXPECT_NEAR(e.rms, std::sqrt(0.5 * (r2 * r2 + r3 * r3)), 1e-9);

  // No overlap: NaN metrics, zero samples.
  e = slamming_history_error({0.0, 1e-4}, {1.0, 1.0}, SlammingTheory::Wagner, c);
  EXPECT_EQ(e.samples, 0u);
  EXPECT_TRUE(std::isnan(e.rms));
}

TEST(IoReferenceMetrics, FrontErrorKnownAnswers) {
  const FrontTable mm = martin_moyce_1952();
  const double a = 0.146, g = 9.81, scale = std::sqrt(2 * g / a);
  // A simulated front through the Martin & Moyce points (piecewise linear in t).
  std::vector<double> t, x;
  for (std::size_t i = 0; i < mm.T.size(); ++i) {
    t.push_back(mm.T[i] / scale);
    x.push_back(mm.Z[i] * a);
  }
  SeriesError e = front_error(t, x, a, g, mm, 3.0);
  EXPECT_EQ(e.samples, 13u);
  EXPECT_LT(e.max_abs, 1e-12);
  e = front_error(t, x, a, g, mm, 2.0);  // T ≤ 2.0: 7 points
  EXPECT_EQ(e.samples, 7u);

  for (auto& v : x) v *= 1.05;
  e = front_error(t, x, a, g, mm, 3.0);
  EXPECT_NEAR(e.rms, 0.05, 1e-12);
  EXPECT_NEAR(e.max_abs, 0.05, 1e-12);

  // Koshizuka & Oka points outside the simulated T range [0.41, 2.96] are skipped.
  e = front_error(t, x, a, g, koshizuka_oka_1996(), 3.5);
  EXPECT_EQ(e.samples, 6u);
}

TEST(IoReferenceMetrics, BestFrontShiftFindsAStartUpDelay) {
  const FrontTable mm = martin_moyce_1952();
  const double a = 0.146, g = 9.81, scale = std::sqrt(2 * g / a);
  // A simulated front that runs through the experiment's points 0.2 earlier in T.
  std::vector<double> t, x;
  for (std::size_t i = 0; i < mm.T.size(); ++i) {
    t.push_back((mm.T[i] - 0.2) / scale);
    x.push_back(mm.Z[i] * a);
  }
  EXPECT_GT(front_error(t, x, a, g, mm, 2.5).max_abs, 0.05);
  const ShiftedFrontError b = best_front_shift(t, x, a, g, mm, 2.5);
  EXPECT_NEAR(b.shift, 0.2, 1e-9);
  EXPECT_LT(b.error.max_abs, 1e-12);
  EXPECT_EQ(b.error.samples, 10u);
  // Without a delay in the data the best shift is none.
  for (auto& ti : t) ti += 0.2 / scale;
  EXPECT_EQ(best_front_shift(t, x, a, g, mm, 2.5).shift, 0.0);
}

}  // namespace
}  // namespace slamsph
