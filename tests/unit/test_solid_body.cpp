// Body setup and dynamics API (solid/body_dynamics.h): clamps and the cantilever-mode
// initial velocity, the stable step and sub-stepping, rigid kinds (fixed, prescribed table,
// free under force and torque), momentum conservation of a free spinning elastic block
// through the integrator, volume(i) and the output fields.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/parallel.h"
#include "solid/cantilever_mode.h"
#include "solid/deformation_gradient.h"
#include "solid/rigid_motion.h"
#include "solid/stress_update.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.005;
const Executor kExec(1);

SolidBody rigid_body(const std::string& kind, BodySetup cfg = {}) {
  SolidBody b;
  b.X = box_lattice(4, 2, kDx);
  b.x = b.X;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.V0.push_back(kDx * kDx);
    b.rho0.push_back(2000.0);
    b.m.push_back(2000.0 * kDx * kDx);
  }
  cfg.name = "rigid";
  cfg.kind = body_kind_from_name(kind).value();
  setup_body(b, with_spacing(cfg, kDx));
  return b;
}

}  // namespace

TEST(SolidBodySetup, ClampsAndCantileverMode) {
  const double H = 0.02, L = 0.2, clamp = 0.06;
  BodySetup cfg;
  cfg.clamp_boxes = {Box{{-1.0, -1.0}, {0.0, 1.0}}};
  cfg.cantilever_mode = CantileverModeInput{0.0, L, 0.01};
  const int nx = static_cast<int>(std::lround((L + clamp) / kDx));
  SolidBody b =
      make_body(box_lattice(nx, 4, kDx, {-clamp, -H / 2}), kDx, "tl_sfpm", plate_material(), cfg);
  const double c0 = bulk_sound_speed(2e6, 0.3975, 1000.0);
  EXPECT_NEAR(c0, 57.0, 0.05);  // validation README §5
  int n_clamped = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.X[i].x <= 0.0) {
      EXPECT_TRUE(b.clamped[i]);
      EXPECT_EQ(b.v[i].y, 0.0);
      ++n_clamped;
    } else {
      EXPECT_FALSE(b.clamped[i]);
      EXPECT_NEAR(b.v[i].y, cantilever_mode_velocity(b.X[i].x, L, 0.01, c0), 1e-14);
    }
  }
  EXPECT_EQ(n_clamped, 4 * 12);
  // Mode shape: 0 at the clamp, V_f c0 at the free end.
  EXPECT_NEAR(cantilever_mode_velocity(L, L, 0.01, c0), 0.01 * c0, 1e-12);
  EXPECT_NEAR(cantilever_mode_velocity(1e-9, L, 0.01, c0), 0.0, 1e-9);
}

TEST(SolidBodySetup, StableStepAndSubSteps) {
  SolidBody b = make_body(box_lattice(10, 4, kDx), kDx, "tl_sfpm", plate_material());
  const double nu = 0.3975;
  const double cs = std::sqrt(2e6 * (1 - nu) / (1000.0 * (1 + nu) * (1 - 2 * nu)));
  EXPECT_NEAR(b.material.sound_speed, cs, 1e-12);
  const double dts = stable_time_step(b);
  EXPECT_NEAR(dts, 0.5 * 1.3 * kDx / cs, 1e-15);
  advance_body(b, 0.0, 0.99 * dts, {}, kExec);
  EXPECT_EQ(b.last_substeps, 1);
  advance_body(b, 0.0, 3.5 * dts, {}, kExec);
  EXPECT_EQ(b.last_substeps, 4);
  EXPECT_EQ(stable_time_step(rigid_body("rigid_fixed")), std::numeric_limits<double>::infinity());
}

TEST(SolidBodySetup, ClampedParticlesStayPut) {
  BodySetup cfg;
  cfg.clamp_boxes = {Box{{-1, -1}, {2 * kDx, 1}}};
  SolidBody b = make_body(box_lattice(12, 4, kDx), kDx, "tl_sfpm", plate_material(), cfg);
  for (Vec2& f : b.f_fluid) f = {0.0, -50.0};
  advance_body(b, 0.0, 20 * stable_time_step(b), {0.0, -9.81}, kExec);
  double moved = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.clamped[i]) {
      EXPECT_EQ(b.x[i].x, b.X[i].x);
      EXPECT_EQ(b.x[i].y, b.X[i].y);
      EXPECT_EQ(norm(b.v[i]) + norm(b.a[i]), 0.0);
    } else {
      moved = std::max(moved, norm(b.x[i] - b.X[i]));
    }
  }
  EXPECT_GT(moved, 0.0);
}

TEST(SolidBodyRigid, FixedDoesNothing) {
  SolidBody b = rigid_body("rigid_fixed");
  for (Vec2& f : b.f_fluid) f = {3.0, 4.0};
  advance_body(b, 0.0, 0.1, {0.0, -9.81}, kExec);
  for (std::size_t i = 0; i < b.size(); ++i) {
    EXPECT_EQ(b.x[i].x, b.X[i].x);
    EXPECT_EQ(norm(b.v[i]) + norm(b.a[i]), 0.0);
  }
}

TEST(SolidBodyRigid, PrescribedTable) {
  const std::vector<PrescribedVelocity> tab{{0.0, {0.0, 0.0}}, {1.0, {2.0, -1.0}}};
  EXPECT_NEAR(prescribed_velocity(tab, 0.5).x, 1.0, 1e-15);
  EXPECT_NEAR(prescribed_velocity(tab, 7.0).x, 2.0, 1e-15);  // held at the end
  EXPECT_NEAR(prescribed_velocity(tab, -1.0).x, 0.0, 1e-15);
  // ∫_0.5^2 v_x = 0.75 (ramp) + 2 (held) = 2.75.
  EXPECT_NEAR(prescribed_displacement(tab, 0.5, 2.0).x, 2.75, 1e-14);
  BodySetup cfg;
  cfg.motion = {{0.0, {0.0, 0.0}}, {1.0, {2.0, -1.0}}};
  SolidBody b = rigid_body("rigid_prescribed", cfg);
  double t = 0.0;
  for (int s = 0; s < 7; ++s, t += 0.3) advance_body(b, t, 0.3, {0.0, -9.81}, kExec);
  // t = 2.1: displacement ∫_0^2.1 = 1 + 2·1.1 = 3.2 in x, −1.6 in y.
  for (std::size_t i = 0; i < b.size(); ++i) {
    EXPECT_NEAR(b.x[i].x - b.X[i].x, 3.2, 1e-12);
    EXPECT_NEAR(b.x[i].y - b.X[i].y, -1.6, 1e-12);
    EXPECT_NEAR(b.v[i].x, 2.0, 1e-14);
  }
}

TEST(SolidBodyRigid, FreeBodyUnderForceAndTorque) {
  BodySetup cfg;
  SolidBody b = rigid_body("rigid_free", cfg);
  const double M = b.rigid.mass, I = b.rigid.inertia;
  EXPECT_NEAR(M, 8 * 2000.0 * kDx * kDx, 1e-15);
  // A pure force couple ±f on two particles plus a net push.
  for (Vec2& f : b.f_fluid) f = {0.0, 0.0};
  b.f_fluid[0] = {0.0, -1.0};
  b.f_fluid[3] = {0.0, 1.0};
  const double torque =
      cross(b.X[3] - b.rigid.com, b.f_fluid[3]) + cross(b.X[0] - b.rigid.com, b.f_fluid[0]);
  const double T = 0.01;
  for (int s = 0; s < 10; ++s) advance_body(b, s * T / 10, T / 10, {0.0, -9.81}, kExec);
  EXPECT_NEAR(b.rigid.com.y - b.rigid.com0.y, -0.5 * 9.81 * T * T, 1e-14);
  EXPECT_NEAR(b.rigid.omega, torque / I * T, 1e-3 * std::abs(torque / I * T));
  // Particles move rigidly: pairwise distances kept.
  EXPECT_NEAR(norm(b.x[0] - b.x[7]), norm(b.X[0] - b.X[7]), 1e-14);
  EXPECT_NEAR(b.a[5].y,
              b.rigid.acc.y + b.rigid.alpha * (b.x[5].x - b.rigid.com.x) -
                  b.rigid.omega * b.rigid.omega * (b.x[5].y - b.rigid.com.y),
              1e-9);
}

TEST(SolidBodyDynamics, FreeSpinningBlockConservesMomentumAndEnergy) {
  for (const char* scheme : {"tl_sfpm", "tlsph"}) {
    BodySetup cfg;
    cfg.velocity = {0.3, -0.2};
    cfg.angular_velocity = 40.0;
    SolidBody b =
        make_body(perturbed_lattice(10, 6, kDx, 0.1, 9), kDx, scheme, plate_material(0.1), cfg);
    auto momenta = [&](Vec2& p, double& l) {
      p = {};
      l = 0.0;
      for (std::size_t i = 0; i < b.size(); ++i) {
        p += b.m[i] * b.v[i];
        l += b.m[i] * cross(b.x[i], b.v[i]);
      }
    };
    Vec2 p0, p1;
    double l0, l1;
    momenta(p0, l0);
    const BodyEnergies e0 = body_energies(b);
    for (int s = 0; s < 50; ++s) advance_body(b, 0.0, 1e-4, {}, kExec);
    momenta(p1, l1);
    const BodyEnergies e1 = body_energies(b);
    EXPECT_LT(norm(p1 - p0), 1e-13 * norm(p0)) << scheme;
    EXPECT_LT(std::abs(l1 - l0), 1e-12 * std::abs(l0)) << scheme;
    const double E0 = e0.kinetic + e0.strain + e0.dissipated + e0.hourglass;
    const double E1 = e1.kinetic + e1.strain + e1.dissipated + e1.hourglass;
    EXPECT_NEAR(E1, E0, 1e-3 * E0) << scheme;
    // Volume follows det F.
    EXPECT_NEAR(b.volume(5), b.V0[5] * det(b.F[5]), 1e-18);
  }
}

TEST(SolidBodyOutput, FieldsAndSizes) {
  SolidBody b = make_body(box_lattice(6, 4, kDx), kDx, "tl_sfpm", plate_material());
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i] = Mat2{1.01, 0.0, 0.0, 1.0} * b.X[i];
  compute_deformation_gradients(b, b.topology, kExec);
  update_stress(b, b.F, 0.0, kExec);
  const auto fields = solid_output_fields(b);
  ASSERT_EQ(fields.size(), 6u);
  const char* names[] = {"displacement",  "green_lagrange_strain", "equivalent_strain",
                         "cauchy_stress", "von_mises_stress",      "pressure"};
  for (std::size_t k = 0; k < fields.size(); ++k) {
    EXPECT_EQ(fields[k].name, names[k]);
    EXPECT_EQ(fields[k].values.size(), b.size() * fields[k].components);
  }
  // Uniform stretch 1 %: E_xx = 0.01005, equivalent strain 2/3 E_xx.
  EXPECT_NEAR(fields[1].values[6 * 10], 0.5 * (1.01 * 1.01 - 1.0), 1e-12);
  EXPECT_EQ(fields[1].components, 6);            // symmetric tensor, VTK order xx yy zz xy yz xz
  EXPECT_EQ(fields[1].values[6 * 10 + 2], 0.0);  // plane strain: E_zz = 0
  EXPECT_EQ(fields[3].components, 6);
  EXPECT_NE(fields[3].values[6 * 10 + 2], 0.0);  // plane-strain sigma_zz of the SVK law
  EXPECT_NEAR(fields[2].values[10], 2.0 / 3.0 * 0.5 * (1.01 * 1.01 - 1.0), 1e-12);
  EXPECT_EQ(solid_output_fields(rigid_body("rigid_fixed")).size(), 1u);
  // Stored fields reach VTK through the body's field registry.
  std::vector<std::string> vtk;
  SolidBody::visit_fields(b, [&](const FieldSpec& spec, const auto&) {
    if (spec.vtk) vtk.emplace_back(spec.name);
  });
  EXPECT_EQ(vtk, (std::vector<std::string>{"velocity", "fluid_force", "deformation_gradient",
                                           "pk1_stress", "part"}));
  EXPECT_EQ(rigid_body("rigid_fixed").volume(2), kDx * kDx);
}
