// The four-lane Wendland pair loop (fluid/gsph_pair_band.h) against the scalar loop it
// replaces: the same sums bit for bit, for every pass, with and without viscosity, on a
// disordered cloud whose lists carry a skin (pairs beyond the support), lists of every length
// modulo 4, a coincident pair (r = 0, skipped) and bands run on two threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/cell_grid.h"
#include "fluid/gsph_fluid_rates.h"
#include "fluid/gsph_pair_band.h"
#include "test_fluid_cloud.h"

using namespace slamsph;

namespace {

FluidParticles cloud(unsigned seed) {
  FluidParticles f = test::disordered_cloud(seed, 30, 24, 0.35);
  f.x[101] = f.x[100];  // a coincident pair
  return f;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// `crowd`: a larger cloud, 600 of its particles moved into a disc of a quarter support, so
// that some lists are longer than the eight lanes' chunk of packed pairs.
void expect_bit_identical_to_the_scalar_loop(PairLoop loop, bool crowd = false) {
  FluidParticles base = crowd ? test::disordered_cloud(3, 60, 40, 0.35) : cloud(3);
  if (crowd)
    for (std::size_t i = 0; i < 600; ++i) {
      const double a = 0.618034 * static_cast<double>(i), s = std::sqrt(i / 600.0);
      base.x[i] = Vec2{0.1, 0.1} + (0.25 * 0.026 * s) * Vec2{std::cos(a), std::sin(a)};
    }
  const Kernel k(KernelType::WendlandC2, 0.013);
  const double list_radius = 1.2 * k.support();  // the solver's Verlet skin of 0.2
  CellGrid grid;
  grid.build(base.x, list_radius);
  base.permute(grid.cell_order());
  grid.build(base.x, list_radius);
  BandedPairs nl;
  build_banded_pairs(base.x, grid, list_radius, Executor(1), nl);
  ASSERT_GT(nl.bands(), 4u);
  int beyond = 0, lengths[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < base.size(); ++i) {
    ++lengths[(nl.half.start[i + 1] - nl.half.start[i]) % 4];
    for (std::uint32_t q = nl.half.start[i]; q < nl.half.start[i + 1]; ++q)
      beyond += norm(base.x[i] - base.x[nl.half.index[q]]) >= k.support();
  }
  ASSERT_GT(beyond, 1000);                 // the skin is exercised
  for (int m : lengths) ASSERT_GT(m, 10);  // and the partial last group of four
  std::uint32_t longest = 0;
  for (std::size_t i = 0; i < base.size(); ++i)
    longest = std::max(longest, nl.half.start[i + 1] - nl.half.start[i]);
  if (crowd) {
    ASSERT_GT(longest, 520u);
  }

  for (const double nu : {0.0, 1e-3})
    for (const RatePass pass : {RatePass::Both, RatePass::Momentum, RatePass::Continuity}) {
      const GsphParams prm{30.0, 3.0, nu, {0.0, -9.81}};
      FluidParticles lanes = base, scalar = base;
      compute_gsph_fluid_rates(lanes, nl, k, prm, Executor(2), pass, loop);
      compute_gsph_fluid_rates(scalar, nl, k, prm, Executor(1), pass, PairLoop::Scalar);
      int nonzero = 0;
      for (std::size_t i = 0; i < base.size(); ++i) {
        ASSERT_TRUE(same_bits(lanes.a[i].x, scalar.a[i].x)) << i << " nu " << nu;
        ASSERT_TRUE(same_bits(lanes.a[i].y, scalar.a[i].y)) << i << " nu " << nu;
        ASSERT_TRUE(same_bits(lanes.drho[i], scalar.drho[i])) << i << " nu " << nu;
        nonzero += lanes.drho[i] != 0.0 && lanes.a[i].x != 0.0;
      }
      if (pass == RatePass::Both) {
        EXPECT_GT(nonzero, static_cast<int>(base.size()) / 2);
      }
    }
}

}  // namespace

TEST(GsphPairBand, FourLanesAreBitIdenticalToTheScalarLoop) {
  if (!gsph_band_avx2_available()) GTEST_SKIP() << "no AVX2 on this CPU or build";
  expect_bit_identical_to_the_scalar_loop(PairLoop::FourLanes);
}

// The eight lanes pack the partners inside the support before computing them (a third of the
// listed ones are beyond it): on the same cloud, packs that fill a group and leave partners
// pending, and the partial group at the end of every list.
TEST(GsphPairBand, EightLanesAreBitIdenticalToTheScalarLoop) {
  if (!gsph_band_avx512_available()) GTEST_SKIP() << "no AVX-512F on this CPU or build";
  expect_bit_identical_to_the_scalar_loop(PairLoop::EightLanes);
}

TEST(GsphPairBand, EightLanesHandleListsLongerThanAChunk) {
  if (!gsph_band_avx512_available()) GTEST_SKIP() << "no AVX-512F on this CPU or build";
  expect_bit_identical_to_the_scalar_loop(PairLoop::EightLanes, true);
}

// What the runs use (Auto) is one of the two, or the scalar loop.
TEST(GsphPairBand, AutoIsBitIdenticalToTheScalarLoop) {
  expect_bit_identical_to_the_scalar_loop(PairLoop::Auto);
}
