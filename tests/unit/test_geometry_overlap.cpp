// remove_overlap keeps exactly the fluid particles at distance >= gap from every body
// particle (checked against brute force), on a disc immersed in a fluid block.
#include <gtest/gtest.h>

#include <numbers>

#include "geometry/geometry.h"

using namespace slamsph;

TEST(GeometryOverlap, MatchesBruteForce) {
  const double dxf = 0.01, dxs = 0.005;
  const ParticleLattice fluid = fill_box({{0, 0}, {1, 0.4}}, dxf);
  const ParticleLattice body = disc({0.5, 0.4}, 0.1, dxs);  // half immersed at the surface
  const double gap = 0.5 * (dxf + dxs);
  const auto kept = remove_overlap(fluid.x, body.x, gap);
  std::vector<std::size_t> expect;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    bool ok = true;
    for (const Vec2& s : body.x)
      if (norm2(fluid.x[i] - s) < gap * gap) ok = false;
    if (ok) expect.push_back(i);
  }
  EXPECT_EQ(kept, expect);
  // Removed area ≈ the immersed half-disc grown by about half a fluid spacing.
  const double removed = static_cast<double>(fluid.size() - kept.size()) * dxf * dxf;
  const double half_disc = 0.5 * std::numbers::pi * 0.1 * 0.1;
  EXPECT_GT(removed, half_disc);
  EXPECT_LT(removed, 0.5 * std::numbers::pi * 0.12 * 0.12);
}

TEST(GeometryOverlap, BoundaryDistanceIsKeptAndEmptySolidKeepsAll) {
  const std::vector<Vec2> fluid{{0, 0}, {1, 0}, {2.5, 0}, {10, 10}};
  const std::vector<Vec2> solid{{2, 0}};
  EXPECT_EQ(remove_overlap(fluid, solid, 1.0), (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(remove_overlap(fluid, {}, 1.0), (std::vector<std::size_t>{0, 1, 2, 3}));
}
