// Pair forces of the elastic body (spec §3, Eq. 10): transposes (discrete virial identity
// and f = −∂E/∂x by finite differences), conservation of linear and angular momentum to
// round-off, zero interior force under uniform stress, zero stress under rigid rotation,
// and the dissipative sign of the artificial viscosity. Both schemes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/parallel.h"
#include "solid/artificial_viscosity.h"
#include "solid/deformation_gradient.h"
#include "solid/hourglass_control.h"
#include "solid/stress_update.h"
#include "solid/tl_pair_force.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.01;
const Executor kExec(1);

class PairForce : public ::testing::TestWithParam<const char*> {};

SolidBody deformed_body(const char* scheme, double hourglass, unsigned seed) {
  SolidBody b = make_body(perturbed_lattice(8, 7, kDx, 0.15, seed), kDx, scheme,
                          plate_material(hourglass, 1.0));
  std::mt19937 gen(seed + 1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Mat2 A{1.05, 0.1, -0.04, 0.97};
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.x[i] = A * b.X[i] + Vec2{0.05 * kDx * u(gen), 0.05 * kDx * u(gen)};
    b.v[i] = {u(gen), u(gen)};
  }
  compute_deformation_gradients(b, b.topology, kExec);
  update_stress(b, b.F, 0.0, kExec);
  return b;
}

double total_energy(SolidBody& b, double hourglass) {
  compute_deformation_gradients(b, b.topology, kExec);
  double e = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) e += b.V0[i] * strain_energy_density(b, i);
  return e + hourglass_energy(b, b.topology, hourglass, kExec);
}

}  // namespace

TEST_P(PairForce, VirialIdentityFixesTheTranspose) {
  // For any per-particle P: Σ_k X_k ⊗ f_k = −Σ_i V0_i P_iᵀ exactly (∇0 X = I). A force
  // written with Pᵀ, or with g_ji in place of g_ij, fails this.
  SolidBody b = make_body(perturbed_lattice(8, 7, kDx, 0.15, 3), kDx, GetParam(), plate_material());
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1e5, 1e5);
  for (Mat2& P : b.P) P = {u(gen), u(gen), u(gen), u(gen)};
  std::vector<Vec2> f(b.size());
  compute_stress_forces(b, b.topology, kExec, f);
  Mat2 lhs, rhs;
  double scale = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    lhs += outer(b.X[i], f[i]);
    rhs -= b.V0[i] * transpose(b.P[i]);
    scale += b.V0[i] * (std::abs(b.P[i].xx) + std::abs(b.P[i].xy) + std::abs(b.P[i].yx) +
                        std::abs(b.P[i].yy));
  }
  const Mat2 d = lhs - rhs;
  EXPECT_LT(std::abs(d.xx) + std::abs(d.xy) + std::abs(d.yx) + std::abs(d.yy), 1e-12 * scale);
}

TEST_P(PairForce, ForcesAreEnergyGradients) {
  // Stress force = −∂(Σ V0 Ψ(F))/∂x and hourglass force = −∂E_hg/∂x (central differences).
  const double hg = 0.7;
  SolidBody b = deformed_body(GetParam(), hg, 11);
  std::vector<Vec2> fs(b.size()), fh(b.size());
  compute_stress_forces(b, b.topology, kExec, fs);
  compute_hourglass_forces(b, b.topology, hg, kExec, fh);
  const double eps = 1e-7 * kDx;
  double fmax = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) fmax = std::max(fmax, norm(fs[i] + fh[i]));
  for (std::size_t i : {0ul, 9ul, 20ul, 27ul, 55ul}) {
    for (int c = 0; c < 2; ++c) {
      SolidBody p = b, m = b;
      (c == 0 ? p.x[i].x : p.x[i].y) += eps;
      (c == 0 ? m.x[i].x : m.x[i].y) -= eps;
      const double dE = (total_energy(p, hg) - total_energy(m, hg)) / (2 * eps);
      const double f = c == 0 ? fs[i].x + fh[i].x : fs[i].y + fh[i].y;
      EXPECT_NEAR(-dE, f, 1e-5 * fmax) << "particle " << i << " comp " << c;
    }
  }
}

TEST_P(PairForce, MomentumConservedToRoundOff) {
  SolidBody b = deformed_body(GetParam(), 1.0, 21);
  std::vector<Vec2> fs(b.size()), fv(b.size()), fh(b.size());
  std::vector<double> q(b.size());
  compute_stress_forces(b, b.topology, kExec, fs);
  compute_artificial_viscosity(b, b.topology, b.v, kExec, fv, q);
  compute_hourglass_forces(b, b.topology, 1.0, kExec, fh);
  for (const auto* f : {&fs, &fv, &fh}) {
    Vec2 sum;
    double torque = 0.0, scale = 0.0, tscale = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      sum += (*f)[i];
      torque += cross(b.x[i], (*f)[i]);
      scale += norm((*f)[i]);
      tscale += norm(b.x[i]) * norm((*f)[i]);
    }
    ASSERT_GT(scale, 0.0);
    EXPECT_LT(norm(sum), 1e-13 * scale);
    EXPECT_LT(std::abs(torque), 1e-13 * tscale);
  }
  // Artificial viscosity only dissipates: Σ f·v ≤ 0 and the heating matches it.
  double power = 0.0, heat = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    power += dot(fv[i], b.v[i]);
    heat += q[i];
  }
  EXPECT_LT(power, 0.0);
  EXPECT_NEAR(heat, -power, 1e-12 * heat);
}

TEST_P(PairForce, UniformStressGivesZeroInteriorForce) {
  // Affine deformation: F exact everywhere, uniform P, so interior particles feel no force
  // and only the free surfaces carry the (unbalanced) traction. The right-hand quarter
  // carries −P·e_x per unit height (the pull of the rest of the body across a cut).
  // "Interior": every neighbour's neighbour has a full stencil (2 layers TL-SFPM, 6 TLSPH).
  const int nx = 20, ny = 16;
  const int margin = std::string(GetParam()) == "tlsph" ? 6 : 2;
  SolidBody b = make_body(box_lattice(nx, ny, kDx), kDx, GetParam(), plate_material());
  const Mat2 A{1.03, 0.02, 0.05, 0.99};
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i] = A * b.X[i];
  compute_deformation_gradients(b, b.topology, kExec);
  update_stress(b, b.F, 0.0, kExec);
  const Mat2 P = svk_pk1(std::get<StVenantKirchhoff>(b.material.law).parameters(), A);
  std::vector<Vec2> f(b.size());
  compute_stress_forces(b, b.topology, kExec, f);
  const double unit = (std::abs(P.xx) + std::abs(P.yy)) * kDx;  // boundary force scale
  for (int j = margin; j < ny - margin; ++j)
    for (int i = margin; i < nx - margin; ++i) EXPECT_LT(norm(f[j * nx + i]), 1e-10 * unit);
  // A quarter-body cut through the interior (x > 0.75 L): force = −P e_x · H.
  Vec2 right;
  for (std::size_t i = 0; i < b.size(); ++i)
    if (b.X[i].x > 0.75 * nx * kDx) right += f[i];
  const Vec2 want = -(ny * kDx) * Vec2{P.xx, P.yx};
  EXPECT_NEAR(right.x, want.x, 1e-9 * unit);
  EXPECT_NEAR(right.y, want.y, 1e-9 * unit);
}

TEST_P(PairForce, RigidRotationGivesZeroStressAndForce) {
  std::vector<double> V0;
  SolidBody b =
      make_body(ring_lattice(0.05, 3, kDx, &V0), kDx, GetParam(), plate_material(1.0), {}, V0);
  const double th = 0.8;
  const Mat2 Q{std::cos(th), -std::sin(th), std::sin(th), std::cos(th)};
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i] = Q * b.X[i] + Vec2{1.0, 2.0};
  compute_deformation_gradients(b, b.topology, kExec);
  update_stress(b, b.F, 0.0, kExec);
  std::vector<Vec2> fs(b.size()), fh(b.size());
  compute_stress_forces(b, b.topology, kExec, fs);
  compute_hourglass_forces(b, b.topology, 1.0, kExec, fh);
  const double E = b.material.youngs_modulus;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Mat2& P = b.P[i];
    EXPECT_LT(std::abs(P.xx) + std::abs(P.xy) + std::abs(P.yx) + std::abs(P.yy), 1e-9 * E);
    EXPECT_LT(norm(fs[i]) + norm(fh[i]), 1e-9 * E * kDx);
  }
  EXPECT_LT(hourglass_energy(b, b.topology, 1.0, kExec), 1e-20 * E);
}

INSTANTIATE_TEST_SUITE_P(Schemes, PairForce, ::testing::Values("tl_sfpm", "tlsph"));
