// The cost model of `slamsph check` (app/cost_model.h) against actual runs of shipped cases
// cut to a short end time: predicted fluid steps and solid sub-steps within 30 % of the
// steps the run took, and the predicted CPU time, with the constants scaled by this machine's
// factors (measure_machine_factors: built-in probe runs), within a factor of 2 of the CPU
// time the run used on one thread (CPU, not wall, time). Measured in session 10 (machine
// factors water x0.58-0.59, solid x0.62-0.63): still water +48 %, oscillating plate +11 %,
// elastic gate +16 %; without the factors +150 %, +70 %, +95 % (the constants were fitted
// under load on another day: docs/validation.md §6 "Cost model"). With the constants refitted
// in session 18 (factors x0.85-0.94 water, x0.78-0.81 solid): +22 %, +5 %, +25 %, and the
// sub-cycled skin's solid phase +2 %. Run alone (RUN_SERIAL, tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "app/cost_model.h"
#include "app/simulation.h"
#include "coupling/interaction_lists.h"
#include "io/case_file.h"
#include "io/case_resolution.h"
#include "solid/materials/johnson_cook.h"
#include "solid/solid_body.h"

using namespace slamsph;

namespace {

struct Actual {
  long steps = 0;
  long substeps = 0;
  double cpu = 0.0;
};

// This machine's factors against the calibration runs' (app/cost_model.h), measured once.
const MachineFactors& machine() {
  static const MachineFactors f = [] {
    const MachineFactors m = measure_machine_factors();
    std::printf("machine factors: water x%.3g, solid sub-step x%.3g, solid set-up x%.3g\n", m.fluid,
                m.solid, m.solid_call);
    return m;
  }();
  return f;
}

void check_case(const std::string& file, double end_time, double step_tolerance = 0.3) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/" + file);
  cfg.numerics.end_time = end_time;
  Simulation sim(cfg, silent_options(1));
  const CostPrediction p = predict_cost(sim, scaled({}, machine()));
  Actual a;
  const std::clock_t c0 = std::clock();
  while (sim.time() < end_time * (1.0 - 1e-12)) sim.step();
  a.cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  a.steps = sim.steps();
  a.substeps = sim.solid_substeps();
  std::printf(
      "%s to %g s: steps %ld predicted %ld; sub-steps %ld predicted %ld; CPU %.3f s "
      "predicted %.3f s\n",
      file.c_str(), end_time, a.steps, p.fluid_steps, a.substeps, p.solid_substeps, a.cpu,
      p.cpu_seconds());
  EXPECT_NEAR(static_cast<double>(p.fluid_steps) / static_cast<double>(a.steps), 1.0,
              step_tolerance)
      << file;
  if (a.substeps > 0) {
    EXPECT_NEAR(static_cast<double>(p.solid_substeps) / static_cast<double>(a.substeps), 1.0, 0.3)
        << file;
  }
  EXPECT_GT(p.cpu_seconds(), 0.5 * a.cpu) << file;
  EXPECT_LT(p.cpu_seconds(), 2.0 * a.cpu) << file;
  // The text of `slamsph check` carries the numbers.
  const std::string text = describe_cost(p, 2);
  EXPECT_NE(text.find(std::to_string(p.fluid_steps) + " fluid steps"), std::string::npos) << text;
}

// Water at rest falls nowhere: its step is the acoustic step of water at rest (the speed
// bound sqrt(2 g H) over the water's depth had predicted 15 % more steps, 335 against 290 to
// 0.05 s; docs/validation.md §6 "Cost model", session 14).
TEST(CostModel, StillWater) {
  check_case("cases/still_water.toml", 0.05, 0.05);
}

TEST(CostModel, OscillatingPlateNoWater) {
  check_case("cases/oscillating_plate.toml", 0.004);
}

TEST(CostModel, ElasticGate) {
  check_case("cases/elastic_gate.toml", 0.004);
}

// A body that takes ~190 sub-steps per fluid step (the 2-layer aluminium skin of the reduced
// fuselage case, 2 500 particles, 3.0 pair entries per particle): the solid phase's predicted
// CPU time against the phase's measured time on one thread, within the target's 30 %. The
// machine factor comes from the 2 000-particle plate probe (3.88 entries per particle) at
// 40 sub-steps per call. Session 13, four runs on the idle machine: -12, +5, -11, +8 %
// (the machine's own speed varied by 20 % between them; the probes follow it). The
// unscaled constants would be +49 to +81 %; a cost per particle taken from the plate, +29 %
// more; one factor for the call and the sub-step from one sub-step per call (session 12)
// over-predicted the fuselage skins by 16-86 % (docs/validation.md §6 "Cost model").
TEST(CostModel, SubCycledBodyTheSolidPhase) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/skin_ring_reduced.toml");
  cfg.numerics.end_time = 4e-4;
  Simulation sim(cfg, silent_options(1));
  const CostPrediction p = predict_cost(sim, scaled({}, machine()));
  while (sim.time() < cfg.numerics.end_time * (1.0 - 1e-12)) sim.step();
  const double measured = sim.stepper().phase_times().solid_substeps;
  std::printf(
      "skin_ring_reduced to 0.4 ms: sub-steps %ld predicted %ld; solid phase %.3f s "
      "predicted %.3f s\n",
      sim.solid_substeps(), p.solid_substeps, measured, p.solid_seconds);
  ASSERT_GT(sim.solid_substeps(), 100 * sim.steps());
  EXPECT_NEAR(static_cast<double>(p.solid_substeps) / static_cast<double>(sim.solid_substeps()),
              1.0, 0.05);
  EXPECT_NEAR(p.solid_seconds / measured, 1.0, 0.3);
}

// The height the water can fall (the step's speed bound, app/cost_model.h), from the built
// geometry: none for still water; a dam-break column's height (the tank floor beside it is
// dry; between the particle centres); the water over a breached plate down to the chamber's
// floor below the slot (debris does not hold it).
TEST(CostModel, FallHeight) {
  auto fall = [](const char* file) {
    const CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/" + file);
    const Simulation sim(cfg, silent_options(1));
    return std::pair{predict_cost(sim).fall_height, cfg.numerics.dx};
  };
  const auto [still, dx_still] = fall("cases/still_water.toml");
  EXPECT_LT(still, 0.5 * dx_still);
  const auto [peer, dx_peer] = fall("bench/dam_break_peer.toml");
  EXPECT_NEAR(peer, 1.0 - dx_peer, 1e-9);  // the 1 m column, centre to centre
  const auto [breach, dx_breach] = fall("cases/breached_plate.toml");
  EXPECT_NEAR(breach, 0.262 - 0.5 * dx_breach, 2.0 * dx_breach);  // the top to the tank floor
}

// The water that falls spreads over the dry floor and the fluid–contact pairs grow with the
// wetted length: the dam break's (cases/dam_break.toml, to its end: 7 131 steps) from 5 382
// to 9 352, 7 147 on average. The predicted mean within 20 % of the run's (the initial
// count alone: -25 %).
TEST(CostModel, SpreadingWaterContactPairs) {
  const CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/dam_break.toml");
  Simulation sim(cfg, silent_options(1));
  const CostPrediction p = predict_cost(sim);
  double sum = 0.0;
  while (sim.time() < cfg.numerics.end_time * (1.0 - 1e-12)) {
    sim.step();
    const InteractionLists& l = sim.stepper().lists();
    sum += static_cast<double>(l.fc().index.size() + l.cf().index.size());
  }
  const double mean = sum / static_cast<double>(sim.steps());
  std::printf(
      "dam_break: contact pairs at the start %zu, mean over the run %.0f, predicted %.0f "
      "(at rest %.0f, spread in %.3g s)\n",
      p.contact_pairs, mean, p.contact_pairs_mean, p.contact_pairs_rest, p.spread_seconds);
  EXPECT_NEAR(p.contact_pairs_mean / mean, 1.0, 0.2);
}

}  // namespace

// A Johnson–Cook body's sub-steps cost an SVK body's plus the law's elastic path per
// particle-sub-step (the same fuselage section in both materials, water coarsened to keep the
// test short; no clamps, so no yield is estimated).
TEST(CostModel, JohnsonCookSubstepsCostTheLawsElasticPath) {
  auto per_substep = [](const char* file) {
    CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/" + file);
    cfg.numerics.dx = 0.012;
    Simulation sim(cfg, silent_options(1));
    CostConstants k;
    k.solid_call_ns = 0.0;  // the per-call set-up does not depend on the law
    const CostPrediction p = predict_cost(sim, k);
    double n = 0.0;
    for (const BodyCost& b : p.bodies)
      if (b.elastic) {
        n += static_cast<double>(b.particles);
        EXPECT_EQ(b.yield_fraction, 0.0) << b.loading;
      }
    return p.solid_seconds / (n * static_cast<double>(p.solid_substeps));
  };
  const double svk = per_substep("cases/fuselage/skin_I_floor_column.toml");
  const double jc = per_substep("cases/fuselage/elastic_plastic_I_floor_column.toml");
  EXPECT_NEAR(jc - svk, 1e-9 * CostConstants{}.johnson_cook_elastic_ns, 1e-15);
  // BM_RingSubstepsJohnsonCook against BM_RingSubsteps: 94.3 against 26.4 ns (session 20).
  EXPECT_GT(CostConstants{}.johnson_cook_elastic_ns, 30.0);
}

namespace {

// Per step of a run of `cfg` on one thread: the fraction of the first Johnson–Cook body's
// particles whose plastic strain grew in the step, averaged over the steps (= over its
// particle-sub-steps: one sub-step per step without water), the step count and the time of
// its first failed particle (+inf: none).
struct Yielding {
  double fraction = 0.0;
  double first_failure = std::numeric_limits<double>::infinity();
  double first_yield = std::numeric_limits<double>::infinity();
};
Yielding count_yielding(const CaseConfig& cfg) {
  Simulation sim(cfg, silent_options(1));
  const auto body = [&]() -> const SolidBody& { return sim.bodies().front(); };
  const std::vector<double>* ep = &body().history.values[JohnsonCook::kPlasticStrain];
  Yielding y;
  double sum = 0.0;
  while (sim.time() < cfg.numerics.end_time * (1.0 - 1e-12)) {
    const std::vector<double> before = *ep;
    sim.step();
    ep = &body().history.values[JohnsonCook::kPlasticStrain];
    std::size_t grew = 0;
    for (std::size_t i = 0; i < before.size(); ++i) grew += (*ep)[i] > before[i];
    sum += static_cast<double>(grew) / static_cast<double>(before.size());
    if (grew > 0) y.first_yield = std::min(y.first_yield, sim.time());
    const std::vector<double>& failed = body().history.values[JohnsonCook::kFailed];
    if (std::isinf(y.first_failure) &&
        std::any_of(failed.begin(), failed.end(), [](double f) { return f > 0.5; }))
      y.first_failure = sim.time();
  }
  y.fraction = sum / static_cast<double>(std::max(1L, sim.steps()));
  return y;
}

}  // namespace

// The yield and damage of a Johnson–Cook body estimated from its loading (app/cost_model.h)
// against a run that counts them. The Johnson–Cook bar (150 m/s from its clamp, 21 m/s yield
// speed: an impact) yields behind the elastic front and fails at the clamp within the
// front's crossing (von Kármán's strain 0.23 against the failure strain 0.19): counted
// (session 20) 15 % of its particle-sub-steps yield, first failure at 11.7 µs; estimated
// 10 % and 18.8 µs. A model without yield (0 %) or without failure fails here.
TEST(CostModel, JohnsonCookBarYieldAndFailureFromTheLoading) {
  const CaseConfig cfg =
      load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/johnson_cook_bar.toml");
  const Simulation sim(cfg, silent_options(1));
  const CostPrediction p = predict_cost(sim);
  ASSERT_EQ(p.bodies.size(), 1u);
  const BodyCost& b = p.bodies.front();
  const Yielding y = count_yielding(cfg);
  std::printf(
      "johnson_cook_bar: yielding particle-sub-steps %.3f estimated %.3f; first failure at "
      "%.3g s estimated %.3g s (%s)\n",
      y.fraction, b.yield_fraction, y.first_failure, b.damage_start, b.loading.c_str());
  EXPECT_EQ(b.loading, "impact");
  EXPECT_NEAR(b.yield_fraction / y.fraction, 1.0, 0.5);
  EXPECT_GT(b.damage_start, 0.5 * y.first_failure);
  EXPECT_LT(b.damage_start, 2.0 * y.first_failure);
  // Their cost: the yielding particle-sub-steps (in the solid phase) and the failure zone's
  // gathers from the damage on (in the contact phase), against the same prediction without
  // those costs.
  CostConstants k0;
  k0.johnson_cook_yield_ns = 0.0;
  k0.failure_zone_ns = 0.0;
  const CostPrediction p0 = predict_cost(sim, k0);
  const CostConstants k;
  const double n = static_cast<double>(b.particles);
  const double steps = static_cast<double>(p.fluid_steps);
  const double T = cfg.numerics.end_time;
  EXPECT_NEAR(
      p.solid_seconds - p0.solid_seconds,
      1e-9 * k.johnson_cook_yield_ns * n * static_cast<double>(p.solid_substeps) * b.yield_fraction,
      1e-12);
  EXPECT_NEAR(p.contact_seconds - p0.contact_seconds,
              1e-9 * k.failure_zone_ns * n * steps * (T - b.damage_start) / T, 1e-12);
  EXPECT_GT(p.contact_seconds - p0.contact_seconds, 0.0);
  EXPECT_GT(p.solid_seconds - p0.solid_seconds, 0.0);
}

// The notched specimen pulled at ±1 m/s over its 30 mm gauge (67 /s, slow against its
// 21 m/s yield speed): it starts to yield at ε_y / rate and keeps yielding between the grips;
// at a coarser spacing (dx 0.5 mm, to 150 µs: 1.5 s) the run counts the first yield and the
// fraction. Counted at full size (session 14): yield from ~40 µs at the notch roots, 53-66 %
// of the particles from 90 µs, 47 % of the particle-sub-steps over 300 µs; estimated 60 µs
// and 60 %. The nominal strain does not reach the failure strain in the run (the notch's
// first failure at 250 µs, 4 particles, is not seen: its cost is small).
TEST(CostModel, JohnsonCookNotchedYieldFromTheLoading) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/johnson_cook_notched.toml");
  rescale_resolution(cfg, 0.0005);
  cfg.numerics.end_time = 1.5e-4;
  const Simulation sim(cfg, silent_options(1));
  const CostPrediction p = predict_cost(sim);
  const BodyCost& b = p.bodies.front();
  const Yielding y = count_yielding(cfg);
  std::printf(
      "johnson_cook_notched (dx 0.5 mm, to 150 us): yielding particle-sub-steps %.3f "
      "estimated %.3f; first yield at %.3g s estimated %.3g s; damage estimated at %.3g s "
      "(%s)\n",
      y.fraction, b.yield_fraction, y.first_yield, b.yield_start, b.damage_start,
      b.loading.c_str());
  EXPECT_EQ(b.loading, "clamps pulled apart");
  EXPECT_GT(b.yield_start, y.first_yield);  // the notch roots yield first
  EXPECT_LT(b.yield_start, 3.0 * y.first_yield);
  EXPECT_NEAR(b.yield_fraction / y.fraction, 1.0, 0.5);
  EXPECT_GT(b.damage_start, cfg.numerics.end_time);
  EXPECT_EQ(b.failure_seconds, 0.0);
}
