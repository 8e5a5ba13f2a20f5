// Diverging runs through the slamsph binary (README "Exit codes"): exit 3; stderr names the
// particle, the quantity, the time and the time-step limiter; everything written so far is
// kept (summary.json with status "diverged" and the failure, forces.csv / probes.csv with
// their rows so far, fields.pvd listing frames whose .vtp files exist).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

long lines(const std::string& s) {
  return std::count(s.begin(), s.end(), '\n');
}

// A water block with no tank under a 100 g gravity, 0.1 m above the domain floor: it falls
// out of the domain within ~0.01 s. A small fixed post gives forces.csv a body column.
const char* kFallsOut = R"(schema_version = 1
name = "falls_out"
[numerics]
dx = 0.05
end_time = 1.0
gravity = [0.0, -1000.0]
[numerics.domain]
min = [-0.5, -0.1]
max = [1.5, 1.0]
[fluid]
sound_speed = 20.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.5, 0.5]
[[body]]
name = "post"
kind = "rigid_fixed"
[body.shape]
type = "rectangle"
min = [1.0, 0.0]
max = [1.2, 0.2]
[output]
interval = 0.002
[[output.probe]]
name = "p_floor"
kind = "pressure"
position = [0.25, 0.025]
)";

// A still tank whose dt_floor is above the acoustic step (0.8 ms): the first step collapses.
const char* kStepFloor = R"(schema_version = 1
name = "step_floor"
[numerics]
dx = 0.05
end_time = 0.05
dt_floor = 0.01
[numerics.domain]
min = [-0.5, -0.5]
max = [1.5, 1.5]
[fluid]
sound_speed = 20.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.5, 0.5]
[[body]]
name = "tank"
kind = "rigid_fixed"
[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [1.0, 1.0]
)";

// An elastic disc thrown upwards at 50 m/s, 0.1 m below the domain's top.
const char* kBodyLeaves = R"(schema_version = 1
name = "body_leaves"
[numerics]
dx = 0.02
end_time = 1.0
[numerics.domain]
min = [-0.5, -0.5]
max = [0.5, 0.5]
[materials.rubber]
density = 1100.0
youngs_modulus = 1.2e7
poisson_ratio = 0.4
[[body]]
name = "ball"
material = "rubber"
velocity = [0.0, 50.0]
[body.shape]
type = "disc"
centre = [0.0, 0.3]
radius = 0.1
[output]
interval = 0.0005
)";

class Divergence : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::exists(SLAMSPH_BINARY)) << "build the slamsph target first";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            ("slamsph_div_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override {
    if (!HasFailure())
      fs::remove_all(root_);
    else
      std::printf("kept %s for inspection\n", root_.c_str());
  }

  // Runs the case; returns the exit code, stderr in err_.
  int run(const char* text) {
    std::ofstream(root_ / "case.toml") << text;
    std::ostringstream cmd;
    cmd << "'" << SLAMSPH_BINARY << "' run '" << (root_ / "case.toml").string() << "' --out '"
        << out().string() << "' --threads 1 > /dev/null 2> '" << (root_ / "stderr.txt").string()
        << "'";
    const int st = std::system(cmd.str().c_str());
    err_ = slurp(root_ / "stderr.txt");
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  }
  fs::path out() const { return root_ / "out"; }

  void expect_in_err(const std::string& frag) const {
    EXPECT_NE(err_.find(frag), std::string::npos) << "expected '" << frag << "' in:\n" << err_;
  }

  // Everything written so far is kept and consistent.
  void expect_partial_outputs(bool has_bodies) const {
    const std::string summary = slurp(out() / "summary.json");
    EXPECT_NE(summary.find("\"status\": \"diverged\""), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"failure\": \""), std::string::npos) << summary;
    EXPECT_TRUE(fs::exists(out() / "case.resolved.toml"));
    const std::string probes = slurp(out() / "probes.csv");
    EXPECT_GE(lines(probes), 2) << "probes.csv: header and at least one row";
    if (has_bodies) {
      const std::string forces = slurp(out() / "forces.csv");
      EXPECT_GE(lines(forces), 2) << "forces.csv: header and at least one row";
    }
    // fields.pvd: well-terminated, at least one frame, every listed file exists.
    const std::string pvd = slurp(out() / "fields.pvd");
    EXPECT_NE(pvd.find("</VTKFile>"), std::string::npos) << pvd;
    const std::regex file_attr("file=\"([^\"]+)\"");
    long listed = 0;
    for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), file_attr);
         it != std::sregex_iterator(); ++it, ++listed) {
      const fs::path vtp = out() / (*it)[1].str();
      EXPECT_TRUE(fs::exists(vtp)) << vtp;
      EXPECT_NE(slurp(vtp).find("</VTKFile>"), std::string::npos) << vtp << " is truncated";
    }
    EXPECT_GE(listed, 1) << pvd;
  }

  fs::path root_;
  std::string err_;
};

TEST_F(Divergence, FluidLeavingTheDomainExitsThreeAndKeepsOutputs) {
  ASSERT_EQ(run(kFallsOut), 3) << err_;
  expect_in_err("run diverged: fluid particle ");
  expect_in_err("left the domain at (");
  expect_in_err("with velocity (");
  expect_in_err(" at t = ");
  expect_in_err("limited by fluid acoustic CFL");
  // The particle left through the floor y = -0.1 m: its reported y is below it.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(err_, m, std::regex(R"(left the domain at \(([^,]+), ([^)]+)\))")))
      << err_;
  EXPECT_LT(std::stod(m[2].str()), -0.1);
  expect_partial_outputs(true);
  // Several steps were taken before it diverged: rows beyond the initial one.
  EXPECT_GE(lines(slurp(out() / "forces.csv")), 5);
  EXPECT_GE(lines(slurp(out() / "probes.csv")), 5);
}

TEST_F(Divergence, StepBelowFloorExitsThreeNamingLimiterAndParticle) {
  ASSERT_EQ(run(kStepFloor), 3) << err_;
  expect_in_err("fell below numerics.dt_floor = 0.01 s");
  expect_in_err("at t = 0 s");
  expect_in_err("limiting criterion: fluid acoustic CFL");
  expect_in_err("fluid particle ");
  expect_in_err("|v| = ");
  expect_partial_outputs(true);
}

TEST_F(Divergence, BodyLeavingTheDomainExitsThreeNamingBodyParticle) {
  ASSERT_EQ(run(kBodyLeaves), 3) << err_;
  expect_in_err("body 'ball' particle ");
  expect_in_err("left the domain");
  expect_in_err("limited by solid CFL (body ball)");
  expect_partial_outputs(false);
  EXPECT_GE(lines(slurp(out() / "probes.csv")), 5);
}

}  // namespace
