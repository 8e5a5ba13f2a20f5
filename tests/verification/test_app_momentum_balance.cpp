// The momentum balance (momentum.csv, app/recorder.h; README "Momentum balance"):
//   R = P_f − P_f(0) − M_f g t − Z + Σ_b I_b
// closes to round-off when the fluid–body exchange is exact — an elastic body sub-cycled
// with the kick, on the global step and with next_step; a rigid_free, a prescribed and a
// fixed body; an elastic gate with clamped particles; a channel whose absorbing zone takes
// momentum out of the water — and with fluid_force_correction = none it equals minus the
// impulse the kick would have given, Σ dt/2 (F_n+1 − F_n), summed here from the loads step by
// step. Each test also checks that the terms it guards are large against its tolerance.
// Broken on purpose: the contact reaction halved (coupling/contact_rates.cpp), the kick
// removed (coupling/fluid_force_correction.cpp), the absorbing zone's momentum left out of
// the stepper's sum, and the support's share dt/2 (F_n+1 − F_n) of fixed bodies dropped
// (app/dual_time_stepping.cpp) each made at least one of these tests fail.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"
#include "io/csv_writer.h"

using namespace slamsph;
namespace fs = std::filesystem;

namespace {

struct Balance {
  CsvTable t;
  std::string text;           // momentum.csv as written
  std::string summary;        // summary.json as written
  double scale = 0.0;         // largest |term| (norm over x, y) of any row
  double max_residual = 0.0;  // largest |residual| component of any row
  Vec2 last_residual;
  // Largest norm of the (x, y) pair of columns `name x [N s/m]`, `name y [N s/m]`, taken
  // against row 0 when `change`.
  double max_norm(const std::string& name, bool change = false) const {
    const int cx = t.find(name + " x [N s/m]"), cy = t.find(name + " y [N s/m]");
    EXPECT_GE(cx, 0) << name;
    EXPECT_GE(cy, 0) << name;
    if (cx < 0 || cy < 0) return 0.0;
    const std::vector<double>& x = t.columns[static_cast<std::size_t>(cx)];
    const std::vector<double>& y = t.columns[static_cast<std::size_t>(cy)];
    double m = 0.0;
    for (std::size_t r = 0; r < x.size(); ++r)
      m = std::max(m, change ? std::hypot(x[r] - x[0], y[r] - y[0]) : std::hypot(x[r], y[r]));
    return m;
  }
};

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Runs `cfg` with outputs into a fresh folder on `threads` threads and reads its
// momentum.csv; the finished simulation stays in `sim` if given.
Balance run_and_read(CaseConfig cfg, const std::string& tag, int threads = 1,
                     std::unique_ptr<Simulation>* keep = nullptr) {
  const fs::path dir =
      fs::temp_directory_path() / ("slamsph_momentum_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  RunOptions opt = silent_options(threads);
  opt.write_output = true;
  opt.out_dir = dir.string();
  cfg.output.vtk = false;
  cfg.output.plot.clear();
  cfg.output.snapshots.clear();
  auto sim = std::make_unique<Simulation>(std::move(cfg), opt);
  EXPECT_EQ(sim->run(), 0);
  Balance b;
  b.text = read_file(dir / "momentum.csv");
  b.summary = read_file(dir / "summary.json");
  b.t = read_csv((dir / "momentum.csv").string());
  const std::vector<std::string>& h = b.t.headers;
  for (std::size_t c = 1; c + 1 < h.size(); c += 2) {
    const std::vector<double>& x = b.t.columns[c];
    const std::vector<double>& y = b.t.columns[c + 1];
    for (std::size_t r = 0; r < x.size(); ++r) {
      if (h[c] == "residual x [N s/m]") {
        b.max_residual = std::max({b.max_residual, std::abs(x[r]), std::abs(y[r])});
        b.last_residual = {x[r], y[r]};
      } else if (h[c] == "fluid momentum x [N s/m]") {
        b.scale = std::max(b.scale, std::hypot(x[r] - x[0], y[r] - y[0]));
      } else {
        b.scale = std::max(b.scale, std::hypot(x[r], y[r]));
      }
    }
  }
  EXPECT_EQ(h.back(), "residual y [N s/m]");
  EXPECT_NE(b.summary.find("\"momentum_balance\""), std::string::npos);
  if (keep) *keep = std::move(sim);
  fs::remove_all(dir);
  return b;
}

std::string source(const std::string& rel) {
  return std::string(SLAMSPH_SOURCE_DIR) + "/" + rel;
}

// The elastic cylinder entry (the quick start, coarser and shorter, as the energy test).
CaseConfig cylinder_entry(std::vector<std::string> overrides = {}) {
  overrides.push_back("numerics.end_time=0.015");
  CaseConfig cfg = load_case(source("cases/elastic_cylinder_entry.toml"), overrides);
  rescale_resolution(cfg, 0.01);
  return cfg;
}

// Round-off bound on max |R| / largest term for runs of a few hundred steps: the measured
// values are 4e-16 to 3.5e-15 (printed by each test), so the bound has a margin of ~300;
// the breakages above give 1e-4 to 0.5.
constexpr double kRoundOff = 1e-12;

void expect_closes(const Balance& b, const char* what) {
  std::printf("%s: %zu rows, largest term %.4g N s/m, max |R| %.3g N s/m (%.3g of it)\n", what,
              b.t.rows(), b.scale, b.max_residual, b.max_residual / b.scale);
  EXPECT_GT(b.t.rows(), 5u);
  EXPECT_GT(b.scale, 0.0);
  EXPECT_LT(b.max_residual, kRoundOff * b.scale) << what;
}

}  // namespace

// Sub-cycled elastic cylinder with the kick (the default), a fixed tank and gravity: the
// water's weight goes into the tank, the impact into the cylinder; both close. momentum.csv
// is byte-identical on 1 and 2 threads.
TEST(MomentumBalance, ElasticCylinderEntryClosesToRoundOff) {
  const Balance b = run_and_read(cylinder_entry(), "elastic");
  expect_closes(b, "elastic cylinder, kick");
  EXPECT_GT(b.max_norm("cylinder fluid_impulse"), 0.05 * b.scale) << "the impact must show";
  EXPECT_GT(b.max_norm("fluid momentum", true), 0.05 * b.scale);
  EXPECT_GT(b.max_norm("tank fluid_impulse"), 0.5 * b.scale);
  EXPECT_GT(b.max_norm("fluid gravity_impulse"), 0.5 * b.scale);
  const Balance b2 = run_and_read(cylinder_entry(), "elastic2", 2);
  EXPECT_TRUE(b.text == b2.text) << "momentum.csv differs between 1 and 2 threads";
}

// The same body on the global step (no sub-cycling) and with next_step (the impulse still
// due counted with the body's).
TEST(MomentumBalance, ElasticCylinderGlobalStepAndNextStepClose) {
  expect_closes(run_and_read(cylinder_entry({"numerics.dual_time_stepping=false"}), "global"),
                "elastic cylinder, global step");
  const Balance b =
      run_and_read(cylinder_entry({"numerics.fluid_force_correction=\"next_step\""}), "next");
  expect_closes(b, "elastic cylinder, next_step");
  EXPECT_GT(b.max_norm("cylinder fluid_impulse"), 0.05 * b.scale);
}

TEST(MomentumBalance, RigidFreeCylinderEntryClosesToRoundOff) {
  CaseConfig cfg =
      load_case(source("cases/rigid_cylinder_entry.toml"), {"numerics.end_time=0.015"});
  rescale_resolution(cfg, 0.01);
  const Balance b = run_and_read(cfg, "rigid");
  expect_closes(b, "rigid_free cylinder");
  EXPECT_GT(b.max_norm("cylinder fluid_impulse"), 0.05 * b.scale);
}

TEST(MomentumBalance, PrescribedCylinderClosesToRoundOff) {
  CaseConfig cfg =
      load_case(source("cases/cylinder_constant_speed.toml"), {"numerics.end_time=0.02"});
  rescale_resolution(cfg, 0.01);
  const Balance b = run_and_read(cfg, "prescribed");
  expect_closes(b, "prescribed cylinder");
  EXPECT_GT(b.max_norm("cylinder fluid_impulse"), 0.05 * b.scale);
}

// The elastic gate (clamped at its top, water against it from t = 0): the clamped particles'
// share goes to their support as the water gave it.
TEST(MomentumBalance, ClampedElasticGateClosesToRoundOff) {
  CaseConfig cfg = load_case(source("cases/elastic_gate.toml"),
                             {"numerics.end_time=0.02", "output.interval=0.002"});
  rescale_resolution(cfg, 0.002);
  const Balance b = run_and_read(cfg, "gate");
  expect_closes(b, "clamped elastic gate");
  EXPECT_GT(b.max_norm("gate fluid_impulse"), 0.05 * b.scale);
}

// fluid_force_correction = none: the sub-cycled cylinder never gets dt/2 (F_n+1 − F_n), so
// R = −Σ_n dt_n/2 (F_n+1 − F_n), summed here from the cylinder's load step by step in a
// second, identical run (docs/studies.md §4: the exchange is broken by design).
TEST(MomentumBalance, NoCorrectionShowsTheMissingKick) {
  const std::vector<std::string> none{"numerics.fluid_force_correction=\"none\""};
  const Balance b = run_and_read(cylinder_entry(none), "none");
  CaseConfig cfg = cylinder_entry(none);
  std::size_t cyl = 0;
  Simulation sim(cfg, silent_options(1));
  for (std::size_t k = 0; k < sim.bodies().size(); ++k)
    if (sim.bodies()[k].name == "cylinder") cyl = k;
  Vec2 missing;
  while (sim.time() < cfg.numerics.end_time) {
    const double t0 = sim.time();
    const Vec2 f0 = sim.body_load(cyl).total;
    sim.step();
    missing += (0.5 * (sim.time() - t0)) * (sim.body_load(cyl).total - f0);
  }
  std::printf(
      "elastic cylinder, none: R = (%.6g, %.6g) N s/m, -sum dt/2 dF = (%.6g, %.6g) N s/m, "
      "largest term %.4g N s/m\n",
      b.last_residual.x, b.last_residual.y, -missing.x, -missing.y, b.scale);
  EXPECT_GT(norm(missing), 1e3 * kRoundOff * b.scale) << "the missing kick must be visible";
  EXPECT_NEAR(b.last_residual.x, -missing.x, 1e-6 * norm(missing));
  EXPECT_NEAR(b.last_residual.y, -missing.y, 1e-6 * norm(missing));
}

// A closed channel without gravity whose piston sends a pressure pulse into an absorbing
// zone at the right wall (the absorbing-zone test's channel, shorter): the zone's Σ m Δv
// closes the balance.
TEST(MomentumBalance, AbsorbingZoneMomentumCloses) {
  const char* channel = R"(
schema_version = 1
name = "absorbing_channel"
[numerics]
dx = 0.005
h_over_dx = 1.38
end_time = 0.05
gravity = [0.0, 0.0]
[numerics.domain]
min = [-0.05, -0.05]
max = [0.85, 0.1]
[fluid]
density = 1000.0
sound_speed = 20.0
[fluid.absorbing_zone]
right = 0.15
[[fluid.block]]
min = [0.02, 0.0]
max = [0.8, 0.05]
[[body]]
name = "tank"
kind = "rigid_fixed"
density = 1000.0
[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [0.8, 0.05]
layers = 4
open_top = false
[[body]]
name = "piston"
kind = "rigid_prescribed"
density = 1000.0
motion = [[0.0, 0.0, 0.0], [0.001, 0.1, 0.0], [0.005, 0.1, 0.0], [0.006, 0.0, 0.0]]
[body.shape]
type = "rectangle"
min = [0.0, 0.0]
max = [0.02, 0.05]
[output]
interval = 0.0025
)";
  const Balance b = run_and_read(parse_case_string(channel, "absorbing_channel.toml"), "zone");
  expect_closes(b, "absorbing zone channel");
  EXPECT_GT(b.max_norm("fluid absorbing_zone"), 0.05 * b.scale) << "the zone must take momentum";
}

// The symplectic fluid step (numerics.fluid_integrator, docs/model.md §5) on the dam break at
// CFL 0.5: the tank takes dt times the momentum pass's force, exactly what the water gave up.
// Broken on purpose: the tank credited with the last step's force instead (its impulse taken
// before the momentum pass) made |R| 0.45 % of the largest term; the second half's impulse
// left out (below) 18 %.
TEST(MomentumBalance, SymplecticDamBreakClosesToRoundOff) {
  CaseConfig cfg = load_case(
      source("cases/dam_break.toml"),
      {"numerics.end_time=0.1", "numerics.fluid_integrator=\"symplectic\"", "numerics.cfl=0.5"});
  rescale_resolution(cfg, 0.02);
  const Balance b = run_and_read(cfg, "symplectic");
  expect_closes(b, "symplectic dam break");
  EXPECT_GT(b.max_norm("tank fluid_impulse"), 0.05 * b.scale);
}

// The prescribed cylinder with the symplectic step: moved to mid-step for the momentum pass,
// its support takes dt F_n+1/2.
TEST(MomentumBalance, SymplecticPrescribedCylinderClosesToRoundOff) {
  CaseConfig cfg = load_case(
      source("cases/cylinder_constant_speed.toml"),
      {"numerics.end_time=0.02", "numerics.fluid_integrator=\"symplectic\"", "numerics.cfl=0.5"});
  rescale_resolution(cfg, 0.01);
  const Balance b = run_and_read(cfg, "symplectic_prescribed");
  expect_closes(b, "symplectic prescribed cylinder");
  EXPECT_GT(b.max_norm("cylinder fluid_impulse"), 0.05 * b.scale);
}

// Moving bodies with the symplectic step (docs/model.md §5): advanced in two halves around
// the momentum pass, with the correction dt/2 (F_n+1/2 - F_n-1/2) between them, each receives
// dt F_n+1/2 — the sub-cycled elastic cylinder with the kick and with next_step, the same on
// the global step, and a rigid_free cylinder.
// Broken on purpose: the second half's impulse left out of the stepper's sum made each fail
// (|R| 36 % of the largest term; 50 % for the prescribed cylinder above).
TEST(MomentumBalance, SymplecticMovingBodiesCloseToRoundOff) {
  const std::string sym = "numerics.fluid_integrator=\"symplectic\"", cfl = "numerics.cfl=0.5";
  const Balance b = run_and_read(cylinder_entry({sym, cfl}), "sym_elastic");
  expect_closes(b, "symplectic elastic cylinder, kick");
  EXPECT_GT(b.max_norm("cylinder fluid_impulse"), 0.05 * b.scale) << "the impact must show";
  expect_closes(
      run_and_read(cylinder_entry({sym, cfl, "numerics.fluid_force_correction=\"next_step\""}),
                   "sym_next"),
      "symplectic elastic cylinder, next_step");
  expect_closes(
      run_and_read(cylinder_entry({sym, cfl, "numerics.dual_time_stepping=false"}), "sym_global"),
      "symplectic elastic cylinder, global step");
  CaseConfig rigid =
      load_case(source("cases/rigid_cylinder_entry.toml"), {"numerics.end_time=0.015", sym, cfl});
  rescale_resolution(rigid, 0.01);
  const Balance r = run_and_read(rigid, "sym_rigid");
  expect_closes(r, "symplectic rigid_free cylinder");
  EXPECT_GT(r.max_norm("cylinder fluid_impulse"), 0.05 * r.scale);
}
