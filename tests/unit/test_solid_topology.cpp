// Solid topology (solid/solid_topology.h) as its own rebuildable value, for both schemes:
//  - two touching blocks as two unbonded parts: no pair crosses the parts, and each part's
//    lists, B and gradient weights equal (bit for bit) those of the block built alone;
//  - the same two parts bonded: cross pairs exist and everything equals the one-part build
//    of the union;
//  - a subset build (one part active) leaves the other particles without pairs;
//  - in every build, pair reversal is consistent and the gradient of a linear field is exact.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/parallel.h"
#include "solid/solid_topology.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.01;

TopologySpec spec(SolidScheme s, std::vector<std::uint32_t> part = {}, bool bond = false) {
  return {s, kDx, Kernel(KernelType::WendlandC2, 1.3 * kDx), std::move(part), bond, {}};
}

// The lists of particle i as global indices.
std::vector<std::uint32_t> list(const NeighbourList& l, std::size_t i) {
  return {l.index.begin() + l.start[i], l.index.begin() + l.start[i + 1]};
}

void check_reverse_and_linear_exactness(const SolidTopology& t, const std::vector<Vec2>& X) {
  const Mat2 A{1.02, 0.03, -0.01, 0.97};
  std::vector<Vec2> x(X.size());
  for (std::size_t i = 0; i < X.size(); ++i) x[i] = A * X[i] + Vec2{0.3, -0.1};
  for (std::size_t i = 0; i < t.size(); ++i) {
    for (std::uint32_t k = t.pairs.start[i]; k < t.pairs.start[i + 1]; ++k) {
      const std::uint32_t j = t.pairs.index[k], r = t.pair_reverse[k];
      ASSERT_GE(r, t.pairs.start[j]);
      ASSERT_LT(r, t.pairs.start[j + 1]);
      ASSERT_EQ(t.pairs.index[r], i);
    }
    if (t.pairs.count(i) == 0) continue;
    Mat2 F;
    for (std::uint32_t k = t.pairs.start[i]; k < t.pairs.start[i + 1]; ++k)
      F += outer(x[t.pairs.index[k]] - x[i], t.grad0[k]);
    EXPECT_NEAR(F.xx, A.xx, 1e-12);
    EXPECT_NEAR(F.xy, A.xy, 1e-12);
    EXPECT_NEAR(F.yx, A.yx, 1e-12);
    EXPECT_NEAR(F.yy, A.yy, 1e-12);
  }
}

class Topology : public ::testing::TestWithParam<SolidScheme> {};

}  // namespace

TEST_P(Topology, UnbondedPartsEqualSeparateBuildsBondedEqualsUnion) {
  const int nx = 8, ny = 5;
  // Part 0: the left block; part 1: the right block, touching it (one lattice).
  std::vector<Vec2> X = box_lattice(2 * nx, ny, kDx);
  std::vector<std::uint32_t> part(X.size());
  std::vector<std::uint32_t> members[2];
  for (std::size_t i = 0; i < X.size(); ++i) {
    part[i] = static_cast<int>(i) % (2 * nx) < nx ? 0 : 1;
    members[part[i]].push_back(static_cast<std::uint32_t>(i));
  }
  const std::vector<double> V0(X.size(), kDx * kDx);
  const Executor exec(2);

  const SolidTopology unbonded = build_solid_topology(X, V0, spec(GetParam(), part), exec);
  check_reverse_and_linear_exactness(unbonded, X);
  for (int p = 0; p < 2; ++p) {
    std::vector<Vec2> Xp;
    for (std::uint32_t i : members[p]) Xp.push_back(X[i]);
    const SolidTopology alone =
        build_solid_topology(Xp, std::vector<double>(Xp.size(), kDx * kDx), spec(GetParam()), exec);
    for (std::size_t li = 0; li < Xp.size(); ++li) {
      const std::uint32_t i = members[p][li];
      EXPECT_EQ(unbonded.part[i], static_cast<std::uint32_t>(p));
      std::vector<std::uint32_t> mapped;
      for (std::uint32_t lj : list(alone.pairs, li)) mapped.push_back(members[p][lj]);
      ASSERT_EQ(list(unbonded.pairs, i), mapped);
      for (std::uint32_t k = 0; k < mapped.size(); ++k) {
        EXPECT_EQ(unbonded.grad0[unbonded.pairs.start[i] + k].x,
                  alone.grad0[alone.pairs.start[li] + k].x);
        EXPECT_EQ(unbonded.grad0[unbonded.pairs.start[i] + k].y,
                  alone.grad0[alone.pairs.start[li] + k].y);
      }
      EXPECT_EQ(unbonded.B[i].xx, alone.B[li].xx);
      EXPECT_EQ(unbonded.B[i].yy, alone.B[li].yy);
    }
  }

  const SolidTopology bonded = build_solid_topology(X, V0, spec(GetParam(), part, true), exec);
  const SolidTopology whole = build_solid_topology(X, V0, spec(GetParam()), exec);
  std::size_t cross = 0;
  for (std::size_t i = 0; i < X.size(); ++i)
    for (std::uint32_t j : list(bonded.pairs, i)) cross += part[i] != part[j];
  EXPECT_GT(cross, 0u);
  EXPECT_EQ(bonded.pairs.index, whole.pairs.index);
  EXPECT_EQ(bonded.pair_reverse, whole.pair_reverse);
  ASSERT_EQ(bonded.grad0.size(), whole.grad0.size());
  for (std::size_t k = 0; k < whole.grad0.size(); ++k) {
    EXPECT_EQ(bonded.grad0[k].x, whole.grad0[k].x);
    EXPECT_EQ(bonded.grad0[k].y, whole.grad0[k].y);
  }
  EXPECT_EQ(bonded.part, part);
}

TEST_P(Topology, SubsetBuildLeavesInactiveParticlesWithoutPairs) {
  const std::vector<Vec2> X = box_lattice(10, 6, kDx);
  const std::vector<double> V0(X.size(), kDx * kDx);
  std::vector<std::uint32_t> active;
  for (std::size_t i = 0; i < X.size(); ++i)
    if (X[i].x < 0.06) active.push_back(static_cast<std::uint32_t>(i));
  const SolidTopology t = build_solid_topology(X, V0, spec(GetParam()), Executor(1), active);
  ASSERT_EQ(t.size(), X.size());
  for (std::size_t i = 0; i < X.size(); ++i) {
    const bool on = X[i].x < 0.06;
    EXPECT_EQ(t.pairs.count(i) > 0, on) << i;
    for (std::uint32_t j : list(t.pairs, i)) EXPECT_LT(X[j].x, 0.06);
    if (!on) {
      EXPECT_EQ(t.B[i].xx, 0.0);
    }
  }
  check_reverse_and_linear_exactness(t, X);
}

INSTANTIATE_TEST_SUITE_P(Schemes, Topology,
                         ::testing::Values(SolidScheme::TlSfpm, SolidScheme::TlSph),
                         [](const auto& info) {
                           return std::string(info.param == SolidScheme::TlSfpm ? "TlSfpm"
                                                                                : "TlSph");
                         });
