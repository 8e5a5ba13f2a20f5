// GSPH fluid pair forces are antisymmetric: total force sum_i m_i (a_i - g) vanishes to
// round-off on a disordered, non-uniform particle cloud; the rates are bit-identical for
// 1 and 2 threads.
#include <gtest/gtest.h>

#include <cmath>

#include "core/cell_grid.h"
#include "fluid/gsph_fluid_rates.h"
#include "test_fluid_cloud.h"

using namespace slamsph;

namespace {

FluidParticles cloud(unsigned seed) {
  return test::disordered_cloud(seed, 40, 30, 0.3);
}

}  // namespace

TEST(GsphFluidRates, ConservesLinearMomentumToRoundOff) {
  FluidParticles f = cloud(11);
  const Kernel k(KernelType::WendlandC2, 0.013);
  CellGrid grid;
  grid.build(f.x, k.support());
  BandedPairs nl;
  build_banded_pairs(f.x, grid, k.support(), Executor(1), nl);
  const GsphParams prm{30.0, 3.0, 1e-4, {0.0, -9.81}};
  compute_gsph_fluid_rates(f, nl, k, prm, Executor(2));
  Vec2 total, scale;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Vec2 fi = f.m[i] * (f.a[i] - prm.gravity);
    total += fi;
    scale += Vec2{std::abs(fi.x), std::abs(fi.y)};
  }
  EXPECT_GT(scale.x, 1.0);  // forces are not trivially zero
  EXPECT_LT(std::abs(total.x), 1e-12 * scale.x);
  EXPECT_LT(std::abs(total.y), 1e-12 * scale.y);
}

TEST(GsphFluidRates, ThreadCountDoesNotChangeResults) {
  FluidParticles a = cloud(5), b = cloud(5);
  const Kernel k(KernelType::CubicSpline, 0.013);
  CellGrid grid;
  grid.build(a.x, k.support());
  // In cell order the pairs come in many bands that run in parallel (BandedPairs).
  a.permute(grid.cell_order());
  b.permute(grid.cell_order());
  grid.build(a.x, k.support());
  BandedPairs nl;
  build_banded_pairs(a.x, grid, k.support(), Executor(1), nl);
  ASSERT_GT(nl.bands(), 10u);
  const GsphParams prm{30.0, 3.0, 0.0, {0.0, -9.81}};
  compute_gsph_fluid_rates(a, nl, k, prm, Executor(1));
  compute_gsph_fluid_rates(b, nl, k, prm, Executor(2));
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.a[i].x, b.a[i].x);
    ASSERT_EQ(a.a[i].y, b.a[i].y);
    ASSERT_EQ(a.drho[i], b.drho[i]);
  }
}

TEST(GsphFluidRates, UniformStateHasNoInteriorForce) {
  // A uniform-pressure lattice at rest: interior particles feel only gravity.
  FluidParticles f;
  const double dx = 0.01;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      f.resize(f.size() + 1);
      const std::size_t k = f.size() - 1;
      f.x[k] = {(i + 0.5) * dx, (j + 0.5) * dx};
      f.rho[k] = 1000.0;
      f.p[k] = 5e3;
      f.m[k] = 0.1;
    }
  const Kernel k(KernelType::WendlandC2, 1.3 * dx);
  CellGrid grid;
  grid.build(f.x, k.support());
  BandedPairs nl;
  build_banded_pairs(f.x, grid, k.support(), Executor(1), nl);
  compute_gsph_fluid_rates(f, nl, k, {30.0, 3.0, 0.0, {0.0, -9.81}}, Executor(1));
  const std::size_t centre = 10 * 20 + 10;
  EXPECT_NEAR(f.a[centre].x, 0.0, 1e-9);
  EXPECT_NEAR(f.a[centre].y, -9.81, 1e-9);
  EXPECT_NEAR(f.drho[centre], 0.0, 1e-12);
}
