// Cell-linked list: the neighbour lists equal the brute-force sets on random points, and
// do not depend on the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/cell_grid.h"
#include "core/parallel.h"

using namespace slamsph;

TEST(CellGrid, NeighbourListEqualsBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 2.0);
  std::vector<Vec2> pts(3000), q(500);
  for (auto& p : pts) p = {u(rng), 0.5 * u(rng)};
  for (auto& p : q) p = {u(rng) * 1.2, u(rng)};  // some queries outside the points' box
  const double radius = 0.07;
  CellGrid grid;
  grid.build(pts, radius);
  NeighbourList nl, self;
  build_neighbour_list(q, pts, grid, radius, false, Executor(2), nl);
  build_neighbour_list(pts, pts, grid, radius, true, Executor(2), self);
  for (std::size_t i = 0; i < q.size(); ++i) {
    std::vector<std::uint32_t> brute;
    for (std::uint32_t j = 0; j < pts.size(); ++j)
      if (norm2(q[i] - pts[j]) < radius * radius) brute.push_back(j);
    std::vector<std::uint32_t> got(nl.index.begin() + nl.start[i],
                                   nl.index.begin() + nl.start[i + 1]);
    std::sort(got.begin(), got.end());  // lists come in cell order
    ASSERT_EQ(got, brute) << "query " << i;
  }
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    for (std::uint32_t j = 0; j < pts.size(); ++j)
      if (j != i && norm2(pts[i] - pts[j]) < radius * radius) ++pairs;
  }
  EXPECT_EQ(self.index.size(), pairs);
  EXPECT_GT(pairs, 1000u);
}

TEST(CellGrid, ListsIndependentOfThreadCount) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> pts(5000);
  for (auto& p : pts) p = {u(rng), u(rng)};
  CellGrid grid;
  grid.build(pts, 0.03);
  NeighbourList a, b;
  build_neighbour_list(pts, pts, grid, 0.03, true, Executor(1), a);
  build_neighbour_list(pts, pts, grid, 0.03, true, Executor(2), b);
  EXPECT_EQ(a.start, b.start);
  EXPECT_EQ(a.index, b.index);
}

// Banded half lists: every pair within the radius exactly once, and in cell order the
// partner of a pair always lies in the band of its first particle or the next one (what
// makes Executor::for_alternating race-free). Out of cell order there is one band.
TEST(CellGrid, BandedPairsHoldEachPairOnceWithinAdjacentBands) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> pts(3000);
  for (Vec2& p : pts) p = {u(rng), 0.6 * u(rng)};
  const double radius = 0.045;
  CellGrid grid;
  grid.build(pts, radius * 1.2);
  BandedPairs out;
  build_banded_pairs(pts, grid, radius, Executor(2), out);
  EXPECT_EQ(out.bands(), 1u);
  // Cell order.
  std::vector<Vec2> sorted(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) sorted[k] = pts[grid.cell_order()[k]];
  grid.build(sorted, radius * 1.2);
  build_banded_pairs(sorted, grid, radius, Executor(2), out);
  ASSERT_GT(out.bands(), 5u);
  ASSERT_EQ(out.band_start.front(), 0u);
  ASSERT_EQ(out.band_start.back(), sorted.size());
  std::vector<std::size_t> band_of(sorted.size());
  for (std::size_t b = 0; b < out.bands(); ++b)
    for (std::uint32_t i = out.band_start[b]; i < out.band_start[b + 1]; ++i) band_of[i] = b;
  std::size_t pairs = 0, brute = 0;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    for (std::uint32_t k = out.half.start[i]; k < out.half.start[i + 1]; ++k) {
      const std::uint32_t j = out.half.index[k];
      ASSERT_GT(j, i);
      ASSERT_LT(norm(sorted[i] - sorted[j]), radius);
      ASSERT_LE(band_of[j] - band_of[i], 1u);
      ++pairs;
    }
    for (std::size_t j = i + 1; j < sorted.size(); ++j)
      if (norm(sorted[i] - sorted[j]) < radius) ++brute;
  }
  EXPECT_EQ(pairs, brute);
  EXPECT_GT(pairs, 10000u);
}

// In cell order the lists' distance test runs in eight lanes where the CPU has AVX-512F
// (core/candidate_lanes.h): the lists must be the scalar test's, entry for entry, in order —
// with pairs exactly at the radius (a lattice of spacing 1/4, whose distances are exact) left
// out by both, runs of candidates longer and shorter than eight, and any thread count.
TEST(CellGrid, BandedPairsLanesEqualTheScalarTest) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<Vec2> pts;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 60; ++x) {
      Vec2 p{0.25 * x, 0.25 * y};
      if ((x + 3 * y) % 4 == 0) p += Vec2{u(rng), u(rng)};  // a quarter off the lattice
      pts.push_back(p);
    }
  const double radius = 1.0;
  CellGrid grid;
  grid.build(pts, radius);
  std::vector<Vec2> sorted(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) sorted[k] = pts[grid.cell_order()[k]];
  grid.build(sorted, radius);
  // The scalar test, candidate by candidate (cell_grid.cpp without the lanes).
  std::vector<std::uint32_t> start{0}, index;
  std::size_t on_radius = 0;
  for (std::uint32_t i = 0; i < sorted.size(); ++i) {
    grid.for_each_later_candidate(i, sorted[i], [&](std::uint32_t j) {
      const double d2 = norm2(sorted[i] - sorted[j]);
      if (d2 < radius * radius) index.push_back(j);
      if (d2 == radius * radius) ++on_radius;
    });
    start.push_back(static_cast<std::uint32_t>(index.size()));
  }
  ASSERT_GT(on_radius, 1000u);
  for (int threads : {1, 2, 3}) {
    BandedPairs out;
    build_banded_pairs(sorted, grid, radius, Executor(threads), out);
    EXPECT_EQ(out.half.start, start) << threads << " threads";
    EXPECT_EQ(out.half.index, index) << threads << " threads";
  }
}

// The grid renumbered after permuting its points into cell order bins them exactly as a new
// build would (InteractionLists::update keeps it instead of binning the fluid twice per
// rebuild): the same cell order and the same candidate runs for every point.
TEST(CellGrid, RenumberedGridEqualsRebuiltGrid) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> pts(4000);
  for (auto& p : pts) p = {2.0 * u(rng), 0.7 * u(rng)};
  CellGrid grid;
  grid.build(pts, 0.05);
  std::vector<Vec2> sorted(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) sorted[k] = pts[grid.cell_order()[k]];
  grid.renumber_in_cell_order();
  CellGrid fresh;
  fresh.build(sorted, 0.05);
  EXPECT_EQ(grid.cell_order(), fresh.cell_order());
  EXPECT_EQ(grid.row_offsets(), fresh.row_offsets());
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    std::vector<std::uint32_t> a, b;
    grid.for_each_candidate_run(sorted[k], [&](std::uint32_t s, std::uint32_t e) {
      a.push_back(s);
      a.push_back(e);
    });
    fresh.for_each_candidate_run(sorted[k], [&](std::uint32_t s, std::uint32_t e) {
      b.push_back(s);
      b.push_back(e);
    });
    ASSERT_EQ(a, b) << k;
  }
}
