// resolved_case_toml: the case with every default written out (case.resolved.toml), in the
// schema of docs/case_format.md, so parse_case_string(resolved_case_toml(c)) == c.
#include <cstdio>
#include <sstream>

#include "io/case_file.h"
#include "io/case_reader.h"

namespace slamsph {

namespace {

using case_detail::format_double;

std::string q(const std::string& s) {
  std::string o = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      o += '\\';
      o += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      o += buf;
    } else {
      o += ch;
    }
  }
  return o + "\"";
}

std::string key(const std::string& k) {
  const bool bare = !k.empty() && k.find_first_not_of(
                                      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                      "0123456789_-") == std::string::npos;
  return bare ? k : q(k);
}

std::string d(double v) {
  return format_double(v);
}
std::string v2(Vec2 v) {
  // Built by append: GCC 12's -Wrestrict misfires on "literal" + std::string at -O3.
  std::string s("[");
  s.append(d(v.x)).append(", ").append(d(v.y)).append("]");
  return s;
}
std::string b(bool v) {
  return v ? "true" : "false";
}

void box(std::ostream& o, const Box& bx) {
  o << "min = " << v2(bx.min) << "  # [m]\n";
  o << "max = " << v2(bx.max) << "  # [m]\n";
}

}  // namespace

std::string resolved_case_toml(const CaseConfig& c) {
  std::ostringstream o;
  o << "# Resolved case: every default filled in (docs/case_format.md). SI units.\n";
  for (const std::string& s : c.overrides) {
    // A comment line must not be ended early by a newline inside the override.
    std::string one = s;
    for (char& ch : one)
      if (ch == '\n' || ch == '\r') ch = ' ';
    o << "# overridden on the command line: --set " << one << "\n";
  }
  o << "schema_version = " << c.schema_version << "\n";
  o << "name = " << q(c.name) << "\n\n";

  const NumericsConfig& n = c.numerics;
  o << "[numerics]\n";
  o << "dx = " << d(n.dx) << "  # [m]\n";
  o << "h_over_dx = " << d(n.h_over_dx) << "\n";
  o << "kernel = " << q(kernel_name(n.kernel)) << "\n";
  o << "cfl = " << d(n.cfl) << "\n";
  o << "acceleration_cfl = " << d(n.acceleration_cfl) << "\n";
  o << "solid_cfl = " << d(n.solid_cfl) << "\n";
  o << "end_time = " << d(n.end_time) << "  # [s]\n";
  o << "gravity = " << v2(n.gravity) << "  # [m/s^2]\n";
  o << "neighbour_skin = " << d(n.neighbour_skin) << "\n";
  o << "dual_time_stepping = " << b(n.dual_time_stepping) << "\n";
  o << "substep_average = " << b(n.substep_average) << "\n";
  o << "wall_acceleration = "
    << q(n.wall_acceleration == WallAcceleration::Local  ? "local"
         : n.wall_acceleration == WallAcceleration::None ? "none"
                                                         : "body_mean")
    << "\n";
  o << "fluid_force_correction = "
    << q(n.fluid_force_correction == FluidForceCorrection::None       ? "none"
         : n.fluid_force_correction == FluidForceCorrection::NextStep ? "next_step"
                                                                      : "kick")
    << "\n";
  o << "fluid_integrator = "
    << q(n.fluid_integrator == FluidIntegrator::Symplectic ? "symplectic" : "kick_drift_kick")
    << "\n";
  o << "dt_floor = " << d(n.dt_floor) << "  # [s]\n\n";
  o << "[numerics.domain]\n";
  box(o, n.domain);

  const FluidConfig& f = c.fluid;
  if (!f.blocks.empty() || f.sound_speed > 0.0) {
    o << "\n[fluid]\n";
    o << "density = " << d(f.density) << "  # [kg/m^3]\n";
    o << "sound_speed = " << d(f.sound_speed) << "  # [m/s]\n";
    o << "gamma = " << d(f.gamma) << "\n";
    o << "limiter_omega = " << d(f.limiter_omega) << "\n";
    o << "viscosity = " << d(f.viscosity) << "  # [m^2/s]\n";
    o << "cavitation_pressure = " << d(f.cavitation_pressure) << "  # [Pa] gauge\n";
    o << "hydrostatic_correction = " << b(f.hydrostatic_correction) << "\n";
    o << "contact_barrier = " << b(f.contact_barrier) << "\n";
    if (f.absorbing_zone.active()) {
      const AbsorbingZoneConfig& z = f.absorbing_zone;
      o << "\n[fluid.absorbing_zone]\n";
      o << "left = " << d(z.left) << "  # [m]\n";
      o << "right = " << d(z.right) << "  # [m]\n";
      o << "bottom = " << d(z.bottom) << "  # [m]\n";
      o << "top = " << d(z.top) << "  # [m]\n";
      o << "strength = " << d(z.strength) << "\n";
    }
    for (const auto& bl : f.blocks) {
      o << "\n[[fluid.block]]\n";
      box(o, bl.box);
      o << "surface = " << d(bl.surface) << "  # [m]\n";
    }
  }

  for (const auto& m : c.materials) {
    o << "\n[materials." << key(m.name) << "]\n";
    if (const auto* j2 = std::get_if<J2LinearHardeningModel>(&m.model)) {
      o << "model = \"j2_linear_hardening\"\n";
      o << "yield_stress = " << d(j2->yield_stress) << "  # [Pa]\n";
      o << "hardening_modulus = " << d(j2->hardening_modulus) << "  # [Pa]\n";
    } else if (const auto* jc = std::get_if<JohnsonCookModel>(&m.model)) {
      o << "model = \"johnson_cook\"\n";
      o << "jc_a = " << d(jc->a) << "  # [Pa]\n";
      o << "jc_b = " << d(jc->b) << "  # [Pa]\n";
      o << "jc_n = " << d(jc->n) << "\n";
      o << "jc_c = " << d(jc->c) << "\n";
      o << "jc_m = " << d(jc->m) << "\n";
      o << "reference_strain_rate = " << d(jc->reference_strain_rate) << "  # [1/s]\n";
      o << "reference_temperature = " << d(jc->reference_temperature) << "  # [K]\n";
      o << "melting_temperature = " << d(jc->melting_temperature) << "  # [K]\n";
      o << "initial_temperature = " << d(jc->initial_temperature) << "  # [K]\n";
      o << "specific_heat = " << d(jc->specific_heat) << "  # [J/(kg K)]\n";
      o << "heating_fraction = " << d(jc->heating_fraction) << "\n";
      o << "eos_sound_speed = " << d(jc->eos_sound_speed) << "  # [m/s]\n";
      o << "gruneisen_gamma = " << d(jc->gruneisen_gamma) << "\n";
      o << "hugoniot_slope = " << d(jc->hugoniot_slope) << "\n";
      const FailureModel& f = jc->failure;
      if (f.kind == FailureKind::JohnsonCook) {
        o << "failure = \"johnson_cook\"\n";
        o << "failure_d1 = " << d(f.d1) << "\nfailure_d2 = " << d(f.d2)
          << "\nfailure_d3 = " << d(f.d3) << "\nfailure_d4 = " << d(f.d4)
          << "\nfailure_d5 = " << d(f.d5) << "\n";
      } else if (f.kind == FailureKind::CriticalPlasticStrain) {
        o << "failure = \"critical_plastic_strain\"\n";
        o << "critical_plastic_strain = " << d(f.critical_plastic_strain) << "\n";
      } else {
        o << "failure = \"none\"\n";
      }
    } else {
      o << "model = \"svk\"\n";
    }
    o << "density = " << d(m.density) << "  # [kg/m^3]\n";
    if (m.youngs_modulus > 0.0) o << "youngs_modulus = " << d(m.youngs_modulus) << "  # [Pa]\n";
    o << "poisson_ratio = " << d(m.poisson_ratio) << "\n";
    o << "av_alpha = " << d(m.av_alpha) << "\n";
    o << "av_beta = " << d(m.av_beta) << "\n";
    o << "hourglass = " << d(m.hourglass) << "\n";
  }

  for (const auto& bd : c.bodies) {
    o << "\n[[body]]\n";
    o << "name = " << q(bd.name) << "\n";
    o << "kind = " << q(bd.kind) << "\n";
    if (!bd.material.empty()) o << "material = " << q(bd.material) << "\n";
    if (bd.kind == "elastic") {
      o << "scheme = " << q(bd.scheme) << "\n";
    } else {
      o << "density = " << d(bd.density) << "  # [kg/m^3]\n";
    }
    o << "dx = " << d(bd.dx) << "  # [m]\n";
    o << "h_over_dx = " << d(bd.h_over_dx) << "\n";
    o << "velocity = " << v2(bd.velocity) << "  # [m/s]\n";
    o << "angular_velocity = " << d(bd.angular_velocity) << "  # [rad/s]\n";
    o << "gravity = " << b(bd.gravity) << "\n";
    if (bd.kind == "elastic") {
      o << "initial_profile = " << q(bd.initial_profile) << "\n";
      o << "failed_particles = " << q(bd.failed_particles) << "\n";
      if (bd.initial_profile == "cantilever_mode")
        o << "mode_vf = " << d(bd.mode_vf) << "  # [m/s]\n";
    }
    if (bd.kind == "rigid_prescribed") {
      o << "motion = [  # [t (s), vx (m/s), vy (m/s)]\n";
      for (const auto& mp : bd.motion)
        o << "  [" << d(mp.t) << ", " << d(mp.v.x) << ", " << d(mp.v.y) << "],\n";
      o << "]\n";
    }
    if (bd.kind == "rigid_free") {
      if (bd.mass) o << "mass = " << d(*bd.mass) << "  # [kg/m]\n";
      if (bd.inertia) o << "inertia = " << d(*bd.inertia) << "  # [kg m^2/m]\n";
      o << "allow_rotation = " << b(bd.allow_rotation) << "\n";
    }
    const ShapeConfig& s = bd.shape;
    o << "\n[body.shape]\n";
    o << "type = " << q(s.type) << "\n";
    if (s.type == "rectangle" || s.type == "tank") box(o, s.box);
    if (s.type == "disc" || s.type == "ring") o << "centre = " << v2(s.centre) << "  # [m]\n";
    if (s.type == "disc") o << "radius = " << d(s.radius) << "  # [m]\n";
    if (s.type == "ring") {
      o << "inner_radius = " << d(s.inner_radius) << "  # [m]\n";
      o << "outer_radius = " << d(s.outer_radius) << "  # [m]\n";
    }
    if (s.type == "ring" || s.type == "tank") o << "layers = " << s.layers << "\n";
    if (s.type == "tank") o << "open_top = " << b(s.open_top) << "\n";
    if (s.type == "polygon") {
      o << "vertices = [";
      for (std::size_t i = 0; i < s.vertices.size(); ++i) o << (i ? ", " : "") << v2(s.vertices[i]);
      o << "]  # [m]\n";
      o << "fill = " << q(s.fill == PolygonFill::Faces ? "faces" : "cartesian") << "\n";
    }
    if (s.type == "fuselage") {
      const FuselageShape& f = s.fuselage;
      o << "centre = " << v2(s.centre) << "  # [m]\n";
      o << "diameter = " << d(f.diameter) << "  # [m]\n";
      o << "\n[body.shape.skin]\n";
      o << "thickness = " << d(f.skin_thickness) << "  # [m]\n";
      o << "layers = " << f.skin_layers << "\n";
      if (f.stringers.count > 0) {
        const FuselageStringers& g = f.stringers;
        o << "\n[body.shape.stringers]\n";
        o << "count = " << g.count << "\n";
        o << "section = " << q(g.section) << "\n";
        o << "height = " << d(g.height) << "  # [m]\n";
        o << "web_thickness = " << d(g.web_thickness) << "  # [m]\n";
        o << "flange_width = " << d(g.flange_width) << "  # [m]\n";
        o << "flange_thickness = " << d(g.flange_thickness) << "  # [m]\n";
        o << "offset_deg = " << d(g.offset_deg) << "  # [deg]\n";
      }
      if (f.floor.present) {
        o << "\n[body.shape.floor]\n";
        o << "height = " << d(f.floor.height) << "  # [m]\n";
        o << "thickness = " << d(f.floor.thickness) << "  # [m]\n";
        o << "dx = " << d(f.floor_spacing()) << "  # [m]\n";
      }
      if (!f.columns.x.empty()) {
        o << "\n[body.shape.columns]\n";
        o << "x = [";
        for (std::size_t i = 0; i < f.columns.x.size(); ++i)
          o << (i ? ", " : "") << d(f.columns.x[i]);
        o << "]  # [m]\n";
        o << "width = " << d(f.columns.width) << "  # [m]\n";
      }
    }
    if (bd.kind == "elastic" && (!bd.clamp.boxes.empty() || !bd.clamp.layers.empty())) {
      o << "\n[body.clamp]\n";
      const auto box_text = [&](std::size_t i) {
        const Box& bx = bd.clamp.boxes[i];
        const Vec2 v = i < bd.clamp.velocities.size() ? bd.clamp.velocities[i] : Vec2{};
        const std::string vel = v.x != 0.0 || v.y != 0.0 ? ", velocity = " + v2(v) : "";
        return "{min = " + v2(bx.min) + ", max = " + v2(bx.max) + vel + "}";
      };
      if (bd.clamp.boxes.size() == 1) o << "box = " << box_text(0) << "  # [m], [m/s]\n";
      if (bd.clamp.boxes.size() > 1) {
        o << "boxes = [";
        for (std::size_t i = 0; i < bd.clamp.boxes.size(); ++i) o << (i ? ", " : "") << box_text(i);
        o << "]  # [m], [m/s]\n";
      }
      if (!bd.clamp.layers.empty()) {
        o << "layers = [";
        for (std::size_t i = 0; i < bd.clamp.layers.size(); ++i)
          o << (i ? ", " : "") << bd.clamp.layers[i];
        o << "]\n";
      }
    }
    if (!bd.pre_failed.empty()) {
      o << "\n[body.pre_failed]\n";
      o << "boxes = [";
      for (std::size_t i = 0; i < bd.pre_failed.size(); ++i)
        o << (i ? ", " : "") << "{min = " << v2(bd.pre_failed[i].min)
          << ", max = " << v2(bd.pre_failed[i].max) << "}";
      o << "]  # [m], reference coordinates\n";
    }
  }

  const OutputConfig& out = c.output;
  o << "\n[output]\n";
  o << "interval = " << d(out.interval) << "  # [s]\n";
  o << "probe_interval = " << d(out.probe_interval) << "  # [s]\n";
  o << "vtk = " << b(out.vtk) << "\n";
  o << "vtk_precision = " << q(out.vtk_precision) << "\n";
  o << "vtk_compression = " << q(out.vtk_compression) << "\n";
  o << "plot = " << q(out.plot) << "\n";
  if (!out.snapshots.empty()) {
    o << "snapshots = [";
    for (std::size_t i = 0; i < out.snapshots.size(); ++i)
      o << (i ? ", " : "") << d(out.snapshots[i]);
    o << "]  # [s]\n";
  }
  if (!out.skin_profile.empty()) o << "skin_profile = " << q(out.skin_profile) << "\n";
  const Box& view = out.snapshot_view;
  if (out.has_snapshot_view())
    o << "snapshot_view = { min = " << v2(view.min) << ", max = " << v2(view.max) << " }  # [m]\n";
  for (const auto& p : out.probes) {
    o << "\n[[output.probe]]\n";
    o << "name = " << q(p.name) << "\n";
    o << "kind = " << q(p.kind) << "\n";
    const bool two_points = p.kind == "shortening" || p.kind == "midspan_deflection";
    const bool at_point = p.kind == "body_pressure" || p.kind == "body_displacement" ||
                          p.kind == "body_strain" || p.kind == "body_stress";
    if (p.kind == "pressure" || at_point || two_points)
      o << "position = " << v2(p.position) << "  # [m]\n";
    if (two_points) o << "to = " << v2(p.to) << "  # [m]\n";
    if (p.kind == "midspan_deflection") o << "at = " << v2(p.at) << "  # [m]\n";
    if (p.kind == "water_height") o << "x = " << d(p.x) << "  # [m]\n";
    if (p.kind == "fluid_volume")
      o << "box = {min = " << v2(p.box.min) << ", max = " << v2(p.box.max) << "}  # [m]\n";
    if (!p.body.empty()) o << "body = " << q(p.body) << "\n";
  }
  return o.str();
}

}  // namespace slamsph
