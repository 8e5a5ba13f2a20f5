// The cost model's Eulerian path (app/cost_model.h eulerian_particle_ns, eulerian_switched_ns):
// a body whose failed particles start on the Eulerian path (cases/breached_plate.toml's plate,
// a 12 mm slot failed at the start, failed_particles = "eulerian") is costed in the scalar
// loops with the Eulerian terms, against the same body with failed_particles = "lagrangian".
// Predictions only (no run, no timing): the unit tier.
#include <gtest/gtest.h>

#include <string>

#include "app/cost_model.h"
#include "app/simulation.h"
#include "io/case_file.h"
#include "solid/substep_pair_lanes.h"

using namespace slamsph;

namespace {

const BodyCost& plate(const CostPrediction& p) {
  for (const BodyCost& b : p.bodies)
    if (b.name == "plate") return b;
  ADD_FAILURE() << "no body 'plate'";
  return p.bodies.front();
}

CostPrediction predict(const std::string& failed_particles, const CostConstants& k = {}) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/breached_plate.toml");
  for (BodyConfig& b : cfg.bodies)
    if (b.name == "plate") b.failed_particles = failed_particles;
  const Simulation sim(cfg, silent_options(1));
  return predict_cost(sim, k);
}

}  // namespace

// The built body has not made the switch yet (advance_body makes it at the first step), so
// the model makes it on a copy: the slot's 24 failed particles and their reference neighbours
// (28 in all) run the Eulerian path, in the scalar loops. Its sub-steps then cost more than
// the same body's Lagrangian ones (in lanes on an AVX-512F CPU) by at least the factor
// BM_RingSubstepsEulerian measured on a 240-particle ring with fewer switched particles (16:
// 1.45x its Lagrangian path in lanes; 1.80x with 56; session 22, docs/validation.md §6 "Cost
// model"); without the Eulerian terms the model gives 1.26x, with the switch unseen 1.0x.
TEST(CostModel, EulerianBodyCostsTheEulerianPath) {
  const CostPrediction e = predict("eulerian");
  const CostPrediction l = predict("lagrangian");
  const BodyCost& be = plate(e);
  const BodyCost& bl = plate(l);
  ASSERT_EQ(be.particles, 240u);
  EXPECT_GE(be.switched, 24u);
  EXPECT_LE(be.switched, 48u);
  EXPECT_EQ(bl.switched, 0u);
  EXPECT_FALSE(be.lanes);
  EXPECT_EQ(bl.lanes, substep_lanes_avx512_available());
  ASSERT_EQ(e.solid_substeps, l.solid_substeps);
  EXPECT_GT(be.seconds, 1.45 * bl.seconds) << be.seconds << " against " << bl.seconds;
  // The Eulerian terms themselves: per sub-step, per particle and per switched particle.
  CostConstants none;
  none.eulerian_particle_ns = 0.0;
  none.eulerian_switched_ns = 0.0;
  const CostPrediction e0 = predict("eulerian", none);
  const CostConstants k;
  const double term = 1e-9 * static_cast<double>(e.solid_substeps) *
                      (k.eulerian_particle_ns * static_cast<double>(be.particles) +
                       k.eulerian_switched_ns * static_cast<double>(be.switched));
  EXPECT_NEAR(be.seconds - plate(e0).seconds, term, 1e-9 * term);
  EXPECT_GT(term, 0.0);
  // `slamsph check` says so.
  EXPECT_NE(describe_cost(e, 2).find(std::to_string(be.switched) + " particles on the Eulerian"),
            std::string::npos);
}
