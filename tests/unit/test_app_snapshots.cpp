// [output] snapshots and skin_profile (app/snapshots.h) on a tiny soft ring entering water:
// one snapshot per requested time at the first step at or after it, with water, elastic
// body and PNG; the skin's P_yy against the angle from the keel, one row per angle of the
// mid-surface (two middle layers averaged) and symmetric about the keel for a symmetric
// entry (which fails if the angle were measured from another origin).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/run_options.h"
#include "app/simulation.h"
#include "io/case_file.h"
#include "io/csv_writer.h"
#include "io/plot.h"

namespace slamsph {
namespace {

namespace fs = std::filesystem;

const char* kRing = R"(schema_version = 1
name = "snap_ring"
[numerics]
dx = 0.01
end_time = 0.006
[numerics.domain]
min = [-0.1, -0.1]
max = [0.7, 0.7]
[fluid]
sound_speed = 30.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.6, 0.2]
[materials.rubber]
density = 1100.0
youngs_modulus = 1.2e7
poisson_ratio = 0.4
[[body]]
name = "tank"
kind = "rigid_fixed"
density = 1000.0
[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [0.6, 0.4]
layers = 4
[[body]]
name = "ring"
material = "rubber"
velocity = [0.0, -2.0]
dx = 0.005
[body.shape]
type = "ring"
centre = [0.3, 0.3]
inner_radius = 0.09
outer_radius = 0.1
layers = 2
[output]
vtk = false
snapshots = [0.003, 0.006]
skin_profile = "ring"
)";

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// v at angle x [deg] by linear interpolation on the periodic, sorted angles a in [0, 360).
double interpolate_periodic(const std::vector<double>& a, const std::vector<double>& v, double x) {
  x = std::fmod(x + 360.0, 360.0);
  const std::size_t n = a.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double a0 = a[k], a1 = k + 1 < n ? a[k + 1] : a[0] + 360.0;
    const double xx = x < a0 ? x + 360.0 : x;
    if (xx >= a0 && xx <= a1) {
      const double w = (xx - a0) / (a1 - a0);
      return (1.0 - w) * v[k] + w * v[(k + 1) % n];
    }
  }
  return v[0];
}

TEST(AppSnapshots, StrainPressurePngsAndSkinProfile) {
  const fs::path dir = fs::temp_directory_path() / "slamsph_snapshots_test";
  fs::remove_all(dir);
  RunOptions opt = silent_options(1);
  opt.write_output = true;
  opt.out_dir = dir.string();
  Simulation sim(parse_case_string(kRing, "snap_ring.toml"), opt);
  ASSERT_EQ(sim.run(), 0);
  const fs::path s = dir / "snapshots";
  for (const char* n : {"snapshot_01", "snapshot_02"}) {
    const CsvTable t = read_csv((s / (std::string(n) + ".csv")).string());
    int sets[3] = {0, 0, 0};
    for (double v : t.columns[2]) ++sets[static_cast<int>(v)];
    EXPECT_GT(sets[0], 100) << n;  // water
    EXPECT_EQ(sets[1], 238) << n;  // the whole ring (2 layers x 119) is in the view
    EXPECT_EQ(sets[2], 0) << n;    // the view (ring ± half its size) misses the tank
    const std::string gp = slurp(s / (std::string(n) + ".gp"));
    EXPECT_NE(gp.find("equivalent strain"), std::string::npos);
    EXPECT_NE(gp.find("water pressure [Pa]"), std::string::npos);
    if (!find_gnuplot().empty()) {
      EXPECT_GT(fs::file_size(s / (std::string(n) + ".png")), 1000u);
    }
  }
  // The first snapshot is taken at the first step at or after 3 ms, not later.
  EXPECT_NE(slurp(s / "snapshot_01.gp").find("first step at or after 0.003 s"), std::string::npos);
  const CsvTable p = read_csv((s / "skin_pyy_02.csv").string());
  ASSERT_EQ(p.rows(), 119u);                       // one row per angle, the two layers averaged
  EXPECT_NEAR(p.columns[0][0], 0.0, 360.0 / 119);  // within one arc step of the keel
  double pmax = 0.0, asym = 0.0;
  for (std::size_t i = 0; i < p.rows(); ++i) pmax = std::max(pmax, std::abs(p.columns[1][i]));
  // P_yy(θ) against P_yy(360° − θ), interpolated: a mirror image about the keel.
  for (std::size_t i = 0; i < p.rows(); ++i) {
    const double mirror = 360.0 - p.columns[0][i];
    const double q = interpolate_periodic(p.columns[0], p.columns[1], mirror);
    asym = std::max(asym, std::abs(q - p.columns[1][i]));
  }
  EXPECT_GT(pmax, 1e3);
  EXPECT_LT(asym, 0.1 * pmax) << "P_yy not symmetric about the keel";
  fs::remove_all(dir);
}

// A run shortened with --end-time before a listed snapshot drops that snapshot with a
// warning, writes the ones before it and leaves a case.resolved.toml that reads back (it
// used to complete and then fail, exit 2, when the plot step re-read its resolved case).
// Options of a run of kRing into `dir` (emptied) to `end_time` (run --end-time).
RunOptions shortened_run(const fs::path& dir, double end_time) {
  fs::remove_all(dir);
  RunOptions opt = silent_options(1);
  opt.write_output = true;
  opt.out_dir = dir.string();
  opt.end_time = end_time;
  return opt;
}

TEST(AppSnapshots, EndTimeBeforeASnapshotDropsItWithAWarning) {
  const fs::path dir = fs::temp_directory_path() / "slamsph_snapshots_end_time_test";
  Simulation sim(parse_case_string(kRing, "snap_ring.toml"), shortened_run(dir, 0.004));
  ASSERT_EQ(sim.warnings().size(), 1u);
  EXPECT_NE(sim.warnings()[0].find("output.snapshots at 0.006 s"), std::string::npos)
      << sim.warnings()[0];
  ASSERT_EQ(sim.run(), 0);
  EXPECT_TRUE(fs::exists(dir / "snapshots" / "snapshot_01.csv"));
  EXPECT_FALSE(fs::exists(dir / "snapshots" / "snapshot_02.csv"));
  const CaseConfig back = load_case((dir / "case.resolved.toml").string());
  EXPECT_EQ(back.numerics.end_time, 0.004);
  EXPECT_EQ(back.output.snapshots, std::vector<double>{0.003});
  EXPECT_NE(slurp(dir / "summary.json").find("output.snapshots at 0.006 s"), std::string::npos);
  fs::remove_all(dir);
}

// With every snapshot after --end-time, the skin profile (which the case check requires
// snapshots for, as it does the snapshot view) is dropped too, with the warning, and the resolved
// case reads back (a 6-layer fuselage slice to 1 ms completed and then failed, exit 2, in session
// 13).
TEST(AppSnapshots, EndTimeBeforeEverySnapshotDropsTheSkinProfileToo) {
  const fs::path dir = fs::temp_directory_path() / "slamsph_snapshots_end_time_all_test";
  Simulation sim(parse_case_string(kRing, "snap_ring.toml"), shortened_run(dir, 0.002));
  ASSERT_EQ(sim.warnings().size(), 1u);
  EXPECT_NE(sim.warnings()[0].find("no snapshot left, output.skin_profile (written at the "
                                   "snapshot times) is dropped too"),
            std::string::npos)
      << sim.warnings()[0];
  ASSERT_EQ(sim.run(), 0);
  EXPECT_FALSE(fs::exists(dir / "snapshots" / "snapshot_01.csv"));
  const CaseConfig back = load_case((dir / "case.resolved.toml").string());
  EXPECT_TRUE(back.output.snapshots.empty());
  EXPECT_TRUE(back.output.skin_profile.empty());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace slamsph
