// Normals of the faces a crack opens (coupling/surface_normals.h update_normals_near_failure,
// called by gather_body_state; spec §5, docs/model.md §4 "Leak counter"): a Johnson–Cook bar
// whose halves are pulled apart across a failed column (solid/eulerian_failed_interaction.h)
// exposes two interior columns. After the opening their contact normals point out of each
// piece into the gap, while particles away from the failed ones keep the reference normals
// carried by Nanson's rule (zero inside, ±y on the top and bottom faces); before any failure
// the gathered normals are the reference ones (Nanson at F = I, to 1e-12).
#include <gtest/gtest.h>

#include <vector>

#include "core/parallel.h"
#include "coupling/contact_layout.h"
#include "coupling/surface_normals.h"
#include "solid/materials/material_presets.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.001;
constexpr int kNx = 40, kNy = 10, kBand = 20;

SolidBody bar() {
  ElasticMaterialInput m;
  m.name = "al";
  JohnsonCookModel jc = kAl2024T3.model;
  jc.failure = FailureModel{};  // only the marked column fails
  m.model = jc;
  m.density = kAl2024T3.density;
  m.youngs_modulus = kAl2024T3.youngs_modulus;
  m.poisson_ratio = kAl2024T3.poisson_ratio;
  BodySetup cfg;
  cfg.gravity = false;
  return make_body(box_lattice(kNx, kNy, kDx), kDx, "tl_sfpm", m, cfg);
}

std::vector<Vec2> gathered_normals(const std::vector<SolidBody>& bodies) {
  std::vector<std::vector<Vec2>> ref;
  for (const SolidBody& b : bodies) ref.push_back(reference_surface_normals(b.X, b.V0, b.kernel));
  ContactLayout layout = plan_contact_layout(bodies, ref, bodies[0].kernel.support());
  replan_around_failures(layout, bodies);  // as every rate evaluation does before the gather
  ContactParticles c;
  init_contact_particles(c, layout);
  gather_body_state(c, layout, bodies);
  return std::vector<Vec2>(c.normal.begin(), c.normal.begin() + bodies[0].size());
}

int col(std::size_t i) {
  return static_cast<int>(i % kNx);
}
int row(std::size_t i) {
  return static_cast<int>(i / kNx);
}

}  // namespace

TEST(CouplingCrackNormals, OpenedFacesGetNormalsIntoTheGap) {
  std::vector<SolidBody> bodies{bar()};
  SolidBody& b = bodies[0];
  const std::vector<Vec2> before = gathered_normals(bodies);
  const std::vector<Vec2> ref = reference_surface_normals(b.X, b.V0, b.kernel);
  for (std::size_t i = 0; i < b.size(); ++i) {
    EXPECT_NEAR(before[i].x, ref[i].x, 1e-12) << i;  // F = I to round-off: Nanson keeps N
    EXPECT_NEAR(before[i].y, ref[i].y, 1e-12) << i;
  }
  for (std::size_t i = 0; i < b.size(); ++i)
    b.v[i] = Vec2{col(i) > kBand ? 200.0 : (col(i) < kBand ? -200.0 : 0.0), 0.0};
  std::vector<double>& failed = b.history.values[8];
  ASSERT_EQ(b.history.fields[8].name, "failed");
  for (std::size_t i = 0; i < b.size(); ++i)
    if (col(i) == kBand) failed[i] = 1.0;
  refresh_internal_forces(b, Executor(1));
  for (int s = 0; s < 20; ++s) advance_body(b, s * 1e-6, 1e-6, Vec2{}, Executor(1));
  const std::vector<Vec2> after = gathered_normals(bodies);
  // The exposed faces: the last column of the left piece and the first of the right one
  // (interior rows, away from the corners), which had no normal in the reference state.
  int faces = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (row(i) < 2 || row(i) >= kNy - 2) continue;
    if (col(i) == kBand - 1) {
      EXPECT_EQ(ref[i].x, 0.0);
      EXPECT_GT(after[i].x, 0.9) << "left face " << i;
      ++faces;
    }
    if (col(i) == kBand + 1) {
      EXPECT_LT(after[i].x, -0.9) << "right face " << i;
      ++faces;
    }
    // Far from the failed column: the Nanson normal (zero inside the pieces).
    if (col(i) == 5 || col(i) == kNx - 6) {
      EXPECT_EQ(norm(after[i]), 0.0) << i;
    }
  }
  EXPECT_EQ(faces, 2 * (kNy - 4));
}
