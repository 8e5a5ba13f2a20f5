// Water through a breached skin (issue 11; docs/model.md §4 "Ghosts around a failure";
// cases/breached_plate.toml): a 2-layer aluminium plate 2 mm thick (water 2x coarser) under 0.06 m
// of water with a 12 mm slot that starts failed (`[body.pre_failed]`, Eulerian switch). The failed
// particles are debris; the water pushes them out and drains through the slot. What must hold:
//   - every water particle that reaches the plate's underside does so through the slot
//     (its x within a water spacing of the slot when it first passes the plate's bottom
//     face): no leak elsewhere, in particular not at the re-planned ghosts of the slot faces;
//   - the leak counter stays 0: water next to debris (failed particles, whose colour-gradient
//     normal is zero or arbitrary) and in the slot is not counted as leaked;
//   - water does drain, at a rate within [0.4, 1.2] of the 2D orifice estimate
//     Q = C_c w sqrt(2 g H), C_c = π/(π + 2), w the slot's 12 mm, H the depth above it.
//     The measured rate depends on the debris left at the slot's edges (the switched intact
//     edge particles keep tension and hold some failed ones, narrowing the slot by about a
//     particle each side) and on the six water particles across the slot: this is a range,
//     not a validation of the discharge coefficient.
// Reduced for CI: end 0.12 s instead of 0.15 s, and the plate's Young's modulus and bulk sound
// speed 100x and 10x lower (10x fewer solid sub-steps; its deflection under 600 Pa stays
// ~2e-5 m), a plate that only holds the water and lets the slot open. Broken on purpose (see
// docs/model.md §4): failed particles kept in the leak judgement → `leaked` > 0; the
// reference ghosts kept around the failure (no re-plan) → water crosses beside the slot;
// failed_particles = "lagrangian" (the slot stays plugged) → no drain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include "app/simulation.h"
#include "io/case_file.h"

using namespace slamsph;

namespace {

constexpr double kPlateBottom = 0.2, kSlotMin = 0.054, kSlotMax = 0.066, kDx = 0.002;
constexpr double kPlateTop = 0.202;

struct Drain {
  long worst_leaked = 0;
  int outside_slot = 0;    // particles that first passed the plate's underside beside the slot
  int through = 0;         // particles that passed it at all
  double first_time = -1;  // first water below the plate [s]
  double q = 0.0;          // drain rate over the last 30 ms [m^2/s]
  double depth = 0.0;      // water depth above the plate at the end [m]
};

Drain run(const std::vector<std::string>& extra) {
  std::vector<std::string> overrides{"materials.al.youngs_modulus=0.73e9",
                                     "materials.al.eos_sound_speed=532.8", "numerics.end_time=0.12",
                                     "output.vtk=false", "output.snapshots=[0.05]"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());  // later ones win
  CaseConfig cfg =
      load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/breached_plate.toml", overrides);
  Simulation sim(std::move(cfg), silent_options(1));
  Drain d;
  std::unordered_map<long, double> passed;  // fluid id -> x where it first passed
  auto volume_below = [&] {
    double v = 0.0;
    const FluidParticles& f = sim.fluid();
    for (std::size_t i = 0; i < f.size(); ++i)
      if (f.x[i].y < kPlateBottom) v += f.m[i] / f.rho[i];
    return v;
  };
  double v_mark = -1.0, t_mark = 0.0;
  const double end = sim.config().numerics.end_time;
  while (sim.time() < end - 1e-12) {
    sim.step();
    d.worst_leaked = std::max(d.worst_leaked, sim.leaked_particles());
    const FluidParticles& f = sim.fluid();
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (f.x[i].y >= kPlateBottom || passed.count(f.id[i])) continue;
      passed[f.id[i]] = f.x[i].x;
      if (d.first_time < 0) d.first_time = sim.time();
      if (f.x[i].x < kSlotMin - kDx || f.x[i].x > kSlotMax + kDx) ++d.outside_slot;
    }
    if (v_mark < 0 && sim.time() >= end - 0.03) v_mark = volume_below(), t_mark = sim.time();
  }
  d.through = static_cast<int>(passed.size());
  // The case's `fluid_volume` probe ("drained", box below the plate) reads the same volume.
  EXPECT_NEAR(sim.probe_value(0), volume_below(), 1e-12 * (1e-6 + volume_below()));
  d.q = (volume_below() - v_mark) / (sim.time() - t_mark);
  double top = 0.0;
  const FluidParticles& f = sim.fluid();
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f.x[i].x < 0.01) top = std::max(top, f.x[i].y + 0.5 * kDx);
  d.depth = top - kPlateTop;
  std::printf(
      "breached plate: %d particles through (%d beside the slot), first below at %.4f s, drain "
      "%.4g m^2/s over the last 30 ms, depth %.4f m, leaked at most %ld\n",
      d.through, d.outside_slot, d.first_time, d.q, d.depth, d.worst_leaked);
  return d;
}

}  // namespace

TEST(BreachedPlate, WaterDrainsThroughTheSlotOnlyAndNothingCountsAsLeaked) {
  const Drain d = run({});
  EXPECT_EQ(d.worst_leaked, 0);
  EXPECT_EQ(d.outside_slot, 0);
  ASSERT_GT(d.through, 50) << "the water must drain for the test to mean anything";
  const double cc = M_PI / (M_PI + 2.0);
  const double q_orifice = cc * (kSlotMax - kSlotMin) * std::sqrt(2.0 * 9.81 * d.depth);
  std::printf("orifice estimate %.4g m^2/s, measured / estimate %.3f\n", q_orifice,
              d.q / q_orifice);
  EXPECT_GT(d.q, 0.4 * q_orifice);
  EXPECT_LT(d.q, 1.2 * q_orifice);
}

TEST(BreachedPlate, LagrangianFailedParticlesKeepTheSlotPlugged) {
  // The same breach with the failed particles kept in the total-Lagrangian sums: they carry
  // no tension but stay bonded to their neighbours, so the slot does not open. Shows that
  // the drain above is the Eulerian switch's doing, not water passing a plugged slot.
  const Drain d = run({"body[1].failed_particles=\"lagrangian\"", "numerics.end_time=0.06"});
  EXPECT_EQ(d.worst_leaked, 0);
  EXPECT_EQ(d.through, 0);
}
