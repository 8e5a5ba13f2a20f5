// Fluid–structure coupling (spec §4, §6): exact momentum exchange through an impact,
// no leak through a two-particle-thick plate, and the dual-time-stepping switch.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

using namespace slamsph;

namespace {

// A disc moving at 2 m/s into a free water block, no gravity, no walls.
std::string impact_case(const std::string& kind) {
  return R"(
schema_version = 1
name = "impact"
[numerics]
dx = 0.01
end_time = 0.03
gravity = [0.0, 0.0]
[numerics.domain]
min = [-0.5, -0.5]
max = [1.0, 1.0]
[fluid]
density = 1000.0
sound_speed = 30.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.4, 0.2]
[materials.rubber]
density = 1100.0
youngs_modulus = 1.2e7
poisson_ratio = 0.4
[[body]]
name = "disc"
kind = ")" +
         kind +
         R"("
material = "rubber"
velocity = [0.0, -2.0]
[body.shape]
type = "disc"
centre = [0.2, 0.26]
radius = 0.06
)";
}

double momentum_scale(const Simulation& sim) {
  double s = 0.0;
  for (std::size_t i = 0; i < sim.fluid().size(); ++i)
    s += sim.fluid().m[i] * norm(sim.fluid().v[i]);
  for (const SolidBody& b : sim.bodies())
    for (std::size_t i = 0; i < b.size(); ++i) s += b.m[i] * norm(b.v[i]);
  return s;
}

void expect_momentum_conserved(const std::string& kind,
                               const std::vector<std::string>& overrides = {}) {
  Simulation sim(parse_case_string(impact_case(kind), "impact.toml", overrides), silent_options(1));
  const Vec2 p0 = sim.total_momentum();
  double max_force = 0.0;
  while (sim.time() < 0.03) {
    sim.step();
    max_force = std::max(max_force, norm(sim.body_load(0).total));
  }
  const Vec2 p1 = sim.total_momentum();
  const double scale = momentum_scale(sim);
  std::printf(
      "%s: momentum change (%.3g, %.3g) kg m/s per m over %ld steps; scale %.3g; peak force %.0f "
      "N/m\n",
      kind.c_str(), p1.x - p0.x, p1.y - p0.y, sim.steps(), scale, max_force);
  EXPECT_GT(max_force, 500.0);                     // there was an impact
  EXPECT_GT(sim.total_momentum().y, p0.y - 1e-9);  // and it is the same momentum
  EXPECT_LT(std::abs(p1.x - p0.x), 1e-10 * scale);
  EXPECT_LT(std::abs(p1.y - p0.y), 1e-10 * scale);
  // The water gained downward momentum from the disc.
  Vec2 pf;
  for (std::size_t i = 0; i < sim.fluid().size(); ++i) pf += sim.fluid().m[i] * sim.fluid().v[i];
  EXPECT_LT(pf.y, -0.05 * std::abs(p0.y));
}

// Water 0.3 m deep left of a vertical rigid plate two particles thick (body spacing half
// the water's, so the plate is one water spacing thick); optionally water 0.15 m deep on
// its right too. 0.5 s.
std::string thin_plate_case(bool wet_right) {
  std::string t = R"(
schema_version = 1
name = "thin_plate"
[numerics]
dx = 0.01
end_time = 0.5
[numerics.domain]
min = [-0.1, -0.1]
max = [0.7, 0.6]
[fluid]
density = 1000.0
sound_speed = 25.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.3, 0.3]
)";
  if (wet_right) t += "[[fluid.block]]\nmin = [0.31, 0.0]\nmax = [0.61, 0.15]\n";
  t += R"(
[[body]]
name = "tank"
kind = "rigid_fixed"
[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [0.61, 0.5]
[[body]]
name = "plate"
kind = "rigid_fixed"
dx = 0.005
[body.shape]
type = "rectangle"
min = [0.3, 0.0]
max = [0.31, 0.45]
)";
  return t;
}

}  // namespace

TEST(Coupling, RigidBodyImpactConservesMomentumToRoundOff) {
  expect_momentum_conserved("rigid_free");
}

TEST(Coupling, ElasticBodyImpactConservesMomentumToRoundOff) {
  expect_momentum_conserved("elastic");
}

// numerics.fluid_force_correction = "next_step" (docs/model.md §5): the sub-cycled disc gets
// dt/2 (F_n+1 - F_n) as a force over the next step; counting the impulse still due to it
// (Simulation::total_momentum), the exchange stays exact. Broken on purpose: leaving the due
// impulse out of total_momentum fails this test (the momentum error is then 1.4e-3 of scale).
TEST(Coupling, ElasticBodyNextStepCorrectionConservesMomentumToRoundOff) {
  expect_momentum_conserved("elastic", {"numerics.fluid_force_correction=\"next_step\""});
}

TEST(Coupling, ThinPlateDoesNotLeak) {
  // Water 0.3 m deep against a vertical plate two particles thick (body spacing half the
  // water's, so the plate is one water spacing thick); dry on the other side. 0.5 s.
  Simulation sim(parse_case_string(thin_plate_case(false), "thin_plate.toml"), silent_options(1));
  double max_x = 0.0;
  while (sim.time() < 0.5) {
    sim.step();
    for (const Vec2& x : sim.fluid().x) max_x = std::max(max_x, x.x);
  }
  std::printf(
      "leaked %ld, largest water x %.4f m (plate face at 0.3 m), plate force %.1f N/m (rho g H^2/2 "
      "= %.1f)\n",
      sim.leaked_particles(), max_x, sim.body_load(1).total.x, 1000 * 9.81 * 0.09 / 2);
  EXPECT_EQ(sim.leaked_particles(), 0);
  EXPECT_LT(max_x, 0.3);
  // Hydrostatic thrust on the plate, rho g H^2 / 2: measured -7.4 % with this two-layer
  // plate and its ghost layers, -3.9 % with a four-layer plate (the same deficit as the
  // tank's own wall: the kernel-smoothed corners at the floor and the free surface).
  EXPECT_NEAR(sim.body_load(1).total.x / (1000 * 9.81 * 0.09 / 2), 1.0, 0.10);
}

TEST(Coupling, ThinPlateWetOnBothSidesDoesNotLeak) {
  // The same two-particle plate with water on both sides at different depths (0.3 m and
  // 0.15 m): each side must keep its particles (ghost layers act one side at a time).
  Simulation sim(parse_case_string(thin_plate_case(true), "thin_plate_two_sides.toml"),
                 silent_options(1));
  // Ids are assigned block by block: the first block's particles are the left side.
  std::int64_t left_count = 0;
  for (std::size_t i = 0; i < sim.fluid().size(); ++i) left_count += sim.fluid().x[i].x < 0.3;
  long wrong_side = 0;
  while (sim.time() < 0.5) sim.step();
  for (std::size_t i = 0; i < sim.fluid().size(); ++i) {
    const bool left_id = sim.fluid().id[i] < left_count;
    const double x = sim.fluid().x[i].x;
    wrong_side += left_id ? x > 0.3 : x < 0.31;
  }
  const double expected = 1000 * 9.81 * (0.09 - 0.0225) / 2;  // net thrust, left minus right
  std::printf("leaked %ld, particles on the wrong side %ld, net plate force %.1f N/m (%.1f)\n",
              sim.leaked_particles(), wrong_side, sim.body_load(1).total.x, expected);
  EXPECT_EQ(sim.leaked_particles(), 0);
  EXPECT_EQ(wrong_side, 0);
  EXPECT_GT(sim.body_load(1).total.x, 0.5 * expected);  // pushed towards the shallow side
}

TEST(Coupling, DualTimeSteppingMatchesGlobalStep) {
  // Elastic cylinder entry at reduced resolution, 5 ms (the slamming peak), both ways.
  auto run = [](bool dual, double& seconds) {
    CaseConfig cfg =
        load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/elastic_cylinder_entry.toml");
    rescale_resolution(cfg, 0.01);
    // Touching the surface at t = 0 at 2.33 m/s: this compares two time-stepping schemes
    // over the slam, not the entry (the shipped case starts above the water).
    cfg.bodies[1].shape.centre.y = 0.5;
    cfg.bodies[1].velocity = {0.0, -2.33};
    cfg.numerics.end_time = 0.005;
    cfg.numerics.dual_time_stepping = dual;
    Simulation sim(cfg, silent_options(1));
    const int c = 1;  // the cylinder
    double peak = 0.0;
    const auto t0 = std::chrono::steady_clock::now();
    while (sim.time() < cfg.numerics.end_time) {
      sim.step();
      peak = std::max(peak, sim.body_load(c).total.y);
    }
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return peak;
  };
  double t_dual = 0.0, t_single = 0.0;
  const double dual = run(true, t_dual), single = run(false, t_single);
  std::printf(
      "peak force: dual %.1f N/m (%.2f s), single step %.1f N/m (%.2f s), difference %.2f %%, "
      "speed-up %.2f\n",
      dual, t_dual, single, t_single, 100 * (dual / single - 1), t_single / t_dual);
  EXPECT_NEAR(dual / single, 1.0, 0.02);
}
