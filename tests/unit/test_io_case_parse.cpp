// Case-file parsing: a full case parses to the values written in it, a minimal case gets
// every documented default, and resolved_case_toml round-trips to an equal config.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "io/case_file.h"

using namespace slamsph;

namespace {

const std::string kFull = R"(schema_version = 1
name = "full"

[numerics]
dx = 0.005
h_over_dx = 1.5
kernel = "cubic_spline"
cfl = 0.2
solid_cfl = 0.4
end_time = 0.5
gravity = [0, -9.8]
neighbour_skin = 0.2
dual_time_stepping = false
dt_floor = 1e-10

[numerics.domain]
min = [-0.1, -0.1]
max = [1.1, 1.0]

[fluid]
density = 998.0
sound_speed = 40
gamma = 7
limiter_omega = 2.5
viscosity = 1e-6

[[fluid.block]]
min = [0.0, 0.0]
max = [1.0, 0.4]

[[fluid.block]]
min = [0.0, 0.4]
max = [0.2, 0.45]
surface = 0.5

[materials.rubber]
density = 1100
youngs_modulus = 1.2e7
poisson_ratio = 0.4
av_alpha = 1.5
av_beta = 0.5
hourglass = 0.1

[materials."mild steel"]
density = 7850

[[body]]
name = "tank"
kind = "rigid_fixed"
[body.shape]
type = "tank"
min = [0, 0]
max = [1.0, 0.6]
layers = 3

[[body]]
name = "cylinder"
material = "rubber"
scheme = "tlsph"
velocity = [0, -2.33]
dx = 0.0025
h_over_dx = 1.2
[body.shape]
type = "disc"
centre = [0.5, 0.5]
radius = 0.1

[[body]]
name = "wedge"
kind = "rigid_prescribed"
material = "mild steel"
motion = [[0, 0, -1], [0.1, 0, -2.5]]
[body.shape]
type = "polygon"
vertices = [[0.2, 0.8], [0.3, 0.7], [0.4, 0.8]]

[[body]]
name = "plate"
kind = "elastic"
material = "rubber"
initial_profile = "cantilever_mode"
mode_vf = 0.05
gravity = false
[body.shape]
type = "rectangle"
min = [0.6, 0.7]
max = [0.8, 0.72]
[body.clamp]
box = { min = [0.6, 0.7], max = [0.62, 0.72] }

[[body]]
name = "skin"
material = "rubber"
angular_velocity = 0.5
[body.shape]
type = "ring"
centre = [0.5, 0.8]
inner_radius = 0.09
outer_radius = 0.1
[body.clamp]
layers = [1, 0]

[[body]]
name = "ball"
kind = "rigid_free"
density = 500
mass = 3.0
inertia = 0.002
allow_rotation = false
[body.shape]
type = "disc"
centre = [0.9, 0.5]
radius = 0.03

[output]
interval = 0.01
probe_interval = 0.001
vtk = false
plot = "cylinder_entry"

[[output.probe]]
name = "p1"
kind = "pressure"
position = [0.5, 0.1]

[[output.probe]]
kind = "surge_front"

[[output.probe]]
name = "h"
kind = "water_height"
x = 0.2

[[output.probe]]
name = "bp"
kind = "body_pressure"
body = "cylinder"
position = [0.5, 0.4]

[[output.probe]]
name = "tip"
kind = "body_displacement"
body = "plate"
position = [0.8, 0.71]
)";

const std::string kMinimal = R"(schema_version = 1
name = "minimal"
[numerics]
dx = 0.01
end_time = 2.0
[numerics.domain]
min = [-0.1, -0.1]
max = [1, 1]
[fluid]
sound_speed = 20
[[fluid.block]]
min = [0, 0]
max = [0.5, 0.3]
[[body]]
name = "walls"
kind = "rigid_fixed"
[body.shape]
type = "tank"
min = [0, 0]
max = [0.9, 0.9]
)";

void expect_vec(Vec2 a, Vec2 b) {
  EXPECT_DOUBLE_EQ(a.x, b.x);
  EXPECT_DOUBLE_EQ(a.y, b.y);
}

}  // namespace

TEST(IoCaseParse, FullCaseValues) {
  const CaseConfig c = parse_case_string(kFull, "full.toml");
  EXPECT_EQ(c.schema_version, 1);
  EXPECT_EQ(c.name, "full");
  EXPECT_EQ(c.source_path, "full.toml");
  const NumericsConfig& n = c.numerics;
  EXPECT_DOUBLE_EQ(n.dx, 0.005);
  EXPECT_DOUBLE_EQ(n.h_over_dx, 1.5);
  EXPECT_EQ(n.kernel, KernelType::CubicSpline);
  EXPECT_DOUBLE_EQ(n.cfl, 0.2);
  EXPECT_DOUBLE_EQ(n.solid_cfl, 0.4);
  EXPECT_DOUBLE_EQ(n.end_time, 0.5);
  expect_vec(n.gravity, {0.0, -9.8});
  EXPECT_DOUBLE_EQ(n.neighbour_skin, 0.2);
  EXPECT_FALSE(n.dual_time_stepping);
  EXPECT_DOUBLE_EQ(n.dt_floor, 1e-10);
  expect_vec(n.domain.min, {-0.1, -0.1});
  expect_vec(n.domain.max, {1.1, 1.0});

  EXPECT_DOUBLE_EQ(c.fluid.density, 998.0);
  EXPECT_DOUBLE_EQ(c.fluid.sound_speed, 40.0);
  EXPECT_DOUBLE_EQ(c.fluid.gamma, 7.0);
  EXPECT_DOUBLE_EQ(c.fluid.limiter_omega, 2.5);
  EXPECT_DOUBLE_EQ(c.fluid.viscosity, 1e-6);
  ASSERT_EQ(c.fluid.blocks.size(), 2u);
  expect_vec(c.fluid.blocks[0].box.max, {1.0, 0.4});
  EXPECT_DOUBLE_EQ(c.fluid.blocks[0].surface, 0.4);
  EXPECT_DOUBLE_EQ(c.fluid.blocks[1].surface, 0.5);

  ASSERT_EQ(c.materials.size(), 2u);
  const MaterialConfig* r = c.find_material("rubber");
  ASSERT_NE(r, nullptr);
  EXPECT_TRUE(std::holds_alternative<SvkModel>(r->model));
  EXPECT_DOUBLE_EQ(r->density, 1100.0);
  EXPECT_DOUBLE_EQ(r->youngs_modulus, 1.2e7);
  EXPECT_DOUBLE_EQ(r->poisson_ratio, 0.4);
  EXPECT_DOUBLE_EQ(r->av_alpha, 1.5);
  EXPECT_DOUBLE_EQ(r->av_beta, 0.5);
  EXPECT_DOUBLE_EQ(r->hourglass, 0.1);
  ASSERT_NE(c.find_material("mild steel"), nullptr);
  EXPECT_DOUBLE_EQ(c.find_material("mild steel")->youngs_modulus, 0.0);

  ASSERT_EQ(c.bodies.size(), 6u);
  const BodyConfig& tank = c.bodies[0];
  EXPECT_EQ(tank.kind, "rigid_fixed");
  EXPECT_EQ(tank.shape.type, "tank");
  EXPECT_EQ(tank.shape.layers, 3);
  EXPECT_TRUE(tank.shape.open_top);
  EXPECT_DOUBLE_EQ(tank.density, 998.0);  // rigid_fixed without material: fluid density
  EXPECT_DOUBLE_EQ(tank.dx, 0.005);

  const BodyConfig& cyl = c.bodies[1];
  EXPECT_EQ(cyl.kind, "elastic");
  EXPECT_EQ(cyl.scheme, "tlsph");
  EXPECT_EQ(cyl.material, "rubber");
  EXPECT_DOUBLE_EQ(cyl.density, 1100.0);
  EXPECT_DOUBLE_EQ(cyl.dx, 0.0025);
  EXPECT_DOUBLE_EQ(cyl.h_over_dx, 1.2);
  expect_vec(cyl.velocity, {0.0, -2.33});
  expect_vec(cyl.shape.centre, {0.5, 0.5});
  EXPECT_DOUBLE_EQ(cyl.shape.radius, 0.1);
  EXPECT_TRUE(cyl.gravity);

  const BodyConfig& wedge = c.bodies[2];
  EXPECT_EQ(wedge.kind, "rigid_prescribed");
  EXPECT_DOUBLE_EQ(wedge.density, 7850.0);
  ASSERT_EQ(wedge.motion.size(), 2u);
  EXPECT_DOUBLE_EQ(wedge.motion[1].t, 0.1);
  expect_vec(wedge.motion[1].v, {0.0, -2.5});
  ASSERT_EQ(wedge.shape.vertices.size(), 3u);
  expect_vec(wedge.shape.vertices[1], {0.3, 0.7});
  EXPECT_EQ(wedge.shape.fill, PolygonFill::Faces);  // the default for a rigid polygon

  const BodyConfig& plate = c.bodies[3];
  EXPECT_EQ(plate.initial_profile, "cantilever_mode");
  EXPECT_DOUBLE_EQ(plate.mode_vf, 0.05);
  EXPECT_FALSE(plate.gravity);
  ASSERT_EQ(plate.clamp.boxes.size(), 1u);
  expect_vec(plate.clamp.boxes[0].max, {0.62, 0.72});

  const BodyConfig& skin = c.bodies[4];
  EXPECT_EQ(skin.shape.layers, 2);  // default round(0.01 / 0.005)
  EXPECT_EQ(skin.clamp.layers, (std::vector<int>{1, 0}));
  EXPECT_DOUBLE_EQ(skin.angular_velocity, 0.5);

  const BodyConfig& ball = c.bodies[5];
  EXPECT_EQ(ball.kind, "rigid_free");
  EXPECT_DOUBLE_EQ(ball.density, 500.0);
  EXPECT_DOUBLE_EQ(ball.mass.value(), 3.0);
  EXPECT_DOUBLE_EQ(ball.inertia.value(), 0.002);
  EXPECT_FALSE(ball.allow_rotation);

  EXPECT_DOUBLE_EQ(c.output.interval, 0.01);
  EXPECT_DOUBLE_EQ(c.output.probe_interval, 0.001);
  EXPECT_FALSE(c.output.vtk);
  EXPECT_EQ(c.output.plot, "cylinder_entry");
  ASSERT_EQ(c.output.probes.size(), 5u);
  EXPECT_EQ(c.output.probes[1].name, "surge_front_1");
  EXPECT_EQ(c.output.probes[1].kind, "surge_front");
  EXPECT_DOUBLE_EQ(c.output.probes[2].x, 0.2);
  EXPECT_EQ(c.output.probes[3].body, "cylinder");
  expect_vec(c.output.probes[3].position, {0.5, 0.4});
  EXPECT_EQ(c.output.probes[4].kind, "body_displacement");
  EXPECT_EQ(c.output.probes[4].body, "plate");
}

TEST(IoCaseParse, DefaultsFilled) {
  const CaseConfig c = parse_case_string(kMinimal, "min.toml");
  const NumericsConfig& n = c.numerics;
  EXPECT_DOUBLE_EQ(n.h_over_dx, 1.3);
  EXPECT_EQ(n.kernel, KernelType::WendlandC2);
  EXPECT_DOUBLE_EQ(n.cfl, 0.25);
  EXPECT_DOUBLE_EQ(n.solid_cfl, 0.5);
  expect_vec(n.gravity, {0.0, -9.81});
  EXPECT_DOUBLE_EQ(n.neighbour_skin, 0.2);
  EXPECT_TRUE(n.dual_time_stepping);
  EXPECT_DOUBLE_EQ(n.dt_floor, 1e-9);
  EXPECT_DOUBLE_EQ(c.fluid.density, 1000.0);
  EXPECT_DOUBLE_EQ(c.fluid.gamma, 7.0);
  EXPECT_DOUBLE_EQ(c.fluid.limiter_omega, 3.0);
  EXPECT_DOUBLE_EQ(c.fluid.viscosity, 0.0);
  EXPECT_DOUBLE_EQ(c.fluid.blocks[0].surface, 0.3);  // block top
  const BodyConfig& w = c.bodies.at(0);
  EXPECT_DOUBLE_EQ(w.dx, 0.01);
  EXPECT_DOUBLE_EQ(w.h_over_dx, 1.3);
  EXPECT_EQ(w.shape.layers, 4);
  EXPECT_TRUE(w.shape.open_top);
  EXPECT_DOUBLE_EQ(w.density, 1000.0);
  EXPECT_TRUE(w.gravity);
  EXPECT_DOUBLE_EQ(c.output.interval, 2.0 / 50.0);
  EXPECT_DOUBLE_EQ(c.output.probe_interval, 0.0);
  EXPECT_TRUE(c.output.vtk);
  EXPECT_EQ(c.output.plot, "");
}

TEST(IoCaseParse, SolidOnlyCaseAndPrescribedDefaultMotion) {
  const std::string t = R"(schema_version = 1
name = "oscillating plate"
[numerics]
dx = 0.01
end_time = 1.0
gravity = [0, 0]
[numerics.domain]
min = [-1, -1]
max = [1, 1]
[materials.al]
density = 2700
youngs_modulus = 6.75e10
poisson_ratio = 0.34
[[body]]
name = "plate"
material = "al"
initial_profile = "cantilever_mode"
mode_vf = 0.01
[body.shape]
type = "rectangle"
min = [0, 0]
max = [0.2, 0.02]
[body.clamp]
box = {min = [0, 0], max = [0.06, 0.02]}
[[body]]
name = "piston"
kind = "rigid_prescribed"
velocity = [0.5, 0]
[body.shape]
type = "rectangle"
min = [-0.5, -0.5]
max = [-0.4, -0.4]
)";
  const CaseConfig c = parse_case_string(t, "plate.toml");
  EXPECT_TRUE(c.fluid.blocks.empty());
  EXPECT_DOUBLE_EQ(c.fluid.sound_speed, 0.0);
  ASSERT_EQ(c.bodies[1].motion.size(), 1u);
  EXPECT_DOUBLE_EQ(c.bodies[1].motion[0].t, 0.0);
  expect_vec(c.bodies[1].motion[0].v, {0.5, 0.0});
  EXPECT_DOUBLE_EQ(c.bodies[1].density, 1000.0);  // fluid.density default
}

TEST(IoCaseParse, LoadCaseFromFile) {
  const std::string path = ::testing::TempDir() + "slamsph_full_case.toml";
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs(kFull.c_str(), f);
  std::fclose(f);
  const CaseConfig c = load_case(path);
  EXPECT_EQ(c.source_path, path);
  EXPECT_EQ(c.bodies.size(), 6u);
}
