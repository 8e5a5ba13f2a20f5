// entry_series (io/entry_series.h): Cs = F/(ρ V(t)² R) against s(t)/D from a body's actual
// path, t0 the geometric contact time. A decelerating path with a force built from
// Campbell–Weynberg with the actual speed must give Campbell–Weynberg back; a constant V
// or t0 = 0 (the errors of the pre-issue-9 report) would not.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "io/csv_writer.h"
#include "io/entry_series.h"
#include "io/reference_curves.h"

namespace slamsph {
namespace {

constexpr double kR = 0.1, kRho = 1000.0, kSurf = 0.4;

// V(t) = 2 − 10 t, lowest point 10 mm above the surface at t = 0: depth −0.01 + 2t − 5t²;
// contact at t0 = (2 − sqrt(3.8)) / 10.
struct Path {
  std::vector<double> t, y, vy, tf, f;
};
Path decelerating_path() {
  Path p;
  for (int k = 0; k <= 400; ++k) {
    const double t = 1e-4 * k, depth = -0.01 + 2 * t - 5 * t * t, v = 2 - 10 * t;
    p.t.push_back(t);
    p.y.push_back(kSurf + kR - depth);
    p.vy.push_back(-v);
    const double sd = depth / (2 * kR);
    p.tf.push_back(t);
    p.f.push_back(sd < 0 ? 0.0
                         : kRho * v * v * kR *
                               slamming_coefficient(SlammingTheory::CampbellWeynberg, sd));
  }
  return p;
}

TEST(IoEntrySeries, ActualSpeedAndGeometricContactRecoverTheTheory) {
  const Path p = decelerating_path();
  const EntrySeries s = entry_series(p.tf, p.f, p.t, p.y, p.vy, kSurf, kR, kRho);
  const double t0 = (2 - std::sqrt(3.8)) / 10;
  EXPECT_NEAR(s.t0, t0, 1e-7);
  EXPECT_TRUE(s.t0_from_path);
  EXPECT_NEAR(s.speed_at_contact, 2 - 10 * t0, 1e-6);  // t0 from a linear interpolation
  ASSERT_EQ(s.t.size(), p.t.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    EXPECT_NEAR(s.t[k], p.t[k] - s.t0, 1e-15);
    if (s.sd[k] < 0.01) continue;
    worst = std::max(
        worst,
        std::abs(s.cs[k] / slamming_coefficient(SlammingTheory::CampbellWeynberg, s.sd[k]) - 1.0));
  }
  EXPECT_LT(worst, 1e-12);  // samples coincide with the path: exact
  // With the initial speed instead of V(t) the same force reads 1.4-1.6x low at the end.
  const std::size_t last = s.t.size() - 1;
  EXPECT_GT(std::pow(2.0 / s.v[last], 2), 1.4);
  const WindowMean m = mean_cs(s, 0.05, 0.15);
  EXPECT_GT(m.samples, 10u);
  double ref = 0.0;
  for (std::size_t k = 0; k < s.sd.size(); ++k)
    if (s.sd[k] >= 0.05 && s.sd[k] <= 0.15)
      ref += slamming_coefficient(SlammingTheory::CampbellWeynberg, s.sd[k]);
  EXPECT_NEAR(m.value, ref / double(m.samples), 1e-12);
  EXPECT_TRUE(std::isnan(mean_cs(s, 5.0, 6.0).value));
}

TEST(IoEntrySeries, ForceSamplesBetweenPathSamplesAreInterpolated) {
  Path p = decelerating_path();
  std::vector<double> t, y, vy;  // every 5th path sample only
  for (std::size_t k = 0; k < p.t.size(); k += 5)
    t.push_back(p.t[k]), y.push_back(p.y[k]), vy.push_back(p.vy[k]);
  const EntrySeries s = entry_series(p.tf, p.f, t, y, vy, kSurf, kR, kRho);
  EXPECT_NEAR(s.t0, (2 - std::sqrt(3.8)) / 10, 1e-6);  // position is quadratic in t
  for (std::size_t k = 0; k < s.t.size(); ++k)
    EXPECT_NEAR(s.v[k], -p.vy[k], 1e-12);  // the speed is linear: exact
}

TEST(IoEntrySeries, StartingOnTheSurfaceOrNeverReachingItIsHandled) {
  // Touching at t = 0: t0 = 0 from the path.
  const std::vector<double> t{0.0, 0.01}, y{kSurf + kR, kSurf + kR - 0.02}, vy{-2.0, -2.0};
  const EntrySeries s = entry_series(t, {1.0, 2.0}, t, y, vy, kSurf, kR, kRho);
  EXPECT_EQ(s.t0, 0.0);
  EXPECT_TRUE(s.t0_from_path);
  // Starting 1 mm below: extrapolated back at the initial speed, flagged.
  const std::vector<double> y2{kSurf + kR - 0.001, kSurf + kR - 0.021};
  const EntrySeries s2 = entry_series(t, {1.0, 2.0}, t, y2, vy, kSurf, kR, kRho);
  EXPECT_NEAR(s2.t0, -0.0005, 1e-15);
  EXPECT_FALSE(s2.t0_from_path);
  // Hovering above the water: no contact time.
  const std::vector<double> y3{kSurf + kR + 0.05, kSurf + kR + 0.04};
  EXPECT_THROW(entry_series(t, {0.0, 0.0}, t, y3, vy, kSurf, kR, kRho), std::invalid_argument);
  EXPECT_THROW(entry_series(t, {0.0, 0.0}, {0.0}, {1.0}, {-1.0}, kSurf, kR, kRho),
               std::invalid_argument);
}

TEST(IoEntrySeries, LoadsTheBodyPathFromBodiesCsv) {
  namespace fs = std::filesystem;
  const fs::path d = fs::path(testing::TempDir()) / "slamsph_entry_series";
  fs::remove_all(d);
  fs::create_directories(d);
  const Path p = decelerating_path();
  {
    CsvWriter f((d / "forces.csv").string(), {"time [s]", "cyl Fx [N/m]", "cyl Fy [N/m]"});
    CsvWriter b((d / "bodies.csv").string(), {"time [s]", "cyl com_x [m]", "cyl com_y [m]",
                                              "cyl vel_x [m/s]", "cyl vel_y [m/s]"});
    for (std::size_t k = 0; k < p.t.size(); ++k) {
      f.row({p.tf[k], 0.0, p.f[k]});
      b.row({p.t[k], 0.5, p.y[k], 0.0, p.vy[k]});
    }
  }
  EntrySeries s;
  std::string msg;
  ASSERT_TRUE(load_entry_series(d.string(), "cyl", "", kSurf, kR, kRho, 2.0, 0.0, s, msg)) << msg;
  EXPECT_NEAR(s.t0, (2 - std::sqrt(3.8)) / 10, 1e-7);
  write_entry_series(s, (d / "slamming_cs.csv").string());
  const CsvTable t = read_csv((d / "slamming_cs.csv").string());
  const int cs = t.find("Cs [-]"), cw = t.find("Campbell-Weynberg Cs [-]");
  ASSERT_GT(cs, 0);
  ASSERT_GT(cw, 0);
  EXPECT_GT(t.find("modified Logvinovich F [N/m]"), 0);
  // Without a surface level the path is not used: constant speed from t_contact.
  ASSERT_TRUE(load_entry_series(d.string(), "cyl", "", std::nan(""), kR, kRho, 2.0, 0.001, s, msg));
  EXPECT_NEAR(s.t0, 0.001, 1e-15);
  EXPECT_FALSE(load_entry_series(d.string(), "wedge", "", kSurf, kR, kRho, 2.0, 0.0, s, msg));
  EXPECT_NE(msg.find("\"wedge Fy [N/m]\""), std::string::npos) << msg;
}

}  // namespace
}  // namespace slamsph
