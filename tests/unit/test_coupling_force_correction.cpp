// End-of-step fluid-force correction (spec §6, coupling/fluid_force_correction.h): after a
// body was advanced over dt with the old fluid force F_n, it is kicked by dt/2 (F_n+1 - F_n)
// so that it receives dt/2 (F_n + F_n+1), exactly what the kick–drift–kick fluid gives.
// Hand numbers for each body kind, and the impulse balance of a free body.
#include <gtest/gtest.h>

#include <vector>

#include "coupling/fluid_force_correction.h"

using namespace slamsph;

namespace {

SolidBody two_particles(BodyKind kind) {
  SolidBody b;
  b.kind = kind;
  b.X = {{1.0, 0.0}, {-1.0, 0.0}};
  b.x = b.X;
  b.v = {{0.2, 0.0}, {0.2, 0.0}};
  b.m = {2.0, 2.0};
  b.clamped = {0, 0};
  b.f_fluid = {{4.0, 2.0}, {0.0, -1.0}};  // the new force F_n+1
  b.rigid.mass = 4.0;
  b.rigid.inertia = 2.0;
  b.rigid.com = {0.0, 0.0};
  b.rigid.vel = {0.2, 0.0};
  return b;
}

const std::vector<Vec2> kOld{{0.0, 0.0}, {0.0, 1.0}};  // F_n
constexpr double kDt = 0.1;

}  // namespace

TEST(CouplingForceCorrection, ElasticParticlesGetHalfTheForceChange) {
  SolidBody b = two_particles(BodyKind::Elastic);
  b.clamped[1] = 1;
  correct_for_new_fluid_force(b, kOld, kDt);
  // dv = dt/2 (F_n+1 - F_n)/m = 0.05 * (4, 2) / 2 = (0.1, 0.05); the clamped one keeps v.
  EXPECT_NEAR(b.v[0].x, 0.3, 1e-15);
  EXPECT_NEAR(b.v[0].y, 0.05, 1e-15);
  EXPECT_EQ(b.v[1].x, 0.2);
  EXPECT_EQ(b.v[1].y, 0.0);
}

TEST(CouplingForceCorrection, FreeRigidBodyGetsForceAndTorqueChange) {
  SolidBody b = two_particles(BodyKind::RigidFree);
  correct_for_new_fluid_force(b, kOld, kDt);
  // sum dF = (4, 2) + (0, -2) = (4, 0): dV = 0.05 * (4, 0) / 4 = (0.05, 0);
  // torque change = (1, 0) x (4, 2) + (-1, 0) x (0, -2) = 2 + 2 = 4: dω = 0.05 * 4 / 2 = 0.1.
  EXPECT_NEAR(b.rigid.vel.x, 0.25, 1e-15);
  EXPECT_NEAR(b.rigid.vel.y, 0.0, 1e-15);
  EXPECT_NEAR(b.rigid.omega, 0.1, 1e-15);
  // Particle velocities follow the rigid motion: v = V + ω ẑ × (x - c).
  EXPECT_NEAR(b.v[0].x, 0.25, 1e-15);
  EXPECT_NEAR(b.v[0].y, 0.1, 1e-15);
  EXPECT_NEAR(b.v[1].y, -0.1, 1e-15);
  // Impulse balance: momentum change = dt/2 (F_n+1 - F_n) summed.
  EXPECT_NEAR(b.rigid.mass * (b.rigid.vel.x - 0.2), 0.5 * kDt * 4.0, 1e-15);

  SolidBody nr = two_particles(BodyKind::RigidFree);
  nr.rigid.allow_rotation = false;
  correct_for_new_fluid_force(nr, kOld, kDt);
  EXPECT_EQ(nr.rigid.omega, 0.0);
  EXPECT_NEAR(nr.v[0].y, 0.0, 1e-15);
}

TEST(CouplingForceCorrection, FixedAndPrescribedBodiesAreUntouched) {
  for (BodyKind k : {BodyKind::RigidFixed, BodyKind::RigidPrescribed}) {
    SolidBody b = two_particles(k);
    correct_for_new_fluid_force(b, kOld, kDt);
    EXPECT_EQ(b.v[0].x, 0.2);
    EXPECT_EQ(b.v[0].y, 0.0);
    EXPECT_EQ(b.rigid.vel.x, 0.2);
  }
}
