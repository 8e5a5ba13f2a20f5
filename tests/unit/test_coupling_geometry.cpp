// Thin-structure geometry of the coupling (spec §4): ghost layers behind a two-layer plate
// and a two-layer ring (coupling/ghost_layers.h, with the reference normals of
// coupling/surface_normals.h), none behind a body that fills the kernel support, and the
// leak counter's inside/outside rule (coupling/leak_counter.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "core/parallel.h"
#include "coupling/ghost_layers.h"
#include "coupling/leak_counter.h"
#include "coupling/surface_normals.h"

using namespace slamsph;

namespace {

constexpr double kD = 0.01;
const Kernel kKernel(KernelType::WendlandC2, 1.3 * kD);  // support 2.6 d: K = 3 layers

std::vector<Vec2> plate(int nx, int layers) {
  std::vector<Vec2> X;
  for (int j = 0; j < layers; ++j)
    for (int i = 0; i < nx; ++i) X.push_back({(i + 0.5) * kD, (j + 0.5) * kD});
  return X;
}

}  // namespace

TEST(CouplingGhostLayers, TwoLayerPlateGetsTheMissingLayersOnEachSide) {
  const int nx = 24;
  const std::vector<Vec2> X = plate(nx, 2);
  const std::vector<Vec2> n =
      reference_surface_normals(X, std::vector<double>(X.size(), kD * kD), kKernel);
  const std::vector<GhostSpec> g = plan_ghost_layers(X, n, kD, kKernel.support());
  // Every particle of a two-layer plate is on a surface; behind each lies one body layer,
  // so depths 2 and 3 (= ceil(2.6)) are missing: two ghosts per particle away from the
  // plate's ends (whose normals are tilted).
  std::multiset<double> depths_of_mid_top;
  std::size_t mid = 0;
  for (const GhostSpec& s : g) {
    const std::size_t p = s.parent;
    const int col = static_cast<int>(p) % nx;
    if (col < 4 || col >= nx - 4) continue;
    ++mid;
    const bool top = p >= static_cast<std::size_t>(nx);
    EXPECT_NEAR(n[p].x, 0.0, 1e-12);
    EXPECT_NEAR(n[p].y, top ? 1.0 : -1.0, 1e-12);
    const Vec2 ghost = X[p] - (s.depth * kD) * n[p];
    // Top-surface ghosts continue the plate downwards below the bottom layer (y = -0.5 d,
    // -1.5 d); bottom-surface ghosts continue it upwards above the top layer.
    const double y_expected = top ? (1.5 - s.depth) * kD : (0.5 + s.depth) * kD;
    EXPECT_NEAR(ghost.y, y_expected, 1e-12);
    EXPECT_NEAR(ghost.x, X[p].x, 1e-12);
    if (top && col == nx / 2) depths_of_mid_top.insert(s.depth);
  }
  EXPECT_EQ(mid, 2u * 2u * (nx - 8));
  EXPECT_EQ(depths_of_mid_top, (std::multiset<double>{2.0, 3.0}));
}

TEST(CouplingGhostLayers, ThickPlateNeedsNoGhosts) {
  const std::vector<Vec2> X = plate(16, 4);  // 4 layers: 3 behind every surface particle
  const std::vector<Vec2> n =
      reference_surface_normals(X, std::vector<double>(X.size(), kD * kD), kKernel);
  EXPECT_TRUE(plan_ghost_layers(X, n, kD, kKernel.support()).empty());
}

TEST(CouplingGhostLayers, TwoLayerRingGhostsLieOnConcentricCircles) {
  const double R = 0.2;
  const int per = static_cast<int>(std::lround(2 * std::numbers::pi * R / kD));
  std::vector<Vec2> X;
  std::vector<double> V0;
  for (int l = 0; l < 2; ++l)
    for (int k = 0; k < per; ++k) {  // radially aligned layers
      const double r = R + l * kD, t = 2 * std::numbers::pi * k / per;
      X.push_back({r * std::cos(t), r * std::sin(t)});
      V0.push_back(2 * std::numbers::pi * r / per * kD);
    }
  const std::vector<Vec2> n = reference_surface_normals(X, V0, kKernel);
  const std::vector<GhostSpec> g = plan_ghost_layers(X, n, kD, kKernel.support());
  ASSERT_EQ(g.size(), 2 * X.size());
  for (const GhostSpec& s : g) {
    const std::size_t p = s.parent;
    const bool outer = p >= static_cast<std::size_t>(per);
    const Vec2 radial = X[p] / norm(X[p]);
    EXPECT_NEAR(dot(n[p], radial), outer ? 1.0 : -1.0, 1e-9);  // outward normals
    const Vec2 ghost = X[p] - (s.depth * kD) * n[p];
    // Outer-layer ghosts inside the hole at R - (depth - 1) d; inner-layer ghosts outside
    // the ring at R + depth d.
    const double r_expected = outer ? R + kD - s.depth * kD : R + s.depth * kD;
    EXPECT_NEAR(norm(ghost), r_expected, 1e-9);
    EXPECT_TRUE(s.depth == 2.0 || s.depth == 3.0);
    EXPECT_EQ(s.weight, 1.0);
  }
}

// A body of parts with their own spacings (a fuselage's fine skin and coarser floor): each
// part is probed at its own layer spacing. Probing the coarse part at the finest spacing
// finds nothing between its layers (half a coarse spacing away, beyond 0.75 d) and fills
// it with ghosts inside itself; this test fails then.
TEST(CouplingGhostLayers, EachPartOfATwoSpacingBodyIsProbedAtItsOwnSpacing) {
  const double d = 0.005, D = 0.01;         // fine skin, coarse block
  const double support = 2.0 * 1.3 * 0.01;  // water at 0.01 m, h = 1.3 dx
  const double cell = 0.005;                // half a water spacing
  std::vector<Vec2> fine, coarse;
  for (int j = 0; j < 2; ++j)  // 2-layer skin
    for (int i = 0; i < 40; ++i) fine.push_back({(i + 0.5) * d, (j + 0.5) * d});
  for (int j = 0; j < 4; ++j)  // 4-layer block: fills the water's support at its spacing
    for (int i = 0; i < 20; ++i) coarse.push_back({0.3 + (i + 0.5) * D, (j + 0.5) * D});
  auto normals = [](const std::vector<Vec2>& X, double s) {
    return reference_surface_normals(X, std::vector<double>(X.size(), s * s),
                                     Kernel(KernelType::WendlandC2, 1.3 * s));
  };
  const std::vector<Vec2> nf = normals(fine, d), nc = normals(coarse, D);
  std::vector<Vec2> X = fine, n = nf;
  X.insert(X.end(), coarse.begin(), coarse.end());
  n.insert(n.end(), nc.begin(), nc.end());
  std::vector<double> spacing(fine.size(), d);
  spacing.resize(X.size(), D);

  const std::vector<GhostSpec> g = plan_ghost_layers(X, n, spacing, support, cell);
  // The parts lie apart, so the body's plan is the union of each part's own plan.
  std::vector<GhostSpec> expected = plan_ghost_layers(fine, nf, d, support, cell);
  for (GhostSpec s : plan_ghost_layers(coarse, nc, D, support, cell)) {
    s.parent += static_cast<std::uint32_t>(fine.size());
    expected.push_back(s);
  }
  ASSERT_FALSE(expected.empty());
  ASSERT_EQ(g.size(), expected.size());
  for (std::size_t k = 0; k < g.size(); ++k) {
    EXPECT_EQ(g[k].parent, expected[k].parent);
    EXPECT_EQ(g[k].depth, expected[k].depth);
    EXPECT_EQ(g[k].weight, expected[k].weight);
  }
  // The thick coarse block needs no ghosts; the thin fine skin gets them.
  std::size_t coarse_ghosts = 0;
  for (const GhostSpec& s : g) coarse_ghosts += s.parent >= fine.size();
  EXPECT_EQ(coarse_ghosts, 0u);
  EXPECT_GE(g.size(), fine.size());
}

namespace {

// A three-layer plate as contact particles: top normals up, bottom down, middle zero.
ContactParticles contact_plate(int nx) {
  ContactParticles c;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < nx; ++i) {
      c.resize(c.size() + 1);
      const std::size_t s = c.size() - 1;
      c.x[s] = {i * kD, -j * kD};  // top layer at y = 0
      c.volume[s] = kD * kD;
      c.normal[s] = j == 0 ? Vec2{0.0, 1.0} : j == 2 ? Vec2{0.0, -1.0} : Vec2{};
    }
  return c;
}

NeighbourList all_pairs(std::size_t nq, std::size_t np) {
  NeighbourList l;
  l.start.push_back(0);
  for (std::size_t i = 0; i < nq; ++i) {
    for (std::size_t j = 0; j < np; ++j) l.index.push_back(static_cast<std::uint32_t>(j));
    l.start.push_back(static_cast<std::uint32_t>(l.index.size()));
  }
  return l;
}

}  // namespace

TEST(CouplingLeakCounter, InsideOutsideRuleAndStickyFlags) {
  ContactParticles c = contact_plate(9);
  // A ghost just above the top surface (ghosts lie behind surfaces by construction, so the
  // counter must ignore it even when it is the nearest solid particle).
  c.resize(c.size() + 1);
  const std::size_t ghost = c.size() - 1;
  c.x[ghost] = {4 * kD, 0.7 * kD};
  c.volume[ghost] = kD * kD;
  c.ghost[ghost] = 1;
  FluidParticles f;
  f.resize(6);
  f.x[0] = {4.1 * kD, 0.5 * kD};   // above the surface: outside
  f.x[1] = {4.0 * kD, -0.4 * kD};  // 0.4 d below the top surface: inside (> d/4)
  f.x[2] = {2.0 * kD, -0.2 * kD};  // 0.2 d below it: within the tolerance, outside
  f.x[3] = {6.0 * kD, -1.1 * kD};  // nearest is a middle (zero-normal) particle: inside
  f.x[4] = {4.0 * kD, 3.0 * kD};   // farther than one spacing from every solid: not judged
  f.x[5] = {4.0 * kD, 0.75 * kD};  // nearest non-ghost is the top particle below: outside
  const NeighbourList fc = all_pairs(f.size(), c.size());
  EXPECT_EQ(update_leak_flags(f, c, fc, Executor(1)), 2);
  EXPECT_EQ(f.crossed[0], 0);
  EXPECT_EQ(f.crossed[1], 1);
  EXPECT_EQ(f.crossed[2], 0);
  EXPECT_EQ(f.crossed[3], 1);
  EXPECT_EQ(f.crossed[4], 0);
  EXPECT_EQ(f.crossed[5], 0);
  // Sticky: particle 1 back outside stays counted; particle 2 pushed deeper is added.
  f.x[1] = {4.0 * kD, 0.5 * kD};
  f.x[2] = {2.0 * kD, -0.3 * kD};
  EXPECT_EQ(update_leak_flags(f, c, fc, Executor(2)), 3);
  EXPECT_EQ(f.crossed[1], 1);
}
