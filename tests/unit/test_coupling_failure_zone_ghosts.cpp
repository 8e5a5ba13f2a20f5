// Ghosts around a failure (coupling/failure_zone_ghosts.h, coupling/contact_layout.h
// replan_around_failures; docs/model.md §4 "Ghosts around a failure"). A 2-layer Johnson–Cook
// plate of 1 mm particles (thinner than the 5.2 mm contact support, so its surfaces carry
// ghosts) with a slot of four failed columns (`pre_failed_boxes`), whose failed particles have
// left (moved 50 mm down, as the debris does in cases/breached_plate.toml). The faces of the
// slot then have current normals along the plate. With the reference plan their ghosts are
// placed along those normals, inside the intact plate beside the slot (the over-filled support
// at a crack mouth that docs/model.md §7 described); with the re-plan none is, the surface
// particles away from the slot keep exactly their reference ghosts, the failed particles carry
// none and are marked debris, and the layout is a function of the failed flags alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/box.h"
#include "coupling/contact_layout.h"
#include "coupling/surface_normals.h"
#include "solid/eulerian_failed_interaction.h"
#include "solid/materials/material_presets.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kD = 0.001, kSupport = 0.0052, kFluidDx = 0.002;
constexpr int kNx = 60, kSlot0 = 28, kSlot1 = 31;  // failed columns 28..31

int col(std::size_t i) {
  return static_cast<int>(i % kNx);
}

std::vector<SolidBody> breached_plate() {
  ElasticMaterialInput m;
  m.name = "al";
  m.model = kAl2024T3.model;
  m.density = kAl2024T3.density;
  m.youngs_modulus = kAl2024T3.youngs_modulus;
  m.poisson_ratio = kAl2024T3.poisson_ratio;
  BodySetup cfg;
  cfg.gravity = false;
  cfg.pre_failed_boxes = {Box{{kSlot0 * kD, -kD}, {(kSlot1 + 1) * kD, 3 * kD}}};
  std::vector<SolidBody> bodies{make_body(box_lattice(kNx, 2, kD), kD, "tl_sfpm", m, cfg)};
  SolidBody& b = bodies[0];
  const std::vector<double>& failed = *failed_flags(b);
  for (std::size_t i = 0; i < b.size(); ++i)
    if (failed[i] > 0.5) b.x[i].y -= 0.05;  // the debris has left the slot
  return bodies;
}

ContactLayout reference_layout(const std::vector<SolidBody>& bodies) {
  std::vector<std::vector<Vec2>> ref;
  for (const SolidBody& b : bodies) ref.push_back(reference_surface_normals(b.X, b.V0, b.kernel));
  return plan_contact_layout(bodies, ref, kSupport, kFluidDx);
}

ContactParticles gathered(const ContactLayout& layout, const std::vector<SolidBody>& bodies) {
  ContactParticles c;
  init_contact_particles(c, layout);
  gather_body_state(c, layout, bodies);
  return c;
}

// Active ghosts (non-zero volume) closer than 0.75 d to an intact particle of the plate: they
// sit inside the plate, where the plate itself fills the water's support.
int ghosts_inside(const ContactParticles& c, const ContactLayout& l, const SolidBody& b) {
  const std::vector<double>& failed = *failed_flags(b);
  int inside = 0;
  for (std::size_t g = l.first_ghost(); g < c.size(); ++g) {
    if (!(c.volume[g] > 0.0)) continue;
    for (std::size_t i = 0; i < b.size(); ++i)
      if (failed[i] < 0.5 && norm2(c.x[g] - b.x[i]) < 0.5625 * kD * kD) {
        ++inside;
        break;
      }
  }
  return inside;
}

// The active ghosts of particle p: positions and volumes, sorted.
std::vector<std::pair<double, double>> ghosts_of(const ContactParticles& c, const ContactLayout& l,
                                                 std::size_t p) {
  std::vector<std::pair<double, double>> out;
  for (std::size_t g = l.first_ghost(); g < c.size(); ++g)
    if (c.local[g] == p && c.volume[g] > 0.0) out.push_back({c.x[g].y, c.volume[g]});
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(FailureZoneGhosts, SlotFacesGetNoGhostsInsideThePlateAndFarParticlesKeepTheirs) {
  const std::vector<SolidBody> bodies = breached_plate();
  const SolidBody& b = bodies[0];
  ContactLayout re = reference_layout(bodies);
  ASSERT_TRUE(replan_around_failures(re, bodies));
  // What a reference plan does there: the zone's current normals with the reference ghosts.
  ContactLayout ref = re;
  ref.ghosts = ref.reference_ghosts;
  const ContactParticles before = gathered(ref, bodies);
  const ContactParticles after = gathered(re, bodies);
  const int inside_ref = ghosts_inside(before, ref, b), inside_re = ghosts_inside(after, re, b);
  std::printf("ghosts: reference %zu, re-planned %zu; inside the plate: %d -> %d\n",
              ref.ghosts.size(), re.ghosts.size(), inside_ref, inside_re);
  // One per face particle of the slot (4): the defect the re-plan removes must show.
  EXPECT_GE(inside_ref, 4) << "the reference plan should put ghosts inside the plate";
  EXPECT_EQ(inside_re, 0);
  const std::vector<double>& failed = *failed_flags(b);
  for (std::size_t i = 0; i < b.size(); ++i) {
    EXPECT_EQ(after.debris[i], failed[i] > 0.5 ? 1 : 0) << i;
    if (failed[i] > 0.5) {
      EXPECT_TRUE(ghosts_of(after, re, i).empty()) << "failed particle " << i;
    }
    // Surface particles of the zone far enough from the slot to see a flat plate: the
    // re-planned slots reproduce the reference ghosts (same depths, same volumes).
    const int c = col(i);
    if ((c >= kSlot0 - 12 && c <= kSlot0 - 5) || (c >= kSlot1 + 5 && c <= kSlot1 + 12)) {
      const auto g0 = ghosts_of(before, ref, i), g1 = ghosts_of(after, re, i);
      ASSERT_EQ(g0.size(), g1.size()) << i;
      ASSERT_FALSE(g0.empty()) << i;
      for (std::size_t k = 0; k < g0.size(); ++k) {
        EXPECT_NEAR(g0[k].first, g1[k].first, 1e-12) << i;
        EXPECT_DOUBLE_EQ(g0[k].second, g1[k].second) << i;
      }
    }
  }
  // The slot's faces (both rows are surfaces of a 2-layer plate, so they are corners, with
  // diagonal normals): their ghosts lie behind them, outside the plate, or there are none.
  for (std::size_t i = 0; i < b.size(); ++i)
    if (col(i) == kSlot0 - 1 || col(i) == kSlot1 + 1) {
      const Vec2 n = after.normal[i];
      std::printf("face %zu: normal (%.3f, %.3f), %zu ghosts (reference plan: %zu)\n", i, n.x, n.y,
                  ghosts_of(after, re, i).size(), ghosts_of(before, ref, i).size());
      EXPECT_GT(std::abs(n.x), 0.3) << "the face's normal turns into the slot " << i;
    }
}

TEST(FailureZoneGhosts, LayoutIsAFunctionOfTheFailedFlags) {
  std::vector<SolidBody> bodies = breached_plate();
  ContactLayout a = reference_layout(bodies);
  ASSERT_TRUE(replan_around_failures(a, bodies));
  EXPECT_FALSE(replan_around_failures(a, bodies));  // same flags: nothing to do
  // A fresh layout re-planned after the plate has moved (a resumed run re-plans at restore):
  // the same ghosts in the same order.
  for (Vec2& x : bodies[0].x) x += Vec2{0.003, -0.002};
  ContactLayout b = reference_layout(bodies);
  ASSERT_TRUE(replan_around_failures(b, bodies));
  ASSERT_EQ(a.ghosts.size(), b.ghosts.size());
  for (std::size_t g = 0; g < a.ghosts.size(); ++g) {
    EXPECT_EQ(a.ghosts[g].spec.parent, b.ghosts[g].spec.parent) << g;
    EXPECT_EQ(a.ghosts[g].slot, b.ghosts[g].slot) << g;
  }
  // One more failure grows the zone and re-plans.
  std::vector<double>& failed = bodies[0].history.values[8];
  ASSERT_EQ(bodies[0].history.fields[8].name, "failed");
  failed[10] = 1.0;
  EXPECT_TRUE(replan_around_failures(a, bodies));
  EXPECT_NE(a.ghosts.size(), b.ghosts.size());
}
