// `slamsph sweep` and `slamsph converge` end to end on a tiny soft ring entering water
// (1200 water particles, 10 ms; about a second per study): the variants' folders, tables,
// overlay plot and rerun file, validation of every variant before any run, and the
// resolution checks of converge.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/csv_writer.h"

namespace {

namespace fs = std::filesystem;

const char* kRing = R"(schema_version = 1
name = "tiny_ring"
[numerics]
dx = 0.01
end_time = 0.01
[numerics.domain]
min = [-0.1, -0.1]
max = [0.7, 0.7]
[fluid]
sound_speed = 30.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.6, 0.2]
[materials.rubber]
model = "svk"
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
kind = "elastic"
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
interval = 0.005
)";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string l; std::getline(ss, l);) out.push_back(l);
  return out;
}

class StudyCommands : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::exists(SLAMSPH_BINARY)) << "build the slamsph target first";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            ("slamsph_study_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    std::ofstream(root_ / "ring.toml") << kRing;
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(root_);
  }
  int run(const std::string& args) {
    const std::string cmd =
        "cd '" + root_.string() + "' && '" + SLAMSPH_BINARY + "' " + args + " >out.txt 2>err.txt";
    const int status = std::system(cmd.c_str());
    err_ = slurp(root_ / "err.txt");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  fs::path root_;
  std::string err_;
};

// Largest |F| of the ring in a variant's forces.csv, computed here independently.
double peak_of(const fs::path& forces) {
  const slamsph::CsvTable t = slamsph::read_csv(forces.string());
  const int cx = t.find("ring Fx [N/m]"), cy = t.find("ring Fy [N/m]");
  double best = 0.0;
  for (std::size_t i = 0; i < t.rows(); ++i)
    best = std::max(best, std::hypot(t.columns[cx][i], t.columns[cy][i]));
  return best;
}

TEST_F(StudyCommands, SweepTwoByTwo) {
  ASSERT_EQ(run("sweep ring.toml --set 'body[1].velocity=[0,-2],[0,-3]' "
                "--set materials.rubber.youngs_modulus=1.2e7,2.4e7 --out sw -t 1 -q"),
            0)
      << err_;
  const fs::path sw = root_ / "sw";
  const std::vector<std::string> rows = lines(slurp(sw / "sweep.csv"));
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_NE(rows[0].find("peak_force [N/m]"), std::string::npos);
  EXPECT_NE(rows[0].find("keel_deflection [m]"), std::string::npos);
  // Cartesian product, first key slowest; each variant ran its own case.
  const char* vel[] = {"[0.0, -2.0]", "[0.0, -2.0]", "[0.0, -3.0]", "[0.0, -3.0]"};
  const char* young[] = {"1.2e+07", "2.4e+07", "1.2e+07", "2.4e+07"};
  std::vector<double> peaks;
  int k = 0;
  for (const auto& e : fs::directory_iterator(sw)) {
    if (!e.is_directory()) continue;
    ++k;
  }
  ASSERT_EQ(k, 4);
  for (int i = 0; i < 4; ++i) {
    const std::string label = rows[i + 1].substr(0, rows[i + 1].find(','));
    const fs::path dir = sw / label;
    ASSERT_TRUE(fs::exists(dir / "case.resolved.toml")) << label;
    const std::string resolved = slurp(dir / "case.resolved.toml");
    EXPECT_NE(resolved.find(std::string("velocity = ") + vel[i]), std::string::npos) << label;
    EXPECT_NE(resolved.find(std::string("youngs_modulus = ") + young[i]), std::string::npos)
        << label;
    EXPECT_NE(resolved.find("kind = \"body_max_strain\""), std::string::npos);
    EXPECT_NE(rows[i + 1].find(",completed"), std::string::npos) << rows[i + 1];
    // Column 3 (after variant and the two keys) is the peak force, as forces.csv says.
    std::stringstream ss(rows[i + 1]);
    std::vector<std::string> f;
    for (std::string c; std::getline(ss, c, ',');) f.push_back(c);
    const double peak = std::stod(f[f.size() - 12]);
    EXPECT_NEAR(peak, peak_of(dir / "forces.csv"), 1e-6 * peak) << label;
    const double strain = std::stod(f[f.size() - 8]);
    EXPECT_GT(strain, 1e-4) << label;  // the ring deforms
    peaks.push_back(peak);
  }
  // Entering 1.5 times faster: the peak grows (about as V^2 for an impact force).
  EXPECT_GT(peaks[2], 1.3 * peaks[0]);
  EXPECT_GT(peaks[3], 1.3 * peaks[1]);
  const std::string md = slurp(sw / "sweep.md");
  EXPECT_NE(md.find("| body[1].velocity | materials.rubber.youngs_modulus |"), std::string::npos);
  const std::string rerun = slurp(sw / "sweep_rerun.sh");
  EXPECT_NE(rerun.find("slamsph sweep ring.toml --set 'body[1].velocity=[0,-2],[0,-3]'"),
            std::string::npos)
      << rerun;
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    EXPECT_GT(fs::file_size(sw / "sweep_force.png"), 1000u);
  }
  // The variants' folders now hold runs: a second sweep into them needs --overwrite
  // (refused before anything runs), which the rerun file passes.
  const std::string again =
      "sweep ring.toml --set 'body[1].velocity=[0,-2],[0,-3]' "
      "--set materials.rubber.youngs_modulus=1.2e7,2.4e7 --out sw -t 1 -q";
  EXPECT_EQ(run(again), 2);
  EXPECT_NE(err_.find("--overwrite"), std::string::npos) << err_;
  EXPECT_NE(rerun.find("--threads 1 --overwrite"), std::string::npos) << rerun;
  // Two of the runs compared with `slamsph plot DIR1 DIR2 --out OUT`.
  const std::string l1 = rows[1].substr(0, rows[1].find(','));
  const std::string l4 = rows[4].substr(0, rows[4].find(','));
  ASSERT_EQ(run("plot sw/" + l1 + " sw/" + l4 + " --out cmp"), 0) << err_;
  const std::vector<std::string> cmp = lines(slurp(root_ / "cmp" / "overlay.csv"));
  ASSERT_EQ(cmp.size(), 3u);
  EXPECT_EQ(cmp[1].substr(0, cmp[1].find(',')), "../sw/" + l1);
  // The same metrics (peak force onwards) as the sweep's row of that run.
  EXPECT_NE(cmp[2].find(rows[4].substr(rows[4].find(",\"[0,-3]\",2.4e7,") + 17, 20)),
            std::string::npos)
      << cmp[2] << "\n"
      << rows[4];
  EXPECT_NE(slurp(root_ / "cmp" / "overlay_force.gp").find("'../sw/" + l4 + "/forces.csv'"),
            std::string::npos);
}

TEST_F(StudyCommands, EveryVariantValidatedBeforeAnyRun) {
  // The second value is refused: nothing may run, not even the first variant.
  EXPECT_EQ(run("sweep ring.toml --set materials.rubber.youngs_modulus=1.2e7,-5 --out sw -q"), 2);
  EXPECT_NE(err_.find("variant 02_materials.rubber.youngs_modulus=-5"), std::string::npos) << err_;
  EXPECT_NE(err_.find("materials.rubber.youngs_modulus"), std::string::npos) << err_;
  EXPECT_FALSE(fs::exists(root_ / "sw")) << err_;
  EXPECT_EQ(run("sweep ring.toml --out sw -q"), 2);
  EXPECT_NE(err_.find("at least one --set"), std::string::npos) << err_;
  EXPECT_EQ(run("sweep ring.toml --set 'numerics.dx=' --out sw -q"), 2);
}

TEST_F(StudyCommands, ConvergeByDxFactors) {
  ASSERT_EQ(run("converge ring.toml --dx-factors 1,0.8,0.64 --end-time 0.004 --out cv -t 1 -q"), 0)
      << err_;
  const std::string md = slurp(root_ / "cv" / "converge.md");
  EXPECT_NE(md.find("## Observed order and Grid Convergence Index"), std::string::npos);
  const std::vector<std::string> gci = lines(slurp(root_ / "cv" / "converge_gci.csv"));
  ASSERT_EQ(gci.size(), 6u);  // header + 5 metrics, one triple each
  EXPECT_EQ(gci[1].rfind("peak force [N/m],0.64,0.8,1,", 0), 0u) << gci[1];
  EXPECT_EQ(lines(slurp(root_ / "cv" / "converge.csv")).size(), 4u);
  EXPECT_TRUE(fs::exists(root_ / "cv" / "converge_rerun.sh"));
}

TEST_F(StudyCommands, ConvergeNeedsAResolution) {
  EXPECT_EQ(run("converge ring.toml --set materials.rubber.density=1000,1100,1200 -q"), 2);
  EXPECT_NE(err_.find("resolution key"), std::string::npos) << err_;
  EXPECT_EQ(run("converge ring.toml --dx-factors 1,0.5 -q"), 2);
  EXPECT_NE(err_.find("at least three"), std::string::npos) << err_;
  EXPECT_EQ(run("converge ring.toml -q"), 2);
  EXPECT_EQ(
      run("converge ring.toml --set body[1].shape.layers=2,3,4 --set body[1].dx=0.005,0.004 -q"),
      2);
  EXPECT_NE(err_.find("one value per run"), std::string::npos) << err_;
}

}  // namespace
