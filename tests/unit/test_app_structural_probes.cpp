// Structural probes (app/probes.h) on a ring whose particles are moved by hand: zero for a
// rigid translation, and the closed-form values of a uniform vertical stretch
// y = Yc + (1 + a)(Y - Yc) with F = diag(1, 1 + a) (Green–Lagrange E_yy = a + a²/2, von
// Mises equivalent 2/3 E_yy).
#include <gtest/gtest.h>

#include <cmath>

#include "app/run_options.h"
#include "app/simulation.h"
#include "io/case_file.h"

namespace slamsph {
namespace {

const char* kCase = R"(schema_version = 1
name = "probe_ring"
[numerics]
dx = 0.01
end_time = 0.01
gravity = [0.0, 0.0]
[numerics.domain]
min = [-0.1, -0.1]
max = [0.7, 0.7]
[fluid]
sound_speed = 30.0
[materials.rubber]
density = 1100.0
youngs_modulus = 1.2e7
poisson_ratio = 0.4
[[body]]
name = "ring"
material = "rubber"
dx = 0.005
[body.shape]
type = "ring"
centre = [0.3, 0.3]
inner_radius = 0.09
outer_radius = 0.1
layers = 2
[output]
[[output.probe]]
name = "keel"
kind = "keel_deflection"
body = "ring"
[[output.probe]]
name = "oval"
kind = "ovalisation"
body = "ring"
[[output.probe]]
name = "col"
kind = "shortening"
body = "ring"
position = [0.3, 0.2]
to = [0.3, 0.4]
[[output.probe]]
name = "floor"
kind = "midspan_deflection"
body = "ring"
position = [0.2, 0.3]
to = [0.4, 0.3]
at = [0.3, 0.2]
[[output.probe]]
name = "e"
kind = "body_strain"
body = "ring"
position = [0.3, 0.2]
[[output.probe]]
name = "emax"
kind = "body_max_strain"
body = "ring"
[[output.probe]]
name = "s"
kind = "body_stress"
body = "ring"
position = [0.3, 0.2]
)";

// The outer layer's particles sit at r = 0.0975 m; the extreme particles are within half
// an arc step (1.5°) of the axes, so their offsets from the centre are 0.0975 cos(≤1.5°).
constexpr double kR = 0.0975;

Simulation make() {
  return Simulation(parse_case_string(kCase, "probe_ring.toml"), silent_options(1));
}

TEST(AppStructuralProbes, ZeroForRigidTranslation) {
  Simulation sim = make();
  SolidBody& b = sim.bodies()[0];
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i] = b.X[i] + Vec2{0.013, -0.021};
  for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(sim.probe_value(k), 0.0, 1e-15) << k;
}

TEST(AppStructuralProbes, UniformVerticalStretch) {
  Simulation sim = make();
  SolidBody& b = sim.bodies()[0];
  const double a = 0.01, yc = 0.3;
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.x[i] = {b.X[i].x, yc + (1.0 + a) * (b.X[i].y - yc)};
    b.F[i] = Mat2{1.0, 0.0, 0.0, 1.0 + a};
  }
  const double rel = 1e-3;                                 // the extreme particles' cos(≤1.5°)
  EXPECT_NEAR(sim.probe_value(0), -a * kR, rel * a * kR);  // keel bulges out (down) by a R
  EXPECT_NEAR(sim.probe_value(1), 2 * a * kR, rel * 2 * a * kR);   // vertical diameter grows
  EXPECT_NEAR(sim.probe_value(2), -2 * a * kR, rel * 2 * a * kR);  // the "column" lengthens
  // Bottom below the chord; the chord's ends sit up to r sin(1.5°) = 2.6 % of r off the
  // horizontal axis, and their displacement enters the chord.
  EXPECT_NEAR(sim.probe_value(3), -a * kR, 0.03 * a * kR);
  const double eyy = a + 0.5 * a * a;
  EXPECT_NEAR(sim.probe_value(4), 2.0 / 3.0 * eyy, 1e-12);
  EXPECT_NEAR(sim.probe_value(5), 2.0 / 3.0 * eyy, 1e-12);
}

}  // namespace
}  // namespace slamsph
