// The shipped cases/johnson_cook_bar.toml through `slamsph run` (about a second): an Al
// 2024-T3 bar clamped at one end and pulled at 150 m/s fails next to the clamp. Checks the
// failure outputs (failure.csv, summary.json "failures", the VTK history fields) and that
// the failures are where and when the Johnson–Cook model puts them: first failure within
// 5 mm of the clamp and before the tension wave has crossed the bar (0.1 m / 5.3 km/s =
// 19 µs); every failed particle has ε̄p >= D1 = 0.13, the smallest failure strain of
// Al 2024-T3 at rates >= 1/s (ε_f >= D1 since D2 exp(D3 σ*) > 0 and D4 ln ε̇* >= 0).
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/csv_writer.h"

namespace fs = std::filesystem;
using namespace slamsph;

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream f(p);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

TEST(JohnsonCookBar, FailsNextToTheClampAndReportsIt) {
  const fs::path out = fs::temp_directory_path() / ("slamsph_jc_bar_" + std::to_string(getpid()));
  fs::remove_all(out);
  const std::string cmd = std::string("'") + SLAMSPH_BINARY + "' run '" + SLAMSPH_SOURCE_DIR +
                          "/cases/johnson_cook_bar.toml' --threads 1 --quiet --set "
                          "'output.snapshots=[0.00015]' --out '" +
                          out.string() + "' > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);

  const CsvTable f = read_csv((out / "failure.csv").string());
  ASSERT_GT(f.rows(), 10u);
  const int t = f.find("time [s]"), x = f.find("x [m]"),
            ep = f.find("equivalent_plastic_strain [-]");
  const int tr = f.find("triaxiality [-]"), rate = f.find("plastic_strain_rate [1/s]");
  ASSERT_TRUE(t >= 0 && x >= 0 && ep >= 0 && tr >= 0 && rate >= 0);
  const double t0 = f.columns[t][0];
  EXPECT_GT(t0, 2e-6);
  EXPECT_LT(t0, 19e-6);
  EXPECT_LT(f.columns[x][0], 0.005);  // next to the clamp (x = 0)
  for (std::size_t r = 0; r < f.rows(); ++r) {
    EXPECT_GE(f.columns[ep][r], 0.13) << "row " << r;
    EXPECT_GE(f.columns[t][r], t0);
    EXPECT_GT(f.columns[rate][r], 0.0) << "failure happens during plastic flow";
  }
  // summary.json: the count and the first failure's time, written as failure.csv has them.
  const std::string s = read_file(out / "summary.json");
  EXPECT_NE(s.find("\"failed_particles\""), std::string::npos) << s;
  EXPECT_NE(s.find("\"bar\": " + std::to_string(f.rows())), std::string::npos) << s;
  std::ostringstream ts;
  ts.precision(17);
  ts << "\"time_s\": ";
  EXPECT_NE(s.find(ts.str()), std::string::npos) << s;
  // The history fields reach the VTK output.
  const std::string vtp = read_file(out / "vtk" / "bar_00001.vtp");
  for (const char* name : {"equivalent_plastic_strain", "temperature", "damage", "failed",
                           "triaxiality", "plastic_strain_rate"})
    EXPECT_NE(vtp.find(std::string("Name=\"") + name + "\""), std::string::npos) << name;
  // The final snapshot draws every failed particle (set 3 of its CSV), and says how many.
  const CsvTable snap = read_csv((out / "snapshots" / "snapshot_01.csv").string());
  const int set = snap.find("set [-]");
  ASSERT_GE(set, 0);
  std::size_t drawn = 0;
  for (double v : snap.columns[set]) drawn += v == 3.0 ? 1 : 0;
  EXPECT_EQ(drawn, f.rows());
  EXPECT_NE(read_file(out / "snapshots" / "snapshot_01.gp")
                .find(std::to_string(f.rows()) + " failed particles"),
            std::string::npos);
  if (!HasFailure()) fs::remove_all(out);
}
