// The low-dissipation limiter INSIDE the fused GSPH pass (fluid/gsph_fluid_rates.cpp writes
// solve_riemann() out by hand, so riemann_solver.h being right proves nothing about it).
// Two fluid particles on a line, no gravity, no viscosity: the pass must give exactly the
// pair force and continuity term of spec §2 with
//   beta = min(omega * max(U_L - U_R, 0), c0),
//   p*   = (rho_R p_L + rho_L p_R + beta rho_L rho_R (U_L - U_R)) / (rho_L + rho_R),
//   U*   = (rho_L U_L + rho_R U_R + (p_L - p_R)/c0) / (rho_L + rho_R),
//   a_i = 2 V_j p* / rho_i W'(r) e_ij,  drho_i/dt = -2 rho_i V_j (U_L - U*) W'(r)
// (e_ij from i to j; grad_i W_ij = -W'(r) e_ij, v_i - v* = (U_L - U*) e_ij along the pair). The
// expected values are computed here from these formulas, not through solve_riemann(). Three regimes
// are checked: separating (beta = 0), approaching below the cap (beta = omega du) and approaching
// above it (beta = c0), each with unequal densities and pressures so every term matters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/cell_grid.h"
#include "fluid/gsph_fluid_rates.h"

using namespace slamsph;

namespace {

struct PairCase {
  double uL, uR;  // velocities of i and j along e_ij = (x_j - x_i)/r [m/s]
};

struct Expected {
  Vec2 a_i, a_j;
  double drho_i, drho_j;
};

constexpr double kC0 = 20.0, kOmega = 3.0, kDx = 0.01;

FluidParticles two_particles(const PairCase& pc, Vec2 e, double r) {
  FluidParticles f;
  f.resize(2);
  f.x[0] = {0.3, 0.2};
  f.x[1] = f.x[0] + r * e;
  f.v[0] = pc.uL * e + 0.7 * Vec2{-e.y, e.x};  // tangential parts must not matter
  f.v[1] = pc.uR * e - 0.2 * Vec2{-e.y, e.x};
  f.rho[0] = 1003.0;
  f.rho[1] = 998.0;
  f.p[0] = 420.0;
  f.p[1] = -130.0;
  f.m[0] = 1003.0 * kDx * kDx;
  f.m[1] = 0.9 * 998.0 * kDx * kDx;
  f.id = {0, 1};
  return f;
}

Expected by_hand(const FluidParticles& f, const PairCase& pc, Vec2 e, double r, const Kernel& k) {
  const double rL = f.rho[0], rR = f.rho[1], pL = f.p[0], pR = f.p[1];
  const double Vi = f.m[0] / rL, Vj = f.m[1] / rR;
  const double du = pc.uL - pc.uR;
  const double beta = std::min(kOmega * std::max(du, 0.0), kC0);
  const double ps = (rR * pL + rL * pR + beta * rL * rR * du) / (rL + rR);
  const double us = (rL * pc.uL + rR * pc.uR + (pL - pR) / kC0) / (rL + rR);
  const double dW = k.dw(r);  // W'(r) < 0
  Expected x;
  x.a_i = (-2.0 * Vj * ps / rL * dW) * (-1.0 * e);  // grad_i W = W' (x_i - x_j)/r = -W' e
  x.a_j = (-2.0 * Vi * ps / rR * dW) * e;
  x.drho_i = -2.0 * rL * Vj * (pc.uL - us) * dW;
  x.drho_j = -2.0 * rR * Vi * (us - pc.uR) * dW;
  return x;
}

void check(const PairCase& pc, double* beta_used) {
  const Kernel k(KernelType::WendlandC2, 1.3 * kDx);
  const Vec2 e = Vec2{3.0, 4.0} / 5.0;
  const double r = 0.9 * kDx;
  FluidParticles f = two_particles(pc, e, r);
  CellGrid grid;
  grid.build(f.x, k.support());
  BandedPairs nl;
  build_banded_pairs(f.x, grid, k.support(), Executor(1), nl);
  compute_gsph_fluid_rates(f, nl, k, {kC0, kOmega, 0.0, {0.0, 0.0}}, Executor(1));
  const Expected x = by_hand(f, pc, e, r, k);
  const double sa = norm(x.a_i), sd = std::abs(x.drho_i) + std::abs(x.drho_j);
  ASSERT_GT(sa, 1.0);
  EXPECT_NEAR(f.a[0].x, x.a_i.x, 1e-12 * sa);
  EXPECT_NEAR(f.a[0].y, x.a_i.y, 1e-12 * sa);
  EXPECT_NEAR(f.a[1].x, x.a_j.x, 1e-12 * sa);
  EXPECT_NEAR(f.a[1].y, x.a_j.y, 1e-12 * sa);
  EXPECT_NEAR(f.drho[0], x.drho_i, 1e-12 * sd);
  EXPECT_NEAR(f.drho[1], x.drho_j, 1e-12 * sd);
  *beta_used = std::min(kOmega * std::max(pc.uL - pc.uR, 0.0), kC0);
}

}  // namespace

TEST(GsphFusedLimiter, SeparatingPairHasNoDissipation) {
  double beta = -1.0;
  check({-0.8, 1.1}, &beta);  // U_L < U_R: moving apart
  EXPECT_EQ(beta, 0.0);
}

TEST(GsphFusedLimiter, ApproachingPairBelowTheCap) {
  double beta = -1.0;
  check({1.5, -0.5}, &beta);  // du = 2: beta = omega du = 6 < c0
  EXPECT_EQ(beta, 6.0);
}

TEST(GsphFusedLimiter, ApproachingPairAtTheAcousticCap) {
  double beta = -1.0;
  check({5.0, -4.0}, &beta);  // du = 9: omega du = 27 > c0 = 20
  EXPECT_EQ(beta, kC0);
}
