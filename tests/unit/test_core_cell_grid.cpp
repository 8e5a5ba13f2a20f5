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
