// Peak equivalent strain per part (app/part_peaks.h): kept per part, with time and place,
// against hand-computed equivalent strains of uniform stretches.
#include <gtest/gtest.h>

#include <cmath>

#include "app/part_peaks.h"
#include "io/json_writer.h"

namespace slamsph {
namespace {

SolidBody two_part_body() {
  SolidBody b;
  b.name = "section";
  b.kind = BodyKind::Elastic;
  const std::size_t n = 4;
  b.X = {{0, 0}, {1, 0}, {2, 0}, {3, 0}};
  b.x = b.X;
  b.F.assign(n, Mat2::identity());
  b.part = {0, 0, 1, 1};
  b.part_names = {"skin", "floor"};
  return b;
}

// Plane-strain uniaxial stretch F = diag(l, 1): E = diag((l²−1)/2, 0), equivalent strain
// sqrt(2/3 dev(E):dev(E)) = (2/3)·|E_xx| for E_yy = E_zz = 0 (dev = E_xx·(2/3, −1/3, −1/3)).
double uniaxial_equivalent(double l) {
  return 2.0 / 3.0 * std::abs(0.5 * (l * l - 1.0));
}

}  // namespace

TEST(PartPeaks, EachPartKeepsItsOwnPeakWithTimeAndPlace) {
  std::vector<SolidBody> bodies{two_part_body()};
  PartPeaks peaks;
  peaks.reset(bodies);
  bodies[0].F[1] = Mat2{1.02, 0.0, 0.0, 1.0};  // skin particle 1 stretched 2 %
  bodies[0].F[2] = Mat2{1.01, 0.0, 0.0, 1.0};  // floor particle 2 stretched 1 %
  peaks.update(bodies, 0.1);
  bodies[0].F[1] = Mat2::identity();           // the skin relaxes: its peak stays at t = 0.1
  bodies[0].F[3] = Mat2{1.03, 0.0, 0.0, 1.0};  // the floor's peak moves to particle 3
  bodies[0].x[3] = {3.5, -0.25};
  peaks.update(bodies, 0.2);
  const std::size_t k = 5;  // fields per part: strain, time, particle, x, y
  ASSERT_EQ(peaks.state.size(), 2 * k);
  EXPECT_NEAR(peaks.state[0], uniaxial_equivalent(1.02), 1e-12);
  EXPECT_EQ(peaks.state[1], 0.1);
  EXPECT_EQ(peaks.state[2], 1.0);
  EXPECT_NEAR(peaks.state[k + 0], uniaxial_equivalent(1.03), 1e-12);
  EXPECT_EQ(peaks.state[k + 1], 0.2);
  EXPECT_EQ(peaks.state[k + 2], 3.0);
  EXPECT_EQ(peaks.state[k + 3], 3.5);
  EXPECT_EQ(peaks.state[k + 4], -0.25);
  const std::string json = peaks.summary(bodies)[0].to_string(false);
  EXPECT_NE(json.find("\"name\":\"skin\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"name\":\"floor\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"particles\":2"), std::string::npos) << json;
  EXPECT_NE(json.find("\"peak_equivalent_strain\""), std::string::npos) << json;
  // Where on the structure: the floor's peak particle 3 at its reference (3, 0), 90° from
  // the keel about the reference centre (1.5, 0) (+x side; failure.csv's convention).
  EXPECT_NE(json.find("\"peak_reference_position_m\":[3,0]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"peak_angle_deg\":90"), std::string::npos) << json;
}

TEST(PartPeaks, OnePartBodyAndRigidBody) {
  SolidBody plate = two_part_body();
  plate.part.clear();
  plate.part_names.clear();
  SolidBody rigid = two_part_body();
  rigid.kind = BodyKind::RigidFixed;
  rigid.F.clear();
  std::vector<SolidBody> bodies{plate, rigid};
  bodies[0].F[2] = Mat2{1.0, 0.0, 0.0, 0.98};
  PartPeaks peaks;
  peaks.reset(bodies);
  peaks.update(bodies, 0.5);
  EXPECT_NEAR(peaks.state[0], uniaxial_equivalent(0.98), 1e-12);  // part "body"
  const std::vector<JsonObject> s = peaks.summary(bodies);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_NE(s[0].to_string(false).find("\"name\":\"body\""), std::string::npos);
  // A rigid body lists its parts without strain peaks.
  EXPECT_EQ(s[1].to_string(false).find("peak_equivalent_strain"), std::string::npos);
}

}  // namespace slamsph
