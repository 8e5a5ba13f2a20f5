// The fused elastic sub-step (solid/elastic_substep.h) against the operator sequence it
// replaces: the same kick–drift–kick loop written with the standalone operators
// (deformation gradient, update_stress, stress force, artificial viscosity, hourglass
// control, one pass each) gives the same positions, velocities, F, P, forces, internal
// energy, history and energy accumulators to round-off (relative 1e-12; the fused loop sums
// the pair forces in another order), for SVK and for J2 plasticity (which exercises the
// law's history). Also: the synchronisation per sub-step (one parallel region per call, two
// barriers per sub-step plus one) and the thread count by body size, and 1 vs 2 threads
// bit-identical on a body large enough for a team of two.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/parallel.h"
#include "solid/artificial_viscosity.h"
#include "solid/deformation_gradient.h"
#include "solid/elastic_substep.h"
#include "solid/hourglass_control.h"
#include "solid/stress_update.h"
#include "solid/substep_pair_lanes.h"
#include "solid/tl_pair_force.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.005;

bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(Vec2 a, Vec2 b) {
  return same(a.x, b.x) && same(a.y, b.y);
}
bool same(const Mat2& a, const Mat2& b) {
  return same(a.xx, b.xx) && same(a.xy, b.xy) && same(a.yx, b.yx) && same(a.yy, b.yy);
}
template <class T>
long first_difference(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(a[i], b[i])) return static_cast<long>(i);
  return -1;
}

void expect_identical(const SolidBody& a, const SolidBody& b) {
  EXPECT_EQ(first_difference(a.x, b.x), -1) << "x";
  EXPECT_EQ(first_difference(a.v, b.v), -1) << "v";
  EXPECT_EQ(first_difference(a.a, b.a), -1) << "a";
  EXPECT_EQ(first_difference(a.F, b.F), -1) << "F";
  EXPECT_EQ(first_difference(a.P, b.P), -1) << "P";
  EXPECT_EQ(first_difference(a.e, b.e), -1) << "e";
  EXPECT_EQ(first_difference(a.f_int, b.f_int), -1) << "f_int";
  ASSERT_EQ(a.history.values.size(), b.history.values.size());
  for (std::size_t k = 0; k < a.history.values.size(); ++k)
    EXPECT_EQ(first_difference(a.history.values[k], b.history.values[k]), -1) << "history " << k;
  EXPECT_EQ(a.history.updates, b.history.updates);
  EXPECT_TRUE(same(a.dissipated, b.dissipated)) << a.dissipated << " " << b.dissipated;
  EXPECT_TRUE(same(a.hourglass_work, b.hourglass_work));
  EXPECT_TRUE(same(a.external_work, b.external_work));
  EXPECT_EQ(first_difference(a.f_av, b.f_av), -1) << "f_av";
  EXPECT_EQ(first_difference(a.f_hg, b.f_hg), -1) << "f_hg";
  EXPECT_TRUE(same(a.clamp_work, b.clamp_work));
}

double magnitude(double a) {
  return std::abs(a);
}
double magnitude(Vec2 a) {
  return norm(a);
}
double magnitude(const Mat2& a) {
  return std::sqrt(ddot(a, a));
}
// max_i |a_i − b_i| / max_i |b_i| (0 for two zero fields).
template <class T>
double relative_difference(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return 1.0;
  double diff = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, magnitude(a[i] - b[i]));
    scale = std::max(scale, magnitude(b[i]));
  }
  return scale > 0.0 ? diff / scale : diff;
}

// Round-off agreement: the fused loop sums V0_i P_i g_ij and G_i g_ij of i's own side as
// V0_i P_i Σ_j g_ij and G_i Σ_j g_ij and multiplies V0_j P_j before the gradient
// (elastic_substep.h), so its forces differ from the operators' in the last bits; over the
// 21 sub-steps every field of the body stays within `tol` of the reference relative to the
// field's largest entry. tol = 1e-12, eight times the largest difference measured (1.3e-13,
// the viscous force; x and F ≤ 6e-16, v, P and e ≤ 6e-14: the forces are small differences
// of pair terms, and the dynamics carries their last bits over the sub-steps). Print the
// differences with SLAMSPH_PRINT_DIFF=1.
void expect_round_off(const SolidBody& a, const SolidBody& b, double tol) {
  EXPECT_LE(relative_difference(a.x, b.x), tol) << "x";
  EXPECT_LE(relative_difference(a.v, b.v), tol) << "v";
  EXPECT_LE(relative_difference(a.a, b.a), tol) << "a";
  EXPECT_LE(relative_difference(a.F, b.F), tol) << "F";
  EXPECT_LE(relative_difference(a.P, b.P), tol) << "P";
  EXPECT_LE(relative_difference(a.e, b.e), tol) << "e";
  EXPECT_LE(relative_difference(a.f_int, b.f_int), tol) << "f_int";
  EXPECT_LE(relative_difference(a.f_av, b.f_av), tol) << "f_av";
  EXPECT_LE(relative_difference(a.f_hg, b.f_hg), tol) << "f_hg";
  ASSERT_EQ(a.history.values.size(), b.history.values.size());
  for (std::size_t k = 0; k < a.history.values.size(); ++k)
    EXPECT_LE(relative_difference(a.history.values[k], b.history.values[k]), tol)
        << "history " << k;
  EXPECT_EQ(a.history.updates, b.history.updates);
  EXPECT_LE(std::abs(a.dissipated - b.dissipated), tol * std::abs(b.dissipated));
  EXPECT_LE(std::abs(a.hourglass_work - b.hourglass_work), tol * std::abs(b.hourglass_work));
  EXPECT_LE(std::abs(a.external_work - b.external_work), tol * std::abs(b.external_work));
  if (std::getenv("SLAMSPH_PRINT_DIFF"))
    std::printf(
        "x %.2g v %.2g a %.2g F %.2g P %.2g e %.2g f_int %.2g f_av %.2g f_hg %.2g "
        "diss %.2g hg %.2g ext %.2g\n",
        relative_difference(a.x, b.x), relative_difference(a.v, b.v), relative_difference(a.a, b.a),
        relative_difference(a.F, b.F), relative_difference(a.P, b.P), relative_difference(a.e, b.e),
        relative_difference(a.f_int, b.f_int), relative_difference(a.f_av, b.f_av),
        relative_difference(a.f_hg, b.f_hg),
        std::abs(a.dissipated - b.dissipated) / std::abs(b.dissipated),
        std::abs(a.hourglass_work - b.hourglass_work) / std::abs(b.hourglass_work),
        std::abs(a.external_work - b.external_work) / std::abs(b.external_work));
}

// The sub-step loop as it was before the fusion: one operator pass at a time.
void reference_substeps(SolidBody& body, int steps, double h, Vec2 g, const Executor& exec) {
  const std::size_t n = body.size();
  std::vector<Vec2> fext(n), vhalf(n), fs(n);
  std::vector<double> heat(n);
  std::vector<Mat2> F_old, P_old;
  for (std::size_t i = 0; i < n; ++i) fext[i] = body.f_fluid[i] + body.m[i] * g;
  auto accel = [&](std::size_t i) {
    body.a[i] = body.clamped[i] ? Vec2{} : (body.f_int[i] + fext[i]) / body.m[i];
  };
  for (std::size_t i = 0; i < n; ++i) accel(i);
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < n; ++i) {
      if (body.clamped[i]) {
        vhalf[i] = Vec2{};
        body.x[i] = body.X[i];
        continue;
      }
      vhalf[i] = body.v[i] + (0.5 * h) * body.a[i];
      body.x[i] += h * vhalf[i];
    }
    P_old = body.P;
    F_old = body.F;
    compute_deformation_gradients(body, body.topology, exec);
    update_stress(body, F_old, h, exec);
    compute_stress_forces(body, body.topology, exec, fs);
    compute_artificial_viscosity(body, body.topology, vhalf, exec, body.f_av, heat);
    compute_hourglass_forces(body, body.topology, body.material.hourglass, exec, body.f_hg);
    for (std::size_t i = 0; i < n; ++i) body.f_int[i] = fs[i] + body.f_av[i] + body.f_hg[i];
    for (std::size_t i = 0; i < n; ++i) accel(i);
    for (std::size_t i = 0; i < n; ++i) {
      body.v[i] = body.clamped[i] ? Vec2{} : vhalf[i] + (0.5 * h) * body.a[i];
      const Mat2 Fdot = reference_gradient(body.topology, vhalf, i);
      const Mat2 Pm = 0.5 * (P_old[i] + body.P[i]);
      body.e[i] += h * (ddot(Pm, Fdot) / body.rho0[i] + heat[i] / body.m[i]);
    }
    double diss = 0.0, hg = 0.0, ext = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      diss -= dot(body.f_av[i], body.v[i]);
      hg -= dot(body.f_hg[i], body.v[i]);
      ext += dot(fext[i], vhalf[i]);
    }
    body.dissipated += h * diss;
    body.hourglass_work += h * hg;
    body.external_work += h * ext;
  }
}

// A perturbed, clamped, spinning and loaded block: every term of the sub-step is active
// (viscosity on approaching pairs, hourglass control, clamps, fluid force, gravity).
SolidBody loaded_block(int nx, int ny, const ElasticMaterialInput& mat) {
  BodySetup cfg;
  cfg.angular_velocity = 3.0;
  cfg.velocity = {0.5, -1.0};
  cfg.clamp_boxes.push_back({{-1.0, -1.0}, {1.2 * kDx, 1.0}});
  SolidBody b = make_body(perturbed_lattice(nx, ny, kDx, 0.1, 7), kDx, "tl_sfpm", mat, cfg);
  for (std::size_t i = 0; i < b.size(); ++i)
    b.f_fluid[i] = Vec2{std::sin(37.0 * b.X[i].x), std::cos(53.0 * b.X[i].y)} * 40.0;
  return b;
}

void fused_matches_reference(const ElasticMaterialInput& mat) {
  SolidBody fused = loaded_block(12, 6, mat);
  SolidBody ref = fused;
  const Executor exec(1);
  const double h = 0.5 * stable_time_step(fused);
  for (int call = 0; call < 3; ++call) {
    run_elastic_substeps(fused, 7, h, {0.0, -9.81}, exec);
    reference_substeps(ref, 7, h, {0.0, -9.81}, exec);
  }
  expect_round_off(fused, ref, 1e-12);
  // Not a trivial match: the body moved, deformed and heated.
  EXPECT_GT(norm(fused.x.back() - fused.X.back()), 1e-4);
  EXPECT_GT(fused.dissipated, 0.0);
  EXPECT_NE(fused.hourglass_work, 0.0);
  bool history_moved = fused.history.values.empty();  // SVK: nothing to check
  for (std::size_t k = 0; k < fused.history.values.size(); ++k)
    for (double v : fused.history.values[k]) history_moved |= v != fused.history.fields[k].initial;
  EXPECT_TRUE(history_moved) << "the J2 body never yielded";
}

TEST(ElasticSubstep, FusedEqualsOperatorSequenceSvk) {
  fused_matches_reference(plate_material(0.5, 1.0));
}

TEST(ElasticSubstep, FusedEqualsOperatorSequenceJ2) {
  ElasticMaterialInput mat = plate_material(0.5, 1.0);
  mat.model = J2LinearHardeningModel{2.0e4, 1.0e5};  // yields within the run
  fused_matches_reference(mat);
}

TEST(ElasticSubstep, OneRegionTwoBarriersPerSubstep) {
  // 100 x 90 = 9 000 particles: a team of two (kSubstepParticlesPerThread = 1 000).
  SolidBody b = loaded_block(100, 90, plate_material(0.5, 1.0));
  const Executor two(2);
  ASSERT_EQ(two.threads_for(b.size(), kSubstepParticlesPerThread), 2);
  const SyncCounts before = two.sync_counts();
  run_elastic_substeps(b, 5, 0.5 * stable_time_step(b), {}, two);
  const SyncCounts after = two.sync_counts();
  EXPECT_EQ(after.regions - before.regions, 1u);
  EXPECT_EQ(after.barriers - before.barriers, 2u * 5u + 1u);
  // A small body runs on the caller's thread: no region, no barrier.
  SolidBody small = loaded_block(40, 20, plate_material(0.5, 1.0));
  EXPECT_EQ(two.threads_for(small.size(), kSubstepParticlesPerThread), 1);
  run_elastic_substeps(small, 5, 0.5 * stable_time_step(small), {}, two);
  EXPECT_EQ(two.sync_counts().regions, after.regions);
  EXPECT_EQ(two.sync_counts().barriers, after.barriers);
}

TEST(ElasticSubstep, OneAndTwoThreadsBitIdentical) {
  ElasticMaterialInput mat = plate_material(0.5, 1.0);
  mat.model = J2LinearHardeningModel{2.0e4, 1.0e5};
  SolidBody one = loaded_block(100, 90, mat);
  SolidBody two = one;
  const double h = 0.5 * stable_time_step(one);
  run_elastic_substeps(one, 6, h, {0.0, -9.81}, Executor(1));
  run_elastic_substeps(two, 6, h, {0.0, -9.81}, Executor(2));
  expect_identical(one, two);
}

}  // namespace

namespace {

// A spinning ring skin (ring_lattice, 5 layers, inner radius r_in: at 0.3 m ~3 100
// particles, a team of three) with a moving clamp, gravity and a fluid force: the wavefront
// schedule's levels are its cross-sections (~10 particles, two per layer).
SolidBody loaded_ring(const ElasticMaterialInput& mat, double r_in = 0.3) {
  const double dx = 0.003;
  std::vector<double> V0;
  const std::vector<Vec2> X = ring_lattice(r_in, 5, dx, &V0);
  BodySetup cfg;
  cfg.angular_velocity = 3.0;
  cfg.velocity = {0.5, -1.0};
  cfg.clamp_boxes.push_back({{r_in - 0.01, -0.01}, {r_in + 0.03, 0.01}});
  cfg.clamp_velocities.push_back({0.0, 0.2});
  SolidBody b = make_body(X, dx, "tl_sfpm", mat, cfg, V0);
  for (std::size_t i = 0; i < b.size(); ++i)
    b.f_fluid[i] =
        Vec2{std::sin(37.0 * b.X[i].x), std::cos(53.0 * b.X[i].y)} * 40.0 * b.V0[i] / (dx * dx);
  return b;
}

// The wavefront schedule against the two-pass one on copies of `body`: calls of 25 sub-steps
// (two blocks of the wavefront, the second partial), 1 and 7, on 1, 2 and 3 threads.
// Returns the two-pass result.
SolidBody wavefront_matches_two_pass(const SolidBody& body) {
  const double h = 0.5 * stable_time_step(body);
  const int calls[] = {25, 1, 7};
  SolidBody ref = body;
  for (int steps : calls)
    run_elastic_substeps(ref, steps, h, {0.0, -9.81}, Executor(1), SubstepSchedule::TwoPass);
  for (int threads = 1; threads <= 3; ++threads) {
    SolidBody b = body;
    const Executor exec(threads);
    for (int steps : calls)
      run_elastic_substeps(b, steps, h, {0.0, -9.81}, exec, SubstepSchedule::Wavefront);
    SCOPED_TRACE(threads);
    expect_identical(b, ref);
  }
  return ref;
}

// Not a trivial match: the body moved and dissipated, the clamp worked.
void expect_moved(const SolidBody& b) {
  EXPECT_GT(norm(b.x.back() - b.X.back()), 1e-5);
  EXPECT_GT(b.dissipated, 0.0);
  EXPECT_NE(b.hourglass_work, 0.0);
}

}  // namespace

// The wavefront schedule (elastic_substep.cpp, docs/validation.md "Solid sub-step") runs each
// particle's arithmetic of the two-pass schedule in another order, and sums the powers of
// the energy bookkeeping in particle order after each block: the same bits, on a ring and
// on a block (whose levels, diagonals of the lattice, are far wider than a ring's), with
// SVK and with J2 (the law's history), clamps moving and fixed, gravity and a fluid force.
TEST(ElasticSubstep, WavefrontEqualsTwoPassRing) {
  const SolidBody b = wavefront_matches_two_pass(loaded_ring(plate_material(0.5, 1.0)));
  expect_moved(b);
  EXPECT_NE(b.clamp_work, 0.0);
}

TEST(ElasticSubstep, WavefrontEqualsTwoPassRingJ2) {
  ElasticMaterialInput mat = plate_material(0.5, 1.0);
  mat.model = J2LinearHardeningModel{2.0e4, 1.0e5};
  const SolidBody b = wavefront_matches_two_pass(loaded_ring(mat));
  expect_moved(b);
  bool yielded = false;
  for (std::size_t k = 0; k < b.history.values.size(); ++k)
    for (double v : b.history.values[k]) yielded |= v != b.history.fields[k].initial;
  EXPECT_TRUE(yielded);
}

TEST(ElasticSubstep, WavefrontEqualsTwoPassBlock) {
  expect_moved(wavefront_matches_two_pass(loaded_block(100, 30, plate_material(0.5, 1.0))));
}

TEST(ElasticSubstep, WavefrontBarriersPerBlock) {
  // A team of two: per block of up to 20 sub-steps a barrier after the chunks, one after the
  // seam, and one after the sums of the powers unless it is the last block (25 sub-steps: 5).
  SolidBody b = loaded_ring(plate_material(0.5, 1.0));
  const Executor two(2);
  ASSERT_EQ(two.threads_for(b.size(), kSubstepParticlesPerThread), 2);
  const SyncCounts before = two.sync_counts();
  run_elastic_substeps(b, 25, 0.5 * stable_time_step(b), {}, two, SubstepSchedule::Wavefront);
  const SyncCounts after = two.sync_counts();
  EXPECT_EQ(after.regions - before.regions, 1u);
  EXPECT_EQ(after.barriers - before.barriers, 5u);
}

// The two-pass schedule's powers go to one row per thread of the team, and each thread adds
// its share to the particle-order chain of sub-step s − rank inside pass 2, the rest after
// the region (elastic_substep.cpp): calls whose sub-step counts are and are not multiples of
// the team's size (7, 1, 6, 5, 2) on 2 and 3 threads give the bits of 1 thread, energy
// accumulators included (the clamp's work too).
TEST(ElasticSubstep, TwoPassPowerRowsPerThreadBitIdentical) {
  const SolidBody body = loaded_ring(plate_material(0.5, 1.0));
  const double h = 0.5 * stable_time_step(body);
  const int calls[] = {7, 1, 6, 5, 2};
  SolidBody ref = body;
  for (int steps : calls)
    run_elastic_substeps(ref, steps, h, {0.0, -9.81}, Executor(1), SubstepSchedule::TwoPass);
  expect_moved(ref);
  EXPECT_NE(ref.clamp_work, 0.0);
  for (int threads = 2; threads <= 3; ++threads) {
    const Executor exec(threads);
    ASSERT_EQ(exec.threads_for(body.size(), kSubstepParticlesPerThread), threads);
    SolidBody b = body;
    for (int steps : calls)
      run_elastic_substeps(b, steps, h, {0.0, -9.81}, exec, SubstepSchedule::TwoPass);
    SCOPED_TRACE(threads);
    expect_identical(b, ref);
  }
}

// Both passes' pair loops in eight lanes (solid/substep_pair_lanes.h; SubstepPairLoop::Lanes,
// the two-pass schedule's default for calls of kMinLaneSubsteps or more where the CPU has
// AVX-512F) against the scalar loops: the same bits,
// energy accumulators included, on the loaded, clamped ring (3 220 particles, 3–5 pairs
// each: masked slots in 26 of its 403 blocks of eight, the last block half empty) and on a
// block, with every on/off state of hourglass control and viscosity (four instances of the
// lanes), SVK and J2, 1, 2 and 3 threads (team shares that split the blocks of eight),
// calls of 7, 1 and 6 sub-steps. On a CPU without AVX-512F both runs take the scalar loops
// (the test then passes trivially; it says so).
namespace {
void expect_lanes_match_scalar(const SolidBody& body,
                               SubstepSchedule schedule = SubstepSchedule::TwoPass) {
  const double h = 0.5 * stable_time_step(body);
  const int calls[] = {7, 1, 6};
  SolidBody ref = body;
  for (int steps : calls)
    run_elastic_substeps(ref, steps, h, {0.0, -9.81}, Executor(1), SubstepSchedule::TwoPass,
                         SubstepPairLoop::Scalar);
  expect_moved(ref);
  for (int threads = 1; threads <= 3; ++threads) {
    SolidBody b = body;
    const Executor exec(threads);
    for (int steps : calls)
      run_elastic_substeps(b, steps, h, {0.0, -9.81}, exec, schedule, SubstepPairLoop::Lanes);
    SCOPED_TRACE(threads);
    expect_identical(b, ref);
  }
}
}  // namespace

TEST(ElasticSubstep, PairLanesBitIdenticalToScalarRing) {
  if (!substep_lanes_avx512_available()) std::printf("no AVX-512F: both runs scalar\n");
  expect_lanes_match_scalar(loaded_ring(plate_material(0.5, 1.0)));
  ElasticMaterialInput j2 = plate_material(0.5, 1.0);
  j2.model = J2LinearHardeningModel{2.0e4, 1.0e5};
  expect_lanes_match_scalar(loaded_ring(j2));
}

TEST(ElasticSubstep, PairLanesBitIdenticalToScalarHourglassViscousOnOff) {
  for (double hg : {0.0, 0.5})
    for (double av : {0.0, 1.0}) {
      SCOPED_TRACE(hg);
      SCOPED_TRACE(av);
      SolidBody b = loaded_block(60, 40, plate_material(hg, av));
      const double h = 0.5 * stable_time_step(b);
      SolidBody ref = b;
      run_elastic_substeps(ref, 9, h, {0.0, -9.81}, Executor(1), SubstepSchedule::TwoPass,
                           SubstepPairLoop::Scalar);
      for (int threads = 1; threads <= 2; ++threads) {
        SolidBody c = b;
        run_elastic_substeps(c, 9, h, {0.0, -9.81}, Executor(threads), SubstepSchedule::TwoPass,
                             SubstepPairLoop::Lanes);
        SCOPED_TRACE(threads);
        expect_identical(c, ref);
      }
      EXPECT_GT(norm(ref.x.back() - ref.X.back()), 0.0);
    }
}

// The lanes' lagged sweep (SubstepSchedule::Lagged, elastic_substep.cpp; the default for
// bodies of kSubstepLaggedParticles or more, session 20): pass 2 of a block of eight runs in
// the sweep once pass 1 has done every particle it pairs with, else after the barrier. On the
// loaded, clamped ring (layer by layer: a particle's partners in the next layer ~640
// particles on, beyond the lag of 512, so both kinds of block occur) and a block, SVK and J2,
// 1, 2 and 3 threads (shares of ~1 070 particles: blocks pairing across them), calls of 7, 1
// and 6 sub-steps (the chains of the powers finished after the region): the bits of the
// scalar two-pass loops, energy accumulators included.
TEST(ElasticSubstep, LaggedSweepBitIdenticalToScalar) {
  if (!substep_lanes_avx512_available()) std::printf("no AVX-512F: both runs scalar\n");
  ElasticMaterialInput j2 = plate_material(0.5, 1.0);
  j2.model = J2LinearHardeningModel{2.0e4, 1.0e5};
  for (const SolidBody& body : {loaded_ring(plate_material(0.5, 1.0)), loaded_ring(j2),
                                loaded_block(100, 30, plate_material(0.5, 1.0))})
    expect_lanes_match_scalar(body, SubstepSchedule::Lagged);
}

// The schedule rule (elastic_substep.h, session 19): a body of kSubstepWavefrontParticles or
// more takes the two-pass schedule with the pair loops in lanes where they apply (AVX-512F,
// calls of kMinLaneSubsteps sub-steps or more), else the wavefront. A ring of ~20 900
// particles: calls of 9 and 8 sub-steps under Auto on 1 and 2 threads give the bits of the
// forced (scalar) wavefront, and on 2 threads take 2 barriers per sub-step + 1 (the two-pass
// schedule) with the lanes, fewer (the wavefront: 2 per block + 1 between blocks) without; a
// call of 4 sub-steps takes the wavefront either way.
TEST(ElasticSubstep, AutoTakesLanesBeforeWavefrontOnLargeBody) {
  const SolidBody body = loaded_ring(plate_material(0.5, 1.0), 2.0);
  ASSERT_GE(body.size(), kSubstepWavefrontParticles);
  const double h = 0.5 * stable_time_step(body);
  const int calls[] = {9, 8, 4};
  SolidBody ref = body;
  for (int steps : calls)
    run_elastic_substeps(ref, steps, h, {0.0, -9.81}, Executor(1), SubstepSchedule::Wavefront);
  expect_moved(ref);
  const bool lanes = substep_lanes_avx512_available();
  if (!lanes) std::printf("no AVX-512F: Auto takes the wavefront\n");
  for (int threads = 1; threads <= 2; ++threads) {
    SolidBody b = body;
    const Executor exec(threads);
    for (int steps : calls) {
      const SyncCounts before = exec.sync_counts();
      run_elastic_substeps(b, steps, h, {0.0, -9.81}, exec);
      if (threads == 2) {
        const std::uint64_t barriers = exec.sync_counts().barriers - before.barriers;
        const std::uint64_t two_pass = 2u * static_cast<std::uint64_t>(steps) + 1u;
        SCOPED_TRACE(steps);
        if (lanes && steps >= kMinLaneSubsteps)
          EXPECT_EQ(barriers, two_pass);
        else
          EXPECT_LT(barriers, two_pass);  // one block of the wavefront: 2
      }
    }
    SCOPED_TRACE(threads);
    expect_identical(b, ref);
  }
}
