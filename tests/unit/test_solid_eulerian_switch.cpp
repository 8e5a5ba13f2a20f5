// The Lagrangian → Eulerian switch of failed particles (solid/eulerian_failed_interaction.h,
// spec §5, docs/model.md §3 "Eulerian switch of failed particles"):
//  - a free Johnson–Cook body with a band of failed particles and a rotating, perturbed
//    velocity field keeps Σ m v and Σ m x × v to round-off through the switch and after it
//    (the Eulerian pair forces are central and antisymmetric);
//  - the switched set is the failed particles and their reference neighbours, the rebuilt
//    topology has no pair that touches it, and the Eulerian pairs are symmetric;
//  - a bar whose halves move apart across a failed band separates with the switch (the
//    pieces end more than a kernel support apart and the right piece's momentum stops
//    changing: the band carries no load) and stays connected without it;
//  - 1 and 2 threads give bit-identical states on a body large enough for a team of two;
//  - a body without failed particles is untouched (no Eulerian state, same topology);
//  - the fused sub-step's forces on a body with switched particles equal the standalone
//    operators' (stress, viscosity, hourglass, then add_eulerian_forces, as internal_forces
//    sums them): the Eulerian stress and viscous forces are not dropped from the fused loop.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <span>
#include <vector>

#include "core/parallel.h"
#include "solid/artificial_viscosity.h"
#include "solid/body_dynamics.h"
#include "solid/deformation_gradient.h"
#include "solid/elastic_substep.h"
#include "solid/eulerian_failed_interaction.h"
#include "solid/hourglass_control.h"
#include "solid/materials/material_presets.h"
#include "solid/tl_pair_force.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.001;

// Al 2024-T3 (paper Table 1) with the failure criterion off: only the particles a test marks
// as failed are failed.
ElasticMaterialInput aluminium() {
  ElasticMaterialInput m;
  m.name = "al";
  JohnsonCookModel jc = kAl2024T3.model;
  jc.failure = FailureModel{};
  m.model = jc;
  m.density = kAl2024T3.density;
  m.youngs_modulus = kAl2024T3.youngs_modulus;
  m.poisson_ratio = kAl2024T3.poisson_ratio;
  m.av_alpha = 1.0;
  m.hourglass = 0.1;
  return m;
}

SolidBody bar(int nx, int ny) {
  BodySetup cfg;
  cfg.gravity = false;
  return make_body(box_lattice(nx, ny, kDx), kDx, "tl_sfpm", aluminium(), cfg);
}

std::vector<double>& failed_field(SolidBody& b) {
  for (std::size_t k = 0; k < b.history.fields.size(); ++k)
    if (b.history.fields[k].name == "failed") return b.history.values[k];
  throw std::logic_error("no failed field");
}

// Marks the particles of lattice column `col` (of an nx-wide box lattice) as failed.
void fail_column(SolidBody& b, int nx, int col) {
  std::vector<double>& f = failed_field(b);
  for (std::size_t i = 0; i < b.size(); ++i)
    if (static_cast<int>(i % static_cast<std::size_t>(nx)) == col) f[i] = 1.0;
}

struct Momenta {
  Vec2 p;
  double l = 0.0;
  double scale_p = 0.0, scale_l = 0.0;  // Σ m|v| and Σ m|x||v|: the round-off scales
};
Momenta momenta(const SolidBody& b) {
  Momenta m;
  for (std::size_t i = 0; i < b.size(); ++i) {
    m.p += b.m[i] * b.v[i];
    m.l += b.m[i] * cross(b.x[i], b.v[i]);
    m.scale_p += b.m[i] * norm(b.v[i]);
    m.scale_l += b.m[i] * norm(b.x[i]) * norm(b.v[i]);
  }
  return m;
}

void advance(SolidBody& b, int steps, double dt, const Executor& exec) {
  for (int s = 0; s < steps; ++s) advance_body(b, s * dt, dt, Vec2{}, exec);
}

bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Rigid spin about the bar's centre plus uniform noise in [−5, 5] m/s.
void spin(SolidBody& b, int nx, int ny, Vec2 base, double omega, std::mt19937& gen) {
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  const Vec2 c{0.5 * nx * kDx, 0.5 * ny * kDx};
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vec2 r = b.x[i] - c;
    b.v[i] = base + omega * Vec2{-r.y, r.x} + Vec2{u(gen), u(gen)};
  }
}

// Positions perturbed by up to ±amp dx (a non-affine state), F from them, then column `col`
// of the nx-wide lattice failed and the switch applied: the rebuild's C differs from 1.
void perturb_and_switch(SolidBody& b, int nx, int col, double amp, std::mt19937& gen,
                        const Executor& exec) {
  std::uniform_real_distribution<double> u(-amp * kDx, amp * kDx);
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i] += Vec2{u(gen), u(gen)};
  compute_deformation_gradients(b, b.topology, exec);
  fail_column(b, nx, col);
  ASSERT_TRUE(update_eulerian_switch(b, exec));
}

}  // namespace

TEST(EulerianSwitch, SwitchedSetIsFailedAndTheirReferenceNeighbours) {
  SolidBody b = bar(20, 8);
  const NeighbourList ref = b.topology.pairs;
  fail_column(b, 20, 10);
  ASSERT_TRUE(update_eulerian_switch(b, Executor(1)));
  const EulerianState& e = b.eulerian;
  const std::vector<double>& f = failed_field(b);
  for (std::size_t i = 0; i < b.size(); ++i) {
    bool expect = f[i] > 0.5;
    for (std::uint32_t k = ref.start[i]; k < ref.start[i + 1]; ++k)
      expect = expect || f[ref.index[k]] > 0.5;
    EXPECT_EQ(e.switched[i] != 0, expect) << i;
    // No total-Lagrangian pair touches a switched particle.
    for (std::uint32_t k = b.topology.pairs.start[i]; k < b.topology.pairs.start[i + 1]; ++k) {
      EXPECT_FALSE(e.switched[i]) << i;
      EXPECT_FALSE(e.switched[b.topology.pairs.index[k]]) << i;
    }
  }
  EXPECT_GT(e.members.size(), 8u * 3u - 1u);  // the band and a neighbour column each side
  // Eulerian pairs are symmetric and each has a switched end.
  build_eulerian_pairs(b, b.x);
  const NeighbourList& p = e.pairs;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < b.size(); ++i)
    for (std::uint32_t k = p.start[i]; k < p.start[i + 1]; ++k) {
      const std::uint32_t j = p.index[k];
      ++pairs;
      EXPECT_TRUE(e.switched[i] || e.switched[j]);
      const auto jb = p.index.begin() + p.start[j], je = p.index.begin() + p.start[j + 1];
      EXPECT_EQ(std::count(jb, je, static_cast<std::uint32_t>(i)), 1) << i << " " << j;
    }
  EXPECT_GT(pairs, 0u);
}

TEST(EulerianSwitch, BodyWithoutFailureIsUntouched) {
  SolidBody b = bar(20, 8);
  const NeighbourList ref = b.topology.pairs;
  EXPECT_FALSE(update_eulerian_switch(b, Executor(1)));
  advance(b, 3, 2e-7, Executor(1));
  EXPECT_FALSE(b.eulerian.active);
  EXPECT_TRUE(b.eulerian.switched.empty());
  EXPECT_EQ(b.topology.pairs.index, ref.index);
}

// A free body spinning at 2000 rad/s with a random velocity perturbation (±5 m/s) and a
// failed column through its middle: 60 fluid steps of about 3 sub-steps.
TEST(EulerianSwitch, FreeBodyKeepsLinearAndAngularMomentum) {
  const int nx = 24, ny = 10;
  SolidBody b = bar(nx, ny);
  std::mt19937 gen(7);
  spin(b, nx, ny, Vec2{3.0, -1.0}, 2000.0, gen);
  fail_column(b, nx, 12);
  refresh_internal_forces(b, Executor(1));
  const Momenta m0 = momenta(b);
  const double dt = 3.0 * stable_time_step(b);
  advance(b, 60, dt, Executor(1));
  ASSERT_TRUE(b.eulerian.active);
  const Momenta m1 = momenta(b);
  EXPECT_LT(norm(m1.p - m0.p), 1e-13 * m0.scale_p) << m1.p.x - m0.p.x << " " << m1.p.y - m0.p.y;
  EXPECT_LT(std::abs(m1.l - m0.l), 1e-13 * m0.scale_l) << m1.l - m0.l;
  std::printf("|dp|/sum m|v| = %.2e, |dL|/sum m|x||v| = %.2e, switched %zu of %zu\n",
              norm(m1.p - m0.p) / m0.scale_p, std::abs(m1.l - m0.l) / m0.scale_l,
              b.eulerian.members.size(), b.size());
}

// Halves of a 40 x 10 mm bar pulled apart at ±200 m/s across a failed column (failure
// criterion off, so nothing else fails). With the switch the pieces separate: the gap between
// the last particle of the left piece and the first of the right one exceeds the support 2h,
// and the right piece's momentum stops changing. Without it the failed column still joins
// the pieces through the total-Lagrangian sums of its neighbours and the right piece is
// pulled back.
struct Opening {
  double gap = 0.0;          // min x of the right piece − max x of the left piece [m]
  double late_change = 0.0;  // relative change of the right piece's momentum, last 20 µs
  double kept = 0.0;         // right piece's momentum at the end / at the start
};
Opening pull_apart(bool with_switch) {
  const int nx = 40, ny = 10, band = 20;
  SolidBody b = bar(nx, ny);
  b.eulerian_switch = with_switch;
  auto right = [&](std::size_t i) { return static_cast<int>(i % nx) > band; };
  auto left = [&](std::size_t i) { return static_cast<int>(i % nx) < band; };
  for (std::size_t i = 0; i < b.size(); ++i)
    b.v[i] = Vec2{right(i) ? 200.0 : (left(i) ? -200.0 : 0.0), 0.0};
  fail_column(b, nx, band);
  refresh_internal_forces(b, Executor(1));
  auto p_right = [&] {
    double p = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i)
      if (right(i)) p += b.m[i] * b.v[i].x;
    return p;
  };
  const double p0 = p_right();
  const double dt = 1e-6;
  advance(b, 40, dt, Executor(1));
  const double p40 = p_right();
  advance(b, 20, dt, Executor(1));
  const double p60 = p_right();
  Opening o;
  double xl = -1e9, xr = 1e9;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (left(i)) xl = std::max(xl, b.x[i].x);
    if (right(i)) xr = std::min(xr, b.x[i].x);
  }
  o.gap = xr - xl;
  o.late_change = std::abs(p60 - p40) / p0;
  o.kept = p60 / p0;
  return o;
}

TEST(EulerianSwitch, CrackOpensWithTheSwitchAndNotWithout) {
  const Opening with = pull_apart(true);
  const Opening without = pull_apart(false);
  const double support = 2.0 * 1.3 * kDx;
  EXPECT_GT(with.gap, support) << "gap " << with.gap;
  EXPECT_LT(with.late_change, 1e-3) << "the failed band still carries load";
  EXPECT_GT(without.late_change, 10.0 * with.late_change);
  EXPECT_LT(without.kept, with.kept);
  std::printf("with switch: gap %.3f mm, momentum kept %.4f, late change %.2e\n", with.gap * 1e3,
              with.kept, with.late_change);
  std::printf("without:     gap %.3f mm, momentum kept %.4f, late change %.2e\n", without.gap * 1e3,
              without.kept, without.late_change);
}

// 100 x 90 particles (a team of two) with a failed column, 1 vs 2 threads.
TEST(EulerianSwitch, OneAndTwoThreadsBitIdentical) {
  const int nx = 100, ny = 90;
  auto run = [&](int threads) {
    SolidBody b = bar(nx, ny);
    for (std::size_t i = 0; i < b.size(); ++i)
      b.v[i] = Vec2{static_cast<int>(i % nx) > 50 ? 100.0 : -100.0, 0.0};
    fail_column(b, nx, 50);
    refresh_internal_forces(b, Executor(1));
    const Executor exec(threads);
    EXPECT_EQ(exec.threads_for(b.size(), kSubstepParticlesPerThread), threads);
    advance(b, 2, 4.0 * stable_time_step(b), exec);
    EXPECT_TRUE(b.eulerian.active);
    return b;
  };
  const SolidBody a = run(1), c = run(2);
  std::size_t diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff += !(same(a.x[i].x, c.x[i].x) && same(a.x[i].y, c.x[i].y));
    diff += !(same(a.v[i].x, c.v[i].x) && same(a.v[i].y, c.v[i].y));
    diff += !(same(a.P[i].xx, c.P[i].xx) && same(a.P[i].xy, c.P[i].xy) &&
              same(a.P[i].yy, c.P[i].yy) && same(a.F[i].yx, c.F[i].yx));
    diff += !same(a.e[i], c.e[i]);
  }
  EXPECT_EQ(diff, 0u);
  EXPECT_TRUE(same(a.dissipated, c.dissipated));
}

// One fused sub-step on a spinning, perturbed body with a failed column, then the same forces
// from the operators at the sub-step's end state (x, F, P) and half-step velocity. Before
// this test, dropping the Eulerian stress force from the fused loop passed every test here.
TEST(EulerianSwitch, FusedSubstepForcesEqualTheOperators) {
  const int nx = 24, ny = 10;
  SolidBody b = bar(nx, ny);
  std::mt19937 gen(11);
  spin(b, nx, ny, Vec2{}, 1000.0, gen);
  const Executor exec(1);
  perturb_and_switch(b, nx, 12, 0.03, gen, exec);
  if (HasFatalFailure()) return;
  refresh_internal_forces(b, exec);
  run_elastic_substeps(b, 1, 0.5 * stable_time_step(b), Vec2{}, exec);
  const std::span<const Vec2> vh = b.substep.vhalf;  // the one sub-step's v½

  const std::size_t n = b.size();
  std::vector<Vec2> fs(n), fav(n), fhg(n), es(n), ev(n);
  std::vector<double> heat(n), eq(n);
  compute_stress_forces(b, b.topology, exec, fs);
  compute_artificial_viscosity(b, b.topology, vh, exec, fav, heat);
  compute_hourglass_forces(b, b.topology, b.material.hourglass, exec, fhg);
  add_eulerian_forces(b, vh, exec, fs, fav, heat);
  add_eulerian_forces(b, vh, exec, es, ev, eq);  // the Eulerian parts alone
  double scale = 0.0, dev = 0.0, dev_av = 0.0, euler_s = 0.0, euler_v = 0.0, scale_v = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    scale = std::max(scale, norm(b.f_int[i]));
    scale_v = std::max(scale_v, norm(fav[i]));
    dev = std::max(dev, norm(b.f_int[i] - (fs[i] + fav[i] + fhg[i])));
    dev_av = std::max(dev_av, norm(b.f_av[i] - fav[i]));
    euler_s = std::max(euler_s, norm(es[i]));
    euler_v = std::max(euler_v, norm(ev[i]));
  }
  std::printf("max |f_int| %.3e N, fused - operators %.2e, Eulerian stress %.3e, viscous %.3e N\n",
              scale, dev, euler_s, euler_v);
  // The Eulerian terms matter here (else the comparison could not see them dropped).
  ASSERT_GT(euler_s, 1e-2 * scale);
  ASSERT_GT(euler_v, 1e-2 * scale_v);
  EXPECT_LT(dev, 1e-12 * scale);
  EXPECT_LT(dev_av, 1e-12 * scale_v);
}

// A bar deformed non-affinely (positions perturbed by ±5 % of dx), then a column fails: the
// intact particles next to it lose reference neighbours, and their kinematic F from the
// remaining one-sided set jumps. The switch keeps F continuous through SolidBody::F_rebase
// (else the jump enters the stress as a strain increment no force did work for), and after
// the rebuild F still follows the motion: a further uniform stretch S maps F to S F.
TEST(EulerianSwitch, DeformationGradientIsContinuousAcrossTheRebuild) {
  const int nx = 24, ny = 10;
  SolidBody b = bar(nx, ny);
  std::mt19937 gen(3);
  const Executor exec(1);
  perturb_and_switch(b, nx, 12, 0.05, gen, exec);
  if (HasFatalFailure()) return;
  const std::vector<Mat2> before = b.F;  // the switch leaves F as it was
  double jump = 0.0, kept = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.eulerian.switched[i]) continue;
    const Mat2 d = reference_gradient(b.topology, b.x, i) - before[i];  // what it would be
    jump = std::max({jump, std::abs(d.xx), std::abs(d.xy), std::abs(d.yx), std::abs(d.yy)});
  }
  compute_deformation_gradients(b, b.topology, exec);
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.eulerian.switched[i]) continue;
    const Mat2 d = b.F[i] - before[i];
    kept = std::max({kept, std::abs(d.xx), std::abs(d.xy), std::abs(d.yx), std::abs(d.yy)});
  }
  std::printf("kinematic F jump at the rebuild %.3e, F change with the rebase %.3e\n", jump, kept);
  ASSERT_GT(jump, 1e-3);  // the rebuild would move F (else this test could not see a fix)
  EXPECT_LT(kept, 1e-14);
  // A uniform 1 % stretch in x after the rebuild, x' = S x with S = diag(1.01, 1): F' = S F.
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i].x *= 1.01;
  compute_deformation_gradients(b, b.topology, exec);
  double err = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.eulerian.switched[i]) continue;
    const Mat2& f = before[i];
    const Mat2 expect{1.01 * f.xx, 1.01 * f.xy, f.yx, f.yy};
    const Mat2 d = b.F[i] - expect;
    err = std::max({err, std::abs(d.xx), std::abs(d.xy), std::abs(d.yx), std::abs(d.yy)});
  }
  EXPECT_LT(err, 1e-12) << "F does not follow the motion after the rebuild";
}

// After a rebuild F = F_kin C with C ≠ 1 (a perturbed bar, a failed column). The total-
// Lagrangian stress force must be the gradient of Σ V0 Ψ(F_kin C), i.e. its power for any
// velocity field equals minus the stress power Σ V0 P : (Ḟ_kin C) that goes into the internal
// energy. With P instead of P Cᵀ in the pair sums the two differ by O(|C − 1|).
TEST(EulerianSwitch, StressForceIsConjugateToTheRebasedF) {
  const int nx = 24, ny = 10;
  SolidBody b = bar(nx, ny);
  std::mt19937 gen(5);
  const Executor exec(1);
  perturb_and_switch(b, nx, 12, 0.05, gen, exec);
  if (HasFatalFailure()) return;
  std::uniform_real_distribution<double> u(-0.05 * kDx, 0.05 * kDx);
  // A stressed state: P from the law at a further random deformation.
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i] += Vec2{u(gen), u(gen)};
  for (std::size_t i = 0; i < b.size(); ++i)
    b.P[i] = Mat2{1e8 * (1.0 + u(gen) / kDx), 2e7 * u(gen) / kDx, 3e7 * u(gen) / kDx,
                  -5e7 * (1.0 + u(gen) / kDx)};
  std::vector<Vec2> v(b.size()), fs(b.size());
  for (Vec2& vi : v) vi = Vec2{u(gen), u(gen)} / kDx;
  compute_stress_forces(b, b.topology, exec, fs);
  double force_power = 0.0, stress_power = 0.0, scale = 0.0, rebase = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.eulerian.switched[i]) continue;
    force_power += dot(fs[i], v[i]);
    const double sp = b.V0[i] * ddot(b.P[i], reference_gradient(b.topology, v, i) * b.F_rebase[i]);
    stress_power += sp;
    scale += std::abs(sp);
    const Mat2 d = b.F_rebase[i] - Mat2::identity();
    rebase = std::max({rebase, std::abs(d.xx), std::abs(d.xy), std::abs(d.yx), std::abs(d.yy)});
  }
  std::printf("max |C - 1| %.3e, force power %.6e W/m, stress power %.6e W/m\n", rebase,
              force_power, stress_power);
  ASSERT_GT(rebase, 1e-3);
  EXPECT_LT(std::abs(force_power + stress_power), 1e-10 * scale);
}

// The Eulerian pair force is minus the derivative of the switched particles' stress power
// (docs/model.md §3 "Eulerian switch", Eq. E1): for any velocity field its power equals
// −Σ_switched V0 P : Ḟ with Ḟ = L F, the rate eulerian_motion integrates into F and e. Every
// particle carries a stress, so a pair force that let an intact particle's stress act in the
// Eulerian pairs (work reaching no stress power), or dropped the correction K from the force
// while L keeps it, fails this. The torque of the pair forces vanishes where K corrects.
TEST(EulerianSwitch, EulerianForceIsConjugateToTheSwitchedStressPower) {
  const int nx = 24, ny = 10;
  SolidBody b = bar(nx, ny);
  std::mt19937 gen(11);
  const Executor exec(1);
  perturb_and_switch(b, nx, 12, 0.05, gen, exec);
  if (HasFatalFailure()) return;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // A stressed state with symmetric Cauchy stresses: P = J σ F⁻ᵀ.
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double sxy = 3e7 * u(gen);
    const Mat2 sigma{1e8 * (1.0 + 0.3 * u(gen)), sxy, sxy, -5e7 * (1.0 + 0.3 * u(gen))};
    b.P[i] = det(b.F[i]) * (sigma * transpose(inverse(b.F[i])));
  }
  const std::size_t n = b.size();
  std::vector<Vec2> v(n), fs(n), fav(n);
  std::vector<double> heat(n);
  for (Vec2& vi : v) vi = Vec2{u(gen), u(gen)};
  add_eulerian_forces(b, v, exec, fs, fav, heat);
  double force_power = 0.0, stress_power = 0.0, scale = 0.0, torque = 0.0, tscale = 0.0;
  double max_k = 0.0, fscale = 0.0;
  Vec2 fsum;
  for (std::size_t i = 0; i < n; ++i) {
    fsum += fs[i];
    fscale += norm(fs[i]);
    force_power += dot(fs[i], v[i]);
    torque += cross(b.x[i], fs[i]);
    tscale += norm(b.x[i]) * norm(fs[i]);
    if (!b.eulerian.switched[i]) continue;
    Mat2 F_new, Fdot, K;
    eulerian_motion(b, b.x, v, 0.0, i, F_new, Fdot, K);
    const double sp = b.V0[i] * ddot(b.P[i], Fdot);
    stress_power += sp;
    scale += std::abs(sp);
    const Mat2 d = K - Mat2::identity();
    max_k = std::max({max_k, std::abs(d.xx), std::abs(d.xy), std::abs(d.yx), std::abs(d.yy)});
  }
  std::printf(
      "max |K - 1| %.3e, force power %.6e W/m, stress power %.6e W/m, torque %.2e of %.2e\n", max_k,
      force_power, stress_power, torque, tscale);
  ASSERT_GT(max_k, 1e-2);  // the correction matters here
  EXPECT_LT(std::abs(force_power + stress_power), 1e-10 * scale);
  EXPECT_LT(std::abs(torque), 1e-12 * tscale);
  EXPECT_LT(norm(fsum), 1e-14 * fscale);  // pair forces antisymmetric: Σ f = 0
}
