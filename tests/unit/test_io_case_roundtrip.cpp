// resolved_case_toml writes every resolved value; parsing it back gives an equal config
// (field by field, bit-exact doubles) and the resolved text is a fixed point.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "io/case_file.h"

using namespace slamsph;

namespace {

bool same(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}
bool same(Vec2 a, Vec2 b) {
  return same(a.x, b.x) && same(a.y, b.y);
}
bool same(const Box& a, const Box& b) {
  return same(a.min, b.min) && same(a.max, b.max);
}

#define EXPECT_SAME(a, b) EXPECT_TRUE(same(a, b)) << #a

void expect_equal(const CaseConfig& a, const CaseConfig& b) {
  EXPECT_EQ(a.schema_version, b.schema_version);
  EXPECT_EQ(a.name, b.name);
  const NumericsConfig &n = a.numerics, &m = b.numerics;
  EXPECT_SAME(n.dx, m.dx);
  EXPECT_SAME(n.h_over_dx, m.h_over_dx);
  EXPECT_EQ(n.kernel, m.kernel);
  EXPECT_SAME(n.cfl, m.cfl);
  EXPECT_SAME(n.solid_cfl, m.solid_cfl);
  EXPECT_SAME(n.end_time, m.end_time);
  EXPECT_SAME(n.gravity, m.gravity);
  EXPECT_SAME(n.neighbour_skin, m.neighbour_skin);
  EXPECT_EQ(n.dual_time_stepping, m.dual_time_stepping);
  EXPECT_SAME(n.dt_floor, m.dt_floor);
  EXPECT_SAME(n.domain, m.domain);
  EXPECT_SAME(a.fluid.density, b.fluid.density);
  EXPECT_SAME(a.fluid.sound_speed, b.fluid.sound_speed);
  EXPECT_SAME(a.fluid.gamma, b.fluid.gamma);
  EXPECT_SAME(a.fluid.limiter_omega, b.fluid.limiter_omega);
  EXPECT_SAME(a.fluid.viscosity, b.fluid.viscosity);
  ASSERT_EQ(a.fluid.blocks.size(), b.fluid.blocks.size());
  for (std::size_t i = 0; i < a.fluid.blocks.size(); ++i) {
    EXPECT_SAME(a.fluid.blocks[i].box, b.fluid.blocks[i].box);
    EXPECT_SAME(a.fluid.blocks[i].surface, b.fluid.blocks[i].surface);
  }
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    const MaterialConfig &p = a.materials[i], &q = b.materials[i];
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.model, q.model);
    EXPECT_SAME(p.density, q.density);
    EXPECT_SAME(p.youngs_modulus, q.youngs_modulus);
    EXPECT_SAME(p.poisson_ratio, q.poisson_ratio);
    EXPECT_SAME(p.av_alpha, q.av_alpha);
    EXPECT_SAME(p.av_beta, q.av_beta);
    EXPECT_SAME(p.hourglass, q.hourglass);
  }
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const BodyConfig &p = a.bodies[i], &q = b.bodies[i];
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.kind, q.kind);
    EXPECT_EQ(p.scheme, q.scheme);
    EXPECT_EQ(p.material, q.material);
    EXPECT_SAME(p.density, q.density);
    EXPECT_SAME(p.dx, q.dx);
    EXPECT_SAME(p.h_over_dx, q.h_over_dx);
    EXPECT_SAME(p.velocity, q.velocity);
    EXPECT_SAME(p.angular_velocity, q.angular_velocity);
    EXPECT_EQ(p.initial_profile, q.initial_profile);
    EXPECT_SAME(p.mode_vf, q.mode_vf);
    EXPECT_EQ(p.gravity, q.gravity);
    EXPECT_EQ(p.allow_rotation, q.allow_rotation);
    EXPECT_EQ(p.mass.has_value(), q.mass.has_value());
    if (p.mass && q.mass) {
      EXPECT_SAME(*p.mass, *q.mass);
    }
    EXPECT_EQ(p.inertia.has_value(), q.inertia.has_value());
    if (p.inertia && q.inertia) {
      EXPECT_SAME(*p.inertia, *q.inertia);
    }
    ASSERT_EQ(p.motion.size(), q.motion.size());
    for (std::size_t k = 0; k < p.motion.size(); ++k) {
      EXPECT_SAME(p.motion[k].t, q.motion[k].t);
      EXPECT_SAME(p.motion[k].v, q.motion[k].v);
    }
    EXPECT_EQ(p.clamp.boxes.size(), q.clamp.boxes.size());
    for (std::size_t k = 0; k < std::min(p.clamp.boxes.size(), q.clamp.boxes.size()); ++k) {
      EXPECT_SAME(p.clamp.boxes[k], q.clamp.boxes[k]);
    }
    EXPECT_EQ(p.clamp.layers, q.clamp.layers);
    const ShapeConfig &s = p.shape, &t = q.shape;
    EXPECT_EQ(s.type, t.type);
    EXPECT_SAME(s.box, t.box);
    EXPECT_SAME(s.centre, t.centre);
    EXPECT_SAME(s.radius, t.radius);
    EXPECT_SAME(s.inner_radius, t.inner_radius);
    EXPECT_SAME(s.outer_radius, t.outer_radius);
    EXPECT_EQ(s.layers, t.layers);
    EXPECT_EQ(s.open_top, t.open_top);
    ASSERT_EQ(s.vertices.size(), t.vertices.size());
    for (std::size_t k = 0; k < s.vertices.size(); ++k) EXPECT_SAME(s.vertices[k], t.vertices[k]);
    const FuselageShape &f = s.fuselage, &g = t.fuselage;
    EXPECT_SAME(f.diameter, g.diameter);
    EXPECT_SAME(f.skin_thickness, g.skin_thickness);
    EXPECT_EQ(f.skin_layers, g.skin_layers);
    EXPECT_EQ(f.stringers.count, g.stringers.count);
    EXPECT_EQ(f.stringers.section, g.stringers.section);
    EXPECT_SAME(f.stringers.height, g.stringers.height);
    EXPECT_SAME(f.stringers.web_thickness, g.stringers.web_thickness);
    EXPECT_SAME(f.stringers.flange_width, g.stringers.flange_width);
    EXPECT_SAME(f.stringers.flange_thickness, g.stringers.flange_thickness);
    EXPECT_SAME(f.stringers.offset_deg, g.stringers.offset_deg);
    EXPECT_EQ(f.floor.present, g.floor.present);
    EXPECT_SAME(f.floor.height, g.floor.height);
    EXPECT_SAME(f.floor.thickness, g.floor.thickness);
    EXPECT_SAME(f.floor.dx, g.floor.dx);
    EXPECT_EQ(f.columns.x, g.columns.x);
    EXPECT_SAME(f.columns.width, g.columns.width);
  }
  EXPECT_SAME(a.output.interval, b.output.interval);
  EXPECT_SAME(a.output.probe_interval, b.output.probe_interval);
  EXPECT_EQ(a.output.vtk, b.output.vtk);
  EXPECT_EQ(a.output.vtk_precision, b.output.vtk_precision);
  EXPECT_EQ(a.output.vtk_compression, b.output.vtk_compression);
  EXPECT_EQ(a.output.plot, b.output.plot);
  EXPECT_EQ(a.output.snapshots, b.output.snapshots);
  EXPECT_SAME(a.output.snapshot_view.min, b.output.snapshot_view.min);
  EXPECT_SAME(a.output.snapshot_view.max, b.output.snapshot_view.max);
  EXPECT_EQ(a.output.skin_profile, b.output.skin_profile);
  ASSERT_EQ(a.output.probes.size(), b.output.probes.size());
  for (std::size_t i = 0; i < a.output.probes.size(); ++i) {
    const ProbeConfig &p = a.output.probes[i], &q = b.output.probes[i];
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.kind, q.kind);
    EXPECT_SAME(p.position, q.position);
    EXPECT_SAME(p.to, q.to);
    EXPECT_SAME(p.at, q.at);
    EXPECT_SAME(p.x, q.x);
    EXPECT_EQ(p.body, q.body);
  }
}

// Awkward doubles and names that need escaping/quoting.
const std::string kCase = R"(schema_version = 1
name = "round \"trip\" \\ case"
[numerics]
dx = 0.0015
end_time = 0.1
gravity = [1e-300, -9.80665]
[numerics.domain]
min = [-0.30000000000000004, -1]
max = [3.1, 2.2]
[fluid]
sound_speed = 55.5
[[fluid.block]]
min = [0, 0]
max = [3.0, 1.2]
[materials."al 2024"]
density = 2700
youngs_modulus = 67.5e9
poisson_ratio = 0.34
[materials.a-rigid]
density = 3000
[[body]]
name = "tank"
kind = "rigid_fixed"
[body.shape]
type = "tank"
min = [0, 0]
max = [3.0, 2.0]
open_top = false
[[body]]
name = "skin"
material = "al 2024"
velocity = [0, -5]
[body.shape]
type = "ring"
centre = [1.5, 1.6]
inner_radius = 0.297
outer_radius = 0.3
layers = 2
[body.clamp]
layers = [0]
[[body]]
name = "slider"
kind = "rigid_prescribed"
material = "a-rigid"
motion = [[0, 0.1, 0], [0.05, 0.2, 0.1]]
[body.shape]
type = "polygon"
vertices = [[0.1, 1.5], [0.2, 1.5], [0.15, 1.6]]
[[body]]
name = "bridge"
material = "al 2024"
[body.shape]
type = "rectangle"
min = [0.4, 1.7]
max = [0.7, 1.72]
[body.clamp]
boxes = [{min = [0.4, 1.7], max = [0.42, 1.72]}, {min = [0.68, 1.7], max = [0.7, 1.72]}]
[[body]]
name = "free"
kind = "rigid_free"
material = "a-rigid"
mass = 1.0
[body.shape]
type = "disc"
centre = [2.5, 1.5]
radius = 0.05
[output]
snapshots = [0.001, 0.002]
snapshot_view = {min = [1.0, 1.0], max = [2.0, 2.0]}
skin_profile = "skin"
[[output.probe]]
name = "keel"
kind = "body_pressure"
body = "skin"
position = [1.5, 1.3]
[[output.probe]]
name = "skin_disp"
kind = "body_displacement"
body = "skin"
position = [1.5, 1.3]
[[output.probe]]
kind = "water_height"
x = 0.1
[[output.probe]]
name = "strain"
kind = "body_max_strain"
body = "skin"
[[output.probe]]
name = "column"
kind = "shortening"
body = "skin"
position = [1.5, 1.3]
to = [1.5, 1.7]
[[output.probe]]
name = "floor"
kind = "midspan_deflection"
body = "skin"
position = [1.3, 1.5]
to = [1.7, 1.5]
at = [1.5, 1.5]
[[output.probe]]
name = "stress"
kind = "body_stress"
body = "skin"
position = [1.5, 1.3]
)";

}  // namespace

TEST(IoCaseRoundTrip, ResolvedParsesToEqualConfig) {
  const CaseConfig a = parse_case_string(kCase, "rt.toml");
  const std::string text = resolved_case_toml(a);
  const CaseConfig b = parse_case_string(text, "rt.resolved.toml");
  expect_equal(a, b);
  // Fixed point: resolving the resolved case changes nothing.
  EXPECT_EQ(resolved_case_toml(b), text);
  // Defaults are written out, not left implicit.
  EXPECT_NE(text.find("h_over_dx = 1.3"), std::string::npos);
  EXPECT_NE(text.find("kernel = \"wendland_c2\""), std::string::npos);
  EXPECT_NE(text.find("interval = 0.002"), std::string::npos);  // end_time / 50
  EXPECT_NE(text.find("[materials.\"al 2024\"]"), std::string::npos);
}

TEST(IoCaseRoundTrip, MinimalSolidOnlyCase) {
  const std::string t = R"(schema_version = 1
name = "solid"
[numerics]
dx = 0.01
end_time = 1
[numerics.domain]
min = [0, 0]
max = [1, 1]
[materials.m]
density = 1000
youngs_modulus = 1e6
[[body]]
name = "b"
material = "m"
[body.shape]
type = "rectangle"
min = [0.1, 0.1]
max = [0.5, 0.2]
)";
  const CaseConfig a = parse_case_string(t, "s.toml");
  const std::string text = resolved_case_toml(a);
  EXPECT_EQ(text.find("[fluid]"), std::string::npos);
  expect_equal(a, parse_case_string(text, "s.resolved.toml"));
}

TEST(IoCaseRoundTrip, FuselageShape) {
  const std::string t = R"(schema_version = 1
name = "fuselage"
[numerics]
dx = 0.006
end_time = 1
[numerics.domain]
min = [0, 0]
max = [3, 3]
[fluid]
sound_speed = 65
[[fluid.block]]
min = [0, 0]
max = [3, 2]
[materials.al]
density = 2700
youngs_modulus = 67.5e9
poisson_ratio = 0.34
[[body]]
name = "f"
material = "al"
velocity = [0, -5]
[body.shape]
type = "fuselage"
centre = [1.5, 2.3]
diameter = 0.6
[body.shape.skin]
thickness = 0.003
layers = 2
[body.shape.stringers]
count = 30
section = "L"
height = 0.024
web_thickness = 0.003
flange_width = 0.015
flange_thickness = 0.003
[body.shape.floor]
height = -0.09
thickness = 0.01
[body.shape.columns]
x = [-0.1215, 0.1215]
width = 0.009
)";
  const CaseConfig a = parse_case_string(t, "f.toml");
  EXPECT_EQ(a.bodies[0].dx, 0.0015);                       // the skin's spacing, its finest part
  EXPECT_EQ(a.bodies[0].shape.fuselage.floor.dx, 0.0015);  // default: the skin's
  const std::string text = resolved_case_toml(a);
  const CaseConfig b = parse_case_string(text, "f.resolved.toml");
  expect_equal(a, b);
  EXPECT_EQ(resolved_case_toml(b), text);
}
