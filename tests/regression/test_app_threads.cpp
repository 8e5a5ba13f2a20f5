// Thread-count independence (style: gather-style loops, "bit-identical for any thread
// count"): the same case advanced with 1 and with 2 threads gives bit-identical fluid
// positions, velocities, densities, body states and fluid forces; the binary run with
// --threads 1 and --threads 2 writes byte-identical forces.csv and probes.csv.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/simulation.h"
#include "io/case_file.h"

using namespace slamsph;
namespace fs = std::filesystem;

namespace {

std::uint64_t bits(double d) {
  return std::bit_cast<std::uint64_t>(d);
}

// Index of the first entry whose bits differ, or -1.
long first_diff(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (bits(a[i]) != bits(b[i])) return static_cast<long>(i);
  return -1;
}
long first_diff(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (a.size() != b.size()) return 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (bits(a[i].x) != bits(b[i].x) || bits(a[i].y) != bits(b[i].y)) return static_cast<long>(i);
  return -1;
}

#define EXPECT_BITWISE(a, b, what)                                                   \
  do {                                                                               \
    const long k_ = first_diff(a, b);                                                \
    EXPECT_EQ(k_, -1) << what << " differs between 1 and 2 threads at index " << k_; \
  } while (0)

void expect_identical(const Simulation& s1, const Simulation& s2) {
  EXPECT_EQ(bits(s1.time()), bits(s2.time()));
  EXPECT_EQ(s1.steps(), s2.steps());
  EXPECT_EQ(s1.solid_substeps(), s2.solid_substeps());
  EXPECT_EQ(s1.leaked_particles(), s2.leaked_particles());
  EXPECT_BITWISE(s1.fluid().x, s2.fluid().x, "fluid position");
  EXPECT_BITWISE(s1.fluid().v, s2.fluid().v, "fluid velocity");
  EXPECT_BITWISE(s1.fluid().rho, s2.fluid().rho, "fluid density");
  EXPECT_BITWISE(s1.fluid().p, s2.fluid().p, "fluid pressure");
  ASSERT_EQ(s1.bodies().size(), s2.bodies().size());
  for (std::size_t b = 0; b < s1.bodies().size(); ++b) {
    SCOPED_TRACE("body " + s1.bodies()[b].name);
    EXPECT_BITWISE(s1.bodies()[b].x, s2.bodies()[b].x, "body position");
    EXPECT_BITWISE(s1.bodies()[b].v, s2.bodies()[b].v, "body velocity");
    EXPECT_BITWISE(s1.bodies()[b].f_fluid, s2.bodies()[b].f_fluid, "body fluid force");
    const BodyLoad l1 = s1.body_load(b), l2 = s2.body_load(b);
    EXPECT_BITWISE(std::vector<Vec2>({l1.total, l1.viscous}),
                   std::vector<Vec2>({l2.total, l2.viscous}), "body load");
  }
}

// Steps both simulations in lock step, comparing the whole state every `every` steps so
// a difference is reported at the step it appears.
// beside: the 2-thread run's schedule of small bodies' sub-steps and the water's pass
// (app/fsi_stepper.h); with Always the run must have taken that path, rebuilds included.
void run_and_compare(const CaseConfig& cfg, long steps, long every,
                     BesideSchedule beside = BesideSchedule::Measured) {
  Simulation s1(cfg, silent_options(1));
  Simulation s2(cfg, silent_options(2));
  s2.set_beside_schedule(beside);
  ASSERT_GT(s1.fluid().size(), 256u) << "too few particles to exercise the parallel loops";
  expect_identical(s1, s2);
  for (long n = 1; n <= steps; ++n) {
    s1.step();
    s2.step();
    if (n % every == 0 || n == steps) {
      SCOPED_TRACE("after step " + std::to_string(n));
      expect_identical(s1, s2);
      if (::testing::Test::HasFailure()) return;
    }
  }
  // The run really moved: not a trivially identical state at rest.
  double vmax = 0.0;
  for (const Vec2& v : s1.fluid().v) vmax = std::max(vmax, norm(v));
  EXPECT_GT(vmax, 1e-3);
  std::printf("%s: %zu fluid particles, %ld steps to t = %.4g s, max |v| = %.3g m/s\n",
              cfg.name.c_str(), s1.fluid().size(), s1.steps(), s1.time(), vmax);
  if (beside == BesideSchedule::Always) {
    EXPECT_EQ(s1.beside_advances(), 0);  // one thread: always in turn
    std::printf("2 threads: %ld advances beside the water's pass, %ld passes redone\n",
                s2.beside_advances(), s2.beside_passes_redone());
    EXPECT_GT(s2.beside_advances(), 0);
    EXPECT_GT(s2.beside_passes_redone(), 0) << "no rebuild met a pass done beside";
  }
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(AppThreads, DamBreakBitIdenticalFor1And2Threads) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/dam_break.toml");
  cfg.numerics.dx = 0.02;  // 1250 water particles
  run_and_compare(cfg, 150, 25);
}

// The symplectic fluid step (numerics.fluid_integrator): its two passes per step keep the
// gather order of the standard one.
TEST(AppThreads, SymplecticDamBreakBitIdenticalFor1And2Threads) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/dam_break.toml");
  cfg.numerics.dx = 0.02;
  cfg.numerics.cfl = 0.5;
  cfg.numerics.fluid_integrator = FluidIntegrator::Symplectic;
  run_and_compare(cfg, 80, 20);
}

// The symplectic step with a sub-cycled elastic body in contact (the two half advances, the
// mid-step correction).
TEST(AppThreads, SymplecticElasticCylinderEntryBitIdenticalFor1And2Threads) {
  CaseConfig cfg =
      load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/elastic_cylinder_entry.toml");
  cfg.numerics.dx = 0.01;
  cfg.numerics.cfl = 0.5;
  cfg.numerics.fluid_integrator = FluidIntegrator::Symplectic;
  for (BodyConfig& b : cfg.bodies)
    if (b.name == "cylinder") b.shape.centre.y = 0.48;  // 2 cm into the water
  run_and_compare(cfg, 40, 20);
}

TEST(AppThreads, ElasticCylinderEntryBitIdenticalFor1And2Threads) {
  CaseConfig cfg =
      load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/elastic_cylinder_entry.toml");
  cfg.numerics.dx = 0.01;  // 4000 water particles, the disc at dx 0.01 too
  // Start the cylinder in contact so the fluid-solid coupling is exercised within 100 steps.
  for (BodyConfig& b : cfg.bodies)
    if (b.name == "cylinder") b.shape.centre.y = 0.48;  // 2 cm into the water
  run_and_compare(cfg, 100, 20);
  Simulation probe(cfg, silent_options(1));
  for (int n = 0; n < 20; ++n) probe.step();
  // The cylinder feels the water (so the body-force comparison above is not of zeros).
  EXPECT_GT(norm(probe.body_load(1).total), 1.0);
}

// A small body's sub-steps beside the water's pass (app/fsi_stepper.h), in every advance,
// both steps: the pass computed on the lists of the step's start, done again whenever the
// neighbour lists rebuild and reorder the water, gives the one-thread bits. The gate's water
// runs out under it and reorders within the first 400 steps (without the pass done again
// after a rebuild the symplectic run differs from step ~290 on).
TEST(AppThreads, SubstepsBesideTheWaterPassBitIdenticalToOneThread) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/elastic_gate.toml");
  cfg.numerics.dx = 0.0025;  // 2 240 water particles, a 2 x 34 particle gate
  cfg.numerics.fluid_integrator = FluidIntegrator::Symplectic;
  cfg.numerics.cfl = 0.5;
  run_and_compare(cfg, 400, 50, BesideSchedule::Always);
  cfg.numerics.fluid_integrator = FluidIntegrator::KickDriftKick;
  cfg.numerics.cfl = 0.25;
  run_and_compare(cfg, 400, 50, BesideSchedule::Always);
}

TEST(AppThreads, BinaryWritesIdenticalForcesAndProbesFor1And2Threads) {
  ASSERT_TRUE(fs::exists(SLAMSPH_BINARY)) << "build the slamsph target first";
  const fs::path root =
      fs::temp_directory_path() / ("slamsph_threads_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  // elastic_cylinder_entry.toml at dx 0.01 with the cylinder starting in the water, no VTK.
  std::string text = slurp(std::string(SLAMSPH_SOURCE_DIR) + "/cases/elastic_cylinder_entry.toml");
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"\ndx = 0.005", "\ndx = 0.01"},
           {"centre = [0.5, 0.515]", "centre = [0.5, 0.48]"},
           {"[output]\n", "[output]\nvtk = false\n"}}) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << "cases/elastic_cylinder_entry.toml changed: " << from;
    text.replace(at, from.size(), to);
  }
  const std::string src = (root / "case.toml").string();
  std::ofstream(src) << text;
  std::string out[2][2];
  for (int t = 1; t <= 2; ++t) {
    const fs::path dir = root / std::to_string(t);
    std::ostringstream cmd;
    cmd << "'" << SLAMSPH_BINARY << "' run '" << src << "' --out '" << dir.string()
        << "' --exact-threads --threads " << t << " --max-steps 40 --quiet > '"
        << (root / "log.txt").string() << "' 2>&1";
    const int st = std::system(cmd.str().c_str());
    ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << slurp(root / "log.txt");
    out[t - 1][0] = slurp(dir / "forces.csv");
    out[t - 1][1] = slurp(dir / "probes.csv");
    std::string threads_key = "\"threads\": ";
    threads_key += std::to_string(t);
    EXPECT_NE(slurp(dir / "summary.json").find(threads_key), std::string::npos);
  }
  // 40 steps: header plus 41 rows in forces.csv.
  EXPECT_EQ(std::count(out[0][0].begin(), out[0][0].end(), '\n'), 42);
  EXPECT_GT(std::count(out[0][1].begin(), out[0][1].end(), '\n'), 2);
  EXPECT_TRUE(out[0][0] == out[1][0]) << "forces.csv differs between --threads 1 and 2";
  EXPECT_TRUE(out[0][1] == out[1][1]) << "probes.csv differs between --threads 1 and 2";
  if (!::testing::Test::HasFailure()) fs::remove_all(root);
}
