// TL-SFPM gradient (spec §3, paper Eqs. 6–8): neighbour selection, the paper's stencils on a
// Cartesian lattice, exactness for linear fields on Cartesian, ring and perturbed lattices,
// and the B-corrected kernel gradient (Eq. 11) of the TLSPH scheme at cut supports.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "solid/deformation_gradient.h"
#include "solid/fpm_gradient.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.01;
constexpr int kNx = 7, kNy = 6;

std::size_t idx(int i, int j) {
  return static_cast<std::size_t>(j * kNx + i);
}

double field(Vec2 p) {
  return std::sin(37.0 * p.x) + std::cos(53.0 * p.y) + 3.0 * p.x * p.y * 100;
}

// ∇0 f_i of a scalar field through the body's operator (first row of the vector gradient).
Vec2 body_gradient(const SolidBody& b, std::size_t i) {
  std::vector<Vec2> f(b.size());
  for (std::size_t k = 0; k < b.size(); ++k) f[k] = {field(b.X[k]), 0.0};
  const Mat2 G = reference_gradient(b.topology, f, i);
  return {G.xx, G.xy};
}

std::vector<std::uint32_t> set_of(const SolidBody& b, std::size_t i) {
  return {b.topology.fpm_sets.index.begin() + b.topology.fpm_sets.start[i],
          b.topology.fpm_sets.index.begin() + b.topology.fpm_sets.start[i + 1]};
}

}  // namespace

TEST(SolidFpm, SelectionOnCartesianLattice) {
  const SolidBody b = make_body(box_lattice(kNx, kNy, kDx), kDx, "tl_sfpm", plate_material());
  // Interior: the 4 axis neighbours.
  auto s = set_of(b, idx(3, 3));
  std::vector<std::uint32_t> want{
      static_cast<std::uint32_t>(idx(3, 2)), static_cast<std::uint32_t>(idx(2, 3)),
      static_cast<std::uint32_t>(idx(4, 3)), static_cast<std::uint32_t>(idx(3, 4))};
  std::sort(want.begin(), want.end());
  EXPECT_EQ(s, want);
  // Bottom edge: left, right, up.
  s = set_of(b, idx(3, 0));
  want = {static_cast<std::uint32_t>(idx(2, 0)), static_cast<std::uint32_t>(idx(4, 0)),
          static_cast<std::uint32_t>(idx(3, 1))};
  std::sort(want.begin(), want.end());
  EXPECT_EQ(s, want);
  // Corner: two axis neighbours and the diagonal.
  s = set_of(b, idx(0, 0));
  want = {static_cast<std::uint32_t>(idx(1, 0)), static_cast<std::uint32_t>(idx(1, 1)),
          static_cast<std::uint32_t>(idx(0, 1))};
  std::sort(want.begin(), want.end());
  EXPECT_EQ(s, want);
  // Union pair list is symmetric and the reverse index is right.
  for (std::size_t i = 0; i < b.size(); ++i)
    for (std::uint32_t k = b.topology.pairs.start[i]; k < b.topology.pairs.start[i + 1]; ++k) {
      const std::uint32_t rk = b.topology.pair_reverse[k];
      EXPECT_EQ(b.topology.pairs.index[rk], i);
      EXPECT_GE(rk, b.topology.pairs.start[b.topology.pairs.index[k]]);
      EXPECT_LT(rk, b.topology.pairs.start[b.topology.pairs.index[k] + 1]);
    }
  // The corner's diagonal partner (1,1) holds the corner only through the union.
  EXPECT_EQ(b.topology.pairs.count(idx(1, 1)), 5u);
}

TEST(SolidFpm, InteriorIsCentralDifferenceEq6) {
  const SolidBody b = make_body(box_lattice(kNx, kNy, kDx), kDx, "tl_sfpm", plate_material());
  const Vec2 g = body_gradient(b, idx(3, 3));
  const double f1 = field(b.X[idx(2, 3)]), f2 = field(b.X[idx(4, 3)]);
  const double f3 = field(b.X[idx(3, 2)]), f4 = field(b.X[idx(3, 4)]);
  EXPECT_NEAR(g.x, (f2 - f1) / (2 * kDx), 1e-10);
  EXPECT_NEAR(g.y, (f4 - f3) / (2 * kDx), 1e-10);
}

TEST(SolidFpm, BoundaryIsOneSidedEq7) {
  const SolidBody b = make_body(box_lattice(kNx, kNy, kDx), kDx, "tl_sfpm", plate_material());
  // Left edge particle: one-sided in x (neighbour 1 inside), central in y.
  const std::size_t i = idx(0, 3);
  const Vec2 g = body_gradient(b, i);
  const double fi = field(b.X[i]), f1 = field(b.X[idx(1, 3)]);
  const double f3 = field(b.X[idx(0, 2)]), f4 = field(b.X[idx(0, 4)]);
  EXPECT_NEAR(g.x, (f1 - fi) / kDx, 1e-10);
  EXPECT_NEAR(g.y, (f4 - f3) / (2 * kDx), 1e-10);
}

TEST(SolidFpm, CornerIsEq8) {
  // Neighbour 1 on the x axis, 3 the diagonal, 4 on the y axis. With the diagonal weighing
  // 1/3 of an axis neighbour the least-squares gradient has the paper's 0.8 / 0.2 weights:
  //   f_X = (0.8 Δ1 + 0.2 Δ3 − 0.2 Δ4)/d,  f_Y = (−0.2 Δ1 + 0.2 Δ3 + 0.8 Δ4)/d.
  const SolidBody b = make_body(box_lattice(kNx, kNy, kDx), kDx, "tl_sfpm", plate_material());
  const std::size_t i = idx(0, 0);
  const double fi = field(b.X[i]);
  const double d1 = field(b.X[idx(1, 0)]) - fi, d3 = field(b.X[idx(1, 1)]) - fi,
               d4 = field(b.X[idx(0, 1)]) - fi;
  const Vec2 want{(0.8 * d1 + 0.2 * d3 - 0.2 * d4) / kDx, (-0.2 * d1 + 0.2 * d3 + 0.8 * d4) / kDx};
  const Vec2 g = body_gradient(b, i);
  EXPECT_NEAR(g.x, want.x, 1e-10);
  EXPECT_NEAR(g.y, want.y, 1e-10);
  // The generic weighted least-squares form with explicit weights 1, 1/3, 1.
  const std::vector<Vec2> Xj{b.X[idx(1, 0)], b.X[idx(1, 1)], b.X[idx(0, 1)]};
  const std::vector<double> fj{d1 + fi, d3 + fi, d4 + fi}, w{1.0, 1.0 / 3.0, 1.0};
  const Vec2 g2 = fpm_gradient(b.X[i], fi, Xj, fj, w);
  EXPECT_NEAR(g2.x, want.x, 1e-10);
  EXPECT_NEAR(g2.y, want.y, 1e-10);
  // Another diagonal weight gives other numbers: the test can tell.
  const std::vector<double> w2{1.0, 0.5, 1.0};
  EXPECT_GT(std::abs(fpm_gradient(b.X[i], fi, Xj, fj, w2).x - want.x), 1e-3);
}

namespace {

// For x = A X + c every particle's F must be A (both schemes).
void expect_affine_exact(const SolidBody& b0, double tol) {
  SolidBody b = b0;
  const Mat2 A{1.07, -0.21, 0.13, 0.91};
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i] = A * b.X[i] + Vec2{0.3, -0.2};
  double worst = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Mat2 F = reference_gradient(b.topology, b.x, i);
    const Mat2 d = F - A;
    worst = std::max({worst, std::abs(d.xx), std::abs(d.xy), std::abs(d.yx), std::abs(d.yy)});
  }
  EXPECT_LT(worst, tol);
}

}  // namespace

TEST(SolidFpm, LinearFieldsExactCartesian) {
  const auto X = box_lattice(kNx, kNy, kDx);
  expect_affine_exact(make_body(X, kDx, "tl_sfpm", plate_material()), 1e-12);
  expect_affine_exact(make_body(X, kDx, "tlsph", plate_material()), 1e-12);
}

TEST(SolidFpm, LinearFieldsExactRing) {
  std::vector<double> V0;
  const auto X = ring_lattice(0.1, 4, kDx, &V0);
  const SolidBody sfpm = make_body(X, kDx, "tl_sfpm", plate_material(), {}, V0);
  expect_affine_exact(sfpm, 1e-11);
  expect_affine_exact(make_body(X, kDx, "tlsph", plate_material(), {}, V0), 1e-11);
  // Two-layer ring (every particle on a boundary) works too.
  std::vector<double> V2;
  const auto X2 = ring_lattice(0.1, 2, kDx, &V2);
  expect_affine_exact(make_body(X2, kDx, "tl_sfpm", plate_material(), {}, V2), 1e-11);
}

TEST(SolidFpm, LinearFieldsExactPerturbed) {
  const auto X = perturbed_lattice(9, 8, kDx, 0.2, 42);
  expect_affine_exact(make_body(X, kDx, "tl_sfpm", plate_material()), 1e-11);
  expect_affine_exact(make_body(X, kDx, "tlsph", plate_material()), 1e-11);
}

TEST(SolidFpm, CorrectedKernelGradientAtCutSupport) {
  // TLSPH corner and edge particles have a cut kernel support: without B the plain kernel
  // gradient of a linear field is badly off, with B (Eq. 11) it is exact.
  const SolidBody b = make_body(box_lattice(kNx, kNy, kDx), kDx, "tlsph", plate_material());
  const Vec2 a{2.0, -3.0};
  for (std::size_t i : {idx(0, 0), idx(3, 0), idx(kNx - 1, kNy - 1)}) {
    Vec2 plain, corrected;
    for (std::uint32_t k = b.topology.pairs.start[i]; k < b.topology.pairs.start[i + 1]; ++k) {
      const std::uint32_t j = b.topology.pairs.index[k];
      const Vec2 rij = b.X[i] - b.X[j];
      const Vec2 gw = b.kernel.dw_over_r(norm(rij)) * rij;
      const double df = dot(a, b.X[j] - b.X[i]);
      plain += (b.V0[j] * df) * gw;
      corrected += df * b.topology.grad0[k];
    }
    EXPECT_NEAR(corrected.x, a.x, 1e-12);
    EXPECT_NEAR(corrected.y, a.y, 1e-12);
    EXPECT_GT(norm(plain - a), 0.2 * norm(a));
  }
}
