// The contact's fluid-side loop in vector lanes (coupling/contact_pair_lanes.h) against the
// scalar loop it replaces (contact_rates.cpp): the same sums, pair forces kept for the reaction
// and flags, bit for bit, for every pass, with and without viscosity, the static term, the
// short-range barrier and the cavitation limit, on a disordered cloud over wall layers whose
// lists carry a skin (pairs beyond the support), with dry particles, ghosts that face only part
// of the water, pairs inside the barrier radius, cavitating pairs, lists of every length modulo
// 8 and lists longer than a lane chunk (a crowd of wall particles), on two threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "core/cell_grid.h"
#include "core/parallel.h"
#include "coupling/contact_pair.h"
#include "coupling/contact_pair_lanes.h"
#include "coupling/contact_rates.h"
#include "coupling/virtual_pressure.h"
#include "fluid/tait_eos.h"
#include "test_fluid_cloud.h"

using namespace slamsph;

namespace {

template <class T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

struct Scene {
  FluidParticles f;
  ContactParticles c;
  NeighbourList fc, cf;
  Kernel k{KernelType::WendlandC2, 0.013};
};

// 30 x 12 water particles 1 cm apart over four wall layers 5 mm apart (two partners per
// spacing), the third layer ghosts facing up on the left half and down (away from the water)
// on the right; `crowd`: 300 more wall particles packed under the middle of the water, so that
// some lists are longer than a lane chunk.
Scene scene(bool crowd) {
  Scene s;
  s.f = test::disordered_cloud(7, 30, 12, 0.35);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double ds = 0.005;
  for (int l = 0; l < 4; ++l)
    for (int i = 0; i < 64; ++i) {
      s.c.resize(s.c.size() + 1);
      const std::size_t q = s.c.size() - 1;
      s.c.x[q] = {(i - 1.5) * ds, -(l + 0.5) * ds};
      s.c.v[q] = {0.1 * u(rng), 0.3 + 0.1 * u(rng)};
      s.c.a[q] = {0.5 * u(rng), 2.0 * u(rng)};
      s.c.volume[q] = ds * ds * (1.0 + 0.1 * u(rng));
      if (l == 2) {
        s.c.ghost[q] = 1;
        s.c.anchor[q] = s.c.x[q] + Vec2{0.0, 0.01};
        s.c.normal[q] = {0.0, i < 32 ? 1.0 : -1.0};
      }
    }
  if (crowd)
    for (int m = 0; m < 300; ++m) {
      s.c.resize(s.c.size() + 1);
      const std::size_t q = s.c.size() - 1;
      const double a = 0.618034 * m, r = 0.004 * std::sqrt(m / 300.0);
      s.c.x[q] = Vec2{0.15, -0.004} + r * Vec2{std::cos(a), std::sin(a)};
      s.c.v[q] = {0.1 * u(rng), 0.1 * u(rng)};
      s.c.volume[q] = 2e-6;
    }
  // A few water particles inside the barrier radius of the top layer (r0 ~ 3.6 mm).
  for (int n = 0; n < 12; ++n) s.f.x[static_cast<std::size_t>(7 * n)].y = 0.0005 + 0.0001 * n;
  // Sums that start at -0 and at other values.
  for (std::size_t i = 0; i < s.f.size(); ++i) {
    s.f.a[i] = i % 3 == 0 ? Vec2{-0.0, -0.0} : Vec2{u(rng), u(rng)};
    s.f.drho[i] = i % 3 == 0 ? -0.0 : u(rng);
  }
  const double radius = 1.2 * s.k.support();  // the solver's skin of 0.2
  CellGrid gf, gc;
  gf.build(s.f.x, radius);
  gc.build(s.c.x, radius);
  const Executor one(1);
  build_neighbour_list(s.f.x, s.c.x, gc, radius, false, one, s.fc);
  build_neighbour_list(s.c.x, s.f.x, gf, radius, false, one, s.cf);
  compute_virtual_state(s.c, s.f, s.cf, s.k, TaitEos{1000.0, 30.0, 7.0}, {0.0, -9.81}, one);
  // The ghosts facing away from the water found none of it: wet them (as if water lay below)
  // so that their pairs are skipped for facing away, not for being dry.
  for (std::size_t q = 0; q < s.c.size(); ++q)
    if (s.c.ghost[q] && s.c.normal[q].y < 0.0) {
      s.c.wetted[q] = 1;
      s.c.p[q] = 2.0e3;
      s.c.rho[q] = 1000.9;
    }
  for (std::size_t q = 0; q < s.c.size(); q += 9) s.c.wetted[q] = 0;  // dry ones among the wet
  for (std::size_t q = 1; q < s.c.size(); q += 5) s.c.p[q] = -3.0e4;  // suction: cavitation
  return s;
}

void expect_bit_identical_to_the_scalar_loop(PairLoop loop, bool crowd) {
  const Scene base = scene(crowd);
  // The pairs of every kind are there.
  int beyond = 0, dry = 0, back = 0, acting = 0, barrier = 0, lengths[8] = {};
  std::uint32_t longest = 0;
  const double support = base.k.support();
  for (std::size_t i = 0; i < base.f.size(); ++i) {
    const std::uint32_t b = base.fc.start[i], e = base.fc.start[i + 1];
    ++lengths[(e - b) % 8];
    longest = std::max(longest, e - b);
    for (std::uint32_t q = b; q < e; ++q) {
      const std::uint32_t s = base.fc.index[q];
      const double r = norm(base.f.x[i] - base.c.x[s]);
      if (r >= support) {
        ++beyond;
      } else if (!base.c.wetted[s]) {
        ++dry;
      } else if (!base.c.faces(s, base.f.x[i])) {
        ++back;
      } else {
        ++acting;
        barrier +=
            r < 0.25 * (std::sqrt(base.f.m[i] / base.f.rho[i]) + std::sqrt(base.c.volume[s]));
      }
    }
  }
  ASSERT_GT(beyond, 500);
  ASSERT_GT(dry, 100);
  ASSERT_GT(back, 100);
  ASSERT_GT(acting, 1000);
  ASSERT_GT(barrier, 5);
  for (int m : lengths) ASSERT_GT(m, 3);
  if (crowd) {
    ASSERT_GT(longest, kContactLaneChunk);
  } else {
    ASSERT_LT(longest, kContactLaneChunk);
  }

  const Vec2 g{0.0, -9.81};
  for (const double nu : {0.0, 1e-3})
    for (const bool hydrostatic : {true, false})
      for (const double p_barrier : {0.0, 1.3e5})
        for (const RatePass pass : {RatePass::Both, RatePass::Momentum, RatePass::Continuity}) {
          ContactParams prm{30.0, 3.0, nu, g, -1.0e4, hydrostatic, p_barrier};
          Scene lanes = base, scalar = base;
          ContactPairForces kept_lanes, kept_scalar;
          add_contact_to_fluid(lanes.f, lanes.c, lanes.fc, lanes.k, prm, Executor(2), pass,
                               &kept_lanes, loop);
          add_contact_to_fluid(scalar.f, scalar.c, scalar.fc, scalar.k, prm, Executor(1), pass,
                               &kept_scalar, PairLoop::Scalar);
          int changed = 0;
          for (std::size_t i = 0; i < base.f.size(); ++i) {
            ASSERT_TRUE(same_bits(lanes.f.a[i], scalar.f.a[i])) << i << " nu " << nu;
            ASSERT_TRUE(same_bits(lanes.f.drho[i], scalar.f.drho[i])) << i << " nu " << nu;
            changed += !same_bits(lanes.f.a[i], base.f.a[i]) ||
                       !same_bits(lanes.f.drho[i], base.f.drho[i]);
          }
          EXPECT_GT(changed, 60);
          ASSERT_EQ(kept_lanes.acted, kept_scalar.acted);
          ASSERT_EQ(kept_lanes.total.size(), kept_scalar.total.size());
          for (std::size_t q = 0; q < kept_lanes.total.size(); ++q) {
            ASSERT_TRUE(same_bits(kept_lanes.total[q], kept_scalar.total[q])) << q;
            ASSERT_TRUE(same_bits(kept_lanes.viscous[q], kept_scalar.viscous[q])) << q;
          }
        }
  // Cavitating pairs: the limit acts in some (the pair function itself, as the loops call it).
  int cavitating = 0;
  const ContactParams prm{30.0, 3.0, 0.0, g, -1.0e4, true, 0.0};
  for (std::size_t i = 0; i < base.f.size(); ++i)
    for (std::uint32_t q = base.fc.start[i]; q < base.fc.start[i + 1]; ++q) {
      const std::uint32_t s = base.fc.index[q];
      const Vec2 g_rel = prm.gravity - base.c.a[s];
      const ContactPairInput in{base.f.x[i],
                                base.f.v[i],
                                base.f.rho[i],
                                base.f.p[i],
                                base.f.m[i] / base.f.rho[i],
                                base.c.x[s],
                                base.c.v[s],
                                base.c.v_noslip[s],
                                base.c.rho[s],
                                base.c.p[s],
                                base.c.volume[s],
                                g_rel};
      const ContactPairResult r =
          contact_pair<false>(in, base.k, prm.c0, prm.omega, 0.0, prm.cavitation_pressure);
      cavitating += r.active && base.c.wetted[s] && r.p_star == prm.cavitation_pressure;
    }
  EXPECT_GT(cavitating, 50);
}

}  // namespace

TEST(CouplingContactLanes, FourLanesAreBitIdenticalToTheScalarLoop) {
  if (!contact_lanes_avx2_available()) GTEST_SKIP() << "no AVX2 on this CPU or build";
  expect_bit_identical_to_the_scalar_loop(PairLoop::FourLanes, false);
}

TEST(CouplingContactLanes, EightLanesAreBitIdenticalToTheScalarLoop) {
  if (!contact_lanes_avx512_available()) GTEST_SKIP() << "no AVX-512F on this CPU or build";
  expect_bit_identical_to_the_scalar_loop(PairLoop::EightLanes, false);
}

// Lists longer than a chunk go through the scalar loop, the rest of the range through lanes.
TEST(CouplingContactLanes, ListsLongerThanAChunkAreBitIdenticalToTheScalarLoop) {
  if (!contact_lanes_avx2_available()) GTEST_SKIP() << "no AVX2 on this CPU or build";
  expect_bit_identical_to_the_scalar_loop(PairLoop::FourLanes, true);
  if (contact_lanes_avx512_available())
    expect_bit_identical_to_the_scalar_loop(PairLoop::EightLanes, true);
}

// What the runs use (Auto) is one of the two, or the scalar loop.
TEST(CouplingContactLanes, AutoIsBitIdenticalToTheScalarLoop) {
  expect_bit_identical_to_the_scalar_loop(PairLoop::Auto, false);
}
