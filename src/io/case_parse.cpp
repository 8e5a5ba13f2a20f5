// Case-file parser (schema_version 1): TOML tables → CaseConfig, defaults filled, every
// value checked where it is read, cross-references (materials, bodies, domain, tank)
// checked once everything is read. docs/case_format.md is the user-facing description.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <tuple>

#include "core/error.h"
#include "geometry/shape_bounds.h"
#include "io/case_file.h"
#include "io/case_reader.h"
#include "solid/body_kind.h"
#include "solid/materials/material_presets.h"

namespace slamsph {

using case_detail::fail;
using case_detail::format_double;
using case_detail::Reader;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Largest supported water-to-body spacing ratio (docs/model.md §4, tested at 1, 2, 4, 8).
constexpr double kMaxSpacingRatio = 8.0;

const std::vector<std::string> kKernels{"wendland_c2", "cubic_spline"};
const std::vector<std::string> kForceCorrections{"kick", "none", "next_step"};
const std::vector<std::string> kFluidIntegrators{"kick_drift_kick", "symplectic"};
const std::vector<std::string> kWallAccelerations{"body_mean", "local", "none"};
// Body kinds and schemes: the one table of names in solid/body_kind.h.
template <class Table>
std::vector<std::string> names_of(const Table& table) {
  std::vector<std::string> out;
  for (const auto& entry : table) out.emplace_back(entry.first);
  return out;
}
const std::vector<std::string> kKinds = names_of(kBodyKindNames);
const std::vector<std::string> kSchemes = names_of(kSolidSchemeNames);
const std::vector<std::string> kPolygonFills{"faces", "cartesian"};
const std::vector<std::string> kShapes{"rectangle", "disc", "ring", "polygon", "tank", "fuselage"};
const std::vector<std::string> kSections{"I", "L"};
const std::vector<std::string> kProbeKinds{
    "pressure",          "surge_front", "water_height",       "max_speed",       "body_pressure",
    "body_displacement", "body_strain", "body_stress",        "body_max_strain", "keel_deflection",
    "ovalisation",       "shortening",  "midspan_deflection", "fluid_volume"};
const std::vector<std::string> kPlots{"",      "cylinder_entry", "dam_break",
                                      "plate", "gate",           "structure"};
const std::vector<std::string> kProfiles{"", "cantilever_mode"};
const std::vector<std::string> kFailedParticles{"lagrangian", "eulerian"};
const std::vector<std::string> kModels{"svk", "j2_linear_hardening", "johnson_cook"};
const std::vector<std::string> kFailures{"none", "johnson_cook", "critical_plastic_strain"};

// Value range of a number key. An open bound excludes the value itself.
struct Rule {
  double lo = -kInf, hi = kInf;
  bool lo_open = false, hi_open = false;
  std::string expected;
};
Rule positive(const std::string& e) {
  return {0.0, kInf, true, false, e};
}
Rule non_negative(const std::string& e) {
  return {0.0, kInf, false, false, e};
}
Rule any(const std::string& e) {
  return {-kInf, kInf, false, false, e};
}

std::string pretty(double v) {
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15)
    return std::to_string(static_cast<long long>(v));
  return format_double(v);
}

std::string rule_text(const Rule& r) {
  if (r.hi == kInf) return std::string("must be ") + (r.lo_open ? "> " : ">= ") + pretty(r.lo);
  if (r.lo == -kInf) return std::string("must be ") + (r.hi_open ? "< " : "<= ") + pretty(r.hi);
  return std::string("must be in ") + (r.lo_open ? "(" : "[") + pretty(r.lo) + ", " + pretty(r.hi) +
         (r.hi_open ? ")" : "]");
}

bool rule_ok(const Rule& r, double v) {
  const bool lo = r.lo_open ? v > r.lo : v >= r.lo;
  const bool hi = r.hi_open ? v < r.hi : v <= r.hi;
  return lo && hi;
}

// Number with a default (`def` nullopt: required).
double num(const Reader& r, std::string_view key, const Rule& rule,
           std::optional<double> def = std::nullopt) {
  std::optional<double> v = r.number(key, rule.expected);
  if (!v) {
    if (!def) r.missing(key, rule.expected);
    return *def;
  }
  r.check(rule_ok(rule, *v), key, rule_text(rule), rule.expected, *v);
  return *v;
}

// A name that becomes part of a file name (vtk/<body>_00000.vtp) and of CSV headers:
// letters, digits, '_', '-', '.'; not starting with '.'; at most 64 characters.
bool file_safe_name(const std::string& s) {
  if (s.empty() || s.size() > 64 || s[0] == '.') return false;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

// Segments p1-p2 and q1-q2 cross or touch (orientation test).
bool segments_meet(Vec2 p1, Vec2 p2, Vec2 q1, Vec2 q2) {
  auto orient = [](Vec2 a, Vec2 b, Vec2 c) {
    const double v = cross(b - a, c - a);
    return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
  };
  auto on = [](Vec2 a, Vec2 b, Vec2 c) {  // c on segment ab, given collinear
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
  };
  const int o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2), o3 = orient(q1, q2, p1),
            o4 = orient(q1, q2, p2);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on(p1, p2, q1)) || (o2 == 0 && on(p1, p2, q2)) ||
         (o3 == 0 && on(q1, q2, p1)) || (o4 == 0 && on(q1, q2, p2));
}

std::string vec_text(Vec2 v) {
  // Appended piece by piece: GCC 12 reports a false -Wrestrict for "[" + std::string here.
  std::string s = "[";
  s += pretty(v.x);
  s += ", ";
  s += pretty(v.y);
  s += "]";
  return s;
}

Vec2 vec(const Reader& r, std::string_view key, const std::string& expected,
         std::optional<Vec2> def = std::nullopt) {
  std::optional<Vec2> v = r.vec2(key, expected);
  if (!v) {
    if (!def) r.missing(key, "a 2-element array [x, y] of " + expected);
    return *def;
  }
  return *v;
}

// min/max keys of a table; max must exceed min in both directions.
Box read_box(const Reader& r) {
  const Vec2 mn = vec(r, "min", "coordinates in m");
  const Vec2 mx = vec(r, "max", "coordinates in m");
  if (!(mn.x < mx.x && mn.y < mx.y))
    r.bad("max", "must exceed min in x and y (min = " + vec_text(mn) + ")", "a box with min < max",
          vec_text(mx));
  return {mn, mx};
}

bool box_inside(const Box& in, const Box& out) {
  // Tolerance for coordinates written as multiples of dx in decimal.
  const double tol = 1e-9 * std::max({1.0, std::abs(out.min.x), std::abs(out.max.x),
                                      std::abs(out.min.y), std::abs(out.max.y)});
  return in.min.x >= out.min.x - tol && in.min.y >= out.min.y - tol &&
         in.max.x <= out.max.x + tol && in.max.y <= out.max.y + tol;
}
std::string box_text(const Box& b) {
  return "{min = " + vec_text(b.min) + ", max = " + vec_text(b.max) + "}";
}

NumericsConfig parse_numerics(const Reader& root) {
  auto r = root.table("numerics", "a [numerics] table");
  if (!r) root.missing("numerics", "a [numerics] table with dx, end_time and [numerics.domain]");
  r->allow({"dx", "h_over_dx", "kernel", "cfl", "acceleration_cfl", "solid_cfl", "end_time",
            "gravity", "neighbour_skin", "dual_time_stepping", "substep_average",
            "wall_acceleration", "fluid_force_correction", "fluid_integrator", "dt_floor",
            "domain"});
  NumericsConfig n;
  n.dx = num(*r, "dx", positive("a positive length in m"));
  n.h_over_dx = num(*r, "h_over_dx", {1.0, 3.0, false, false, "a ratio h/dx in [1, 3]"}, 1.3);
  n.kernel = kernel_type_from_name(r->choice("kernel", kKernels).value_or("wendland_c2"));
  n.cfl = num(*r, "cfl", {0.0, 1.0, true, false, "a CFL number in (0, 1]"}, 0.25);
  n.acceleration_cfl =
      num(*r, "acceleration_cfl",
          {0.0, 1.0, false, false, "a factor in [0, 1] (0: no acceleration bound)"}, 0.25);
  n.solid_cfl = num(*r, "solid_cfl", {0.0, 1.0, true, false, "a CFL number in (0, 1]"}, 0.5);
  n.end_time = num(*r, "end_time", positive("a positive time in s"));
  n.gravity = vec(*r, "gravity", "accelerations in m/s^2", Vec2{0.0, -9.81});
  n.neighbour_skin =
      num(*r, "neighbour_skin",
          {0.0, 1.0, false, false, "a fraction of the kernel support in [0, 1]"}, 0.2);
  n.dual_time_stepping = r->boolean("dual_time_stepping").value_or(true);
  n.substep_average = r->boolean("substep_average").value_or(true);
  const std::string wall = r->choice("wall_acceleration", kWallAccelerations).value_or("body_mean");
  n.wall_acceleration = wall == "local"  ? WallAcceleration::Local
                        : wall == "none" ? WallAcceleration::None
                                         : WallAcceleration::BodyMean;
  const std::string corr = r->choice("fluid_force_correction", kForceCorrections).value_or("kick");
  n.fluid_force_correction = corr == "none"        ? FluidForceCorrection::None
                             : corr == "next_step" ? FluidForceCorrection::NextStep
                                                   : FluidForceCorrection::Kick;
  n.fluid_integrator =
      r->choice("fluid_integrator", kFluidIntegrators).value_or("kick_drift_kick") == "symplectic"
          ? FluidIntegrator::Symplectic
          : FluidIntegrator::KickDriftKick;
  n.dt_floor = num(*r, "dt_floor", positive("a positive time in s"), 1e-9);
  auto d = r->table("domain", "a table [numerics.domain] with min and max");
  if (!d) r->missing("domain", "a [numerics.domain] table with min = [x, y] and max = [x, y] in m");
  d->allow({"min", "max"});
  n.domain = read_box(*d);
  return n;
}

FluidConfig parse_fluid(const Reader& root, const NumericsConfig& n, std::vector<Reader>& blocks) {
  FluidConfig f;
  auto r = root.table("fluid", "a [fluid] table");
  if (!r) return f;
  r->allow({"density", "sound_speed", "gamma", "limiter_omega", "viscosity", "cavitation_pressure",
            "hydrostatic_correction", "contact_barrier", "absorbing_zone", "block"});
  f.density = num(*r, "density", positive("a positive density in kg/m^3"), 1000.0);
  f.sound_speed = num(*r, "sound_speed", positive("a positive sound speed in m/s"));
  f.gamma = num(*r, "gamma", {1.0, kInf, false, false, "a Tait exponent >= 1"}, 7.0);
  f.limiter_omega = num(*r, "limiter_omega", non_negative("a limiter factor >= 0"), 3.0);
  f.viscosity = num(*r, "viscosity", non_negative("a kinematic viscosity >= 0 in m^2/s"), 0.0);
  f.cavitation_pressure =
      num(*r, "cavitation_pressure",
          {-kInf, 0.0, false, false, "a gauge pressure <= 0 in Pa (e.g. -101325)"}, -101325.0);
  f.hydrostatic_correction = r->boolean("hydrostatic_correction").value_or(true);
  f.contact_barrier = r->boolean("contact_barrier").value_or(true);
  if (auto z = r->table("absorbing_zone", "a table [fluid.absorbing_zone] with wall widths")) {
    z->allow({"left", "right", "bottom", "top", "strength"});
    AbsorbingZoneConfig& a = f.absorbing_zone;
    const Rule width = non_negative("a band width >= 0 in m along that tank wall (0 = none)");
    a.left = num(*z, "left", width, 0.0);
    a.right = num(*z, "right", width, 0.0);
    a.bottom = num(*z, "bottom", width, 0.0);
    a.top = num(*z, "top", width, 0.0);
    a.strength =
        num(*z, "strength", positive("a damping strength > 0 (sigma = strength c0 / width)"), 10.0);
    if (!a.active())
      z->bad("left", "no wall has a zone",
             "a width > 0 for at least one of left, right, bottom, top", "all 0");
  }
  blocks = r->table_array("block", "[[fluid.block]] tables with min and max");
  for (const Reader& b : blocks) {
    b.allow({"min", "max", "surface"});
    FluidBlockConfig fb;
    fb.box = read_box(b);
    if (!box_inside(fb.box, n.domain))
      b.bad("max", "fluid block " + box_text(fb.box) + " lies outside the domain",
            "a block inside numerics.domain " + box_text(n.domain));
    fb.surface =
        num(b, "surface",
            {fb.box.max.y, kInf, false, false,
             "a free-surface height in m at or above the block top " + pretty(fb.box.max.y)},
            fb.box.max.y);
    f.blocks.push_back(fb);
  }
  return f;
}

std::string failure_name(FailureKind k) {
  switch (k) {
    case FailureKind::JohnsonCook:
      return "johnson_cook";
    case FailureKind::CriticalPlasticStrain:
      return "critical_plastic_strain";
    case FailureKind::None:
      break;
  }
  return "none";
}

// [materials.<name>] with model = "johnson_cook" (docs/case_format.md): every key required
// unless a preset supplies it (defaults without a preset, spec §3: reference_temperature
// 293 K, initial_temperature = reference_temperature, heating_fraction 0.9,
// reference_strain_rate 1/s, failure "none").
JohnsonCookModel parse_johnson_cook(const Reader& m, const JohnsonCookPreset* preset,
                                    const std::string& failure) {
  const JohnsonCookModel* d = preset ? &preset->model : nullptr;
  using OptD = std::optional<double>;
  auto def = [&](double JohnsonCookModel::*field) { return d ? OptD(d->*field) : std::nullopt; };
  JohnsonCookModel jc;
  jc.a = num(m, "jc_a", positive("a positive initial yield stress A in Pa"),
             def(&JohnsonCookModel::a));
  jc.b = num(m, "jc_b", non_negative("a hardening coefficient B >= 0 in Pa"),
             def(&JohnsonCookModel::b));
  jc.n = num(m, "jc_n", positive("a positive hardening exponent n"), def(&JohnsonCookModel::n));
  jc.c =
      num(m, "jc_c", non_negative("a strain-rate coefficient C >= 0"), def(&JohnsonCookModel::c));
  jc.m = num(m, "jc_m", positive("a positive thermal-softening exponent m"),
             def(&JohnsonCookModel::m));
  jc.reference_strain_rate =
      num(m, "reference_strain_rate", positive("a positive reference strain rate in 1/s"),
          d ? d->reference_strain_rate : 1.0);
  jc.reference_temperature =
      num(m, "reference_temperature", positive("a positive reference temperature T_r in K"),
          d ? d->reference_temperature : 293.0);
  jc.melting_temperature = num(m, "melting_temperature",
                               {jc.reference_temperature, kInf, true, false,
                                "a melting temperature in K above reference_temperature = " +
                                    pretty(jc.reference_temperature)},
                               def(&JohnsonCookModel::melting_temperature));
  jc.initial_temperature =
      num(m, "initial_temperature", positive("a positive initial temperature in K"),
          jc.reference_temperature);
  jc.specific_heat = num(m, "specific_heat", positive("a positive specific heat in J/(kg K)"),
                         def(&JohnsonCookModel::specific_heat));
  jc.heating_fraction =
      num(m, "heating_fraction",
          {0.0, 1.0, false, false, "a fraction of the plastic work turned into heat in [0, 1]"},
          d ? d->heating_fraction : 0.9);
  jc.eos_sound_speed =
      num(m, "eos_sound_speed", positive("a positive Mie-Gruneisen bulk sound speed c in m/s"),
          def(&JohnsonCookModel::eos_sound_speed));
  jc.gruneisen_gamma = num(m, "gruneisen_gamma", non_negative("a Gruneisen coefficient >= 0"),
                           def(&JohnsonCookModel::gruneisen_gamma));
  jc.hugoniot_slope = num(m, "hugoniot_slope", non_negative("a Hugoniot slope s >= 0"),
                          def(&JohnsonCookModel::hugoniot_slope));
  if (failure == "johnson_cook") {
    const bool same = d && d->failure.kind == FailureKind::JohnsonCook;
    auto fdef = [&](double FailureModel::*field) {
      return same ? OptD(d->failure.*field) : std::nullopt;
    };
    const Rule r = any("a Johnson-Cook failure constant");
    jc.failure.kind = FailureKind::JohnsonCook;
    jc.failure.d1 = num(m, "failure_d1", r, fdef(&FailureModel::d1));
    jc.failure.d2 = num(m, "failure_d2", r, fdef(&FailureModel::d2));
    jc.failure.d3 = num(m, "failure_d3", r, fdef(&FailureModel::d3));
    jc.failure.d4 = num(m, "failure_d4", r, fdef(&FailureModel::d4));
    jc.failure.d5 = num(m, "failure_d5", r, fdef(&FailureModel::d5));
    // ε_f at zero triaxiality, reference rate and temperature must be a strain.
    m.check(jc.failure.d1 + jc.failure.d2 > 0.0, m.has("failure_d1") ? "failure_d1" : "failure_d2",
            "gives a failure strain D1 + D2 = " + pretty(jc.failure.d1 + jc.failure.d2) +
                " <= 0 at zero triaxiality",
            "D1 + D2 > 0", jc.failure.d1);
  } else if (failure == "critical_plastic_strain") {
    jc.failure.kind = FailureKind::CriticalPlasticStrain;
    jc.failure.critical_plastic_strain =
        num(m, "critical_plastic_strain", positive("a positive critical plastic strain"));
  }
  return jc;
}

std::vector<MaterialConfig> parse_materials(const Reader& root,
                                            std::vector<std::pair<std::string, int>>& lines) {
  std::vector<MaterialConfig> out;
  auto r = root.table("materials", "[materials.<name>] tables");
  if (!r) return out;
  for (auto&& [k, node] : r->raw()) {
    const std::string name(k.str());
    const toml::table* t = node.as_table();
    const int kl = static_cast<int>(k.source().begin.line);
    if (!t)
      fail(r->source(), kl, r->key_path(name), "wrong type",
           "a table [materials." + name + "] with density, youngs_modulus, poisson_ratio",
           case_detail::describe(node));
    const Reader m(r->source(), *t, r->key_path(name), kl);
    // The model decides which keys apply; its name becomes a typed value here.
    const std::string model = m.choice("model", kModels).value_or("svk");
    std::vector<std::string> keys{"model",    "density", "youngs_modulus", "poisson_ratio",
                                  "av_alpha", "av_beta", "hourglass"};
    if (model == "j2_linear_hardening")
      keys.insert(keys.end(), {"yield_stress", "hardening_modulus"});
    // Johnson–Cook: the preset (a shipped material) supplies every default; the failure
    // choice decides which failure constants apply.
    const JohnsonCookPreset* preset = nullptr;
    std::string failure = "none";
    if (model == "johnson_cook") {
      std::vector<std::string> names;
      for (const auto& pr : kJohnsonCookPresets) names.emplace_back(pr.name);
      if (const auto pn = m.choice("preset", names))
        for (const auto& pr : kJohnsonCookPresets)
          if (pr.name == *pn) preset = &pr;
      failure = m.choice("failure", kFailures)
                    .value_or(preset ? failure_name(preset->model.failure.kind) : "none");
      keys.insert(
          keys.end(),
          {"preset", "jc_a", "jc_b", "jc_n", "jc_c", "jc_m", "reference_strain_rate",
           "reference_temperature", "melting_temperature", "initial_temperature", "specific_heat",
           "heating_fraction", "eos_sound_speed", "gruneisen_gamma", "hugoniot_slope", "failure"});
      if (failure == "johnson_cook")
        keys.insert(keys.end(),
                    {"failure_d1", "failure_d2", "failure_d3", "failure_d4", "failure_d5"});
      if (failure == "critical_plastic_strain") keys.emplace_back("critical_plastic_strain");
    }
    m.allow(keys, "for material model '" + model + "'" +
                      (model == "johnson_cook" ? " with failure '" + failure + "'" : ""));
    MaterialConfig mc;
    mc.name = name;
    if (model == "johnson_cook") {
      mc.model = parse_johnson_cook(m, preset, failure);
    } else if (model == "j2_linear_hardening") {
      J2LinearHardeningModel j2;
      j2.yield_stress = num(m, "yield_stress", positive("a positive yield stress in Pa"));
      j2.hardening_modulus =
          num(m, "hardening_modulus", non_negative("a hardening modulus >= 0 in Pa"));
      mc.model = j2;
    } else {
      mc.model = SvkModel{};
    }
    using OptD = std::optional<double>;
    mc.density = num(m, "density", positive("a positive density in kg/m^3"),
                     preset ? OptD(preset->density) : std::nullopt);
    mc.youngs_modulus = num(m, "youngs_modulus", positive("a positive Young's modulus in Pa"),
                            preset ? preset->youngs_modulus : 0.0);
    mc.poisson_ratio =
        num(m, "poisson_ratio", {-1.0, 0.5, true, true, "a Poisson ratio in (-1, 0.5)"},
            preset ? preset->poisson_ratio : 0.0);
    mc.av_alpha = num(m, "av_alpha", non_negative("an artificial-viscosity alpha >= 0"), 1.0);
    mc.av_beta = num(m, "av_beta", non_negative("an artificial-viscosity beta >= 0"), 0.0);
    mc.hourglass = num(m, "hourglass", non_negative("an hourglass coefficient >= 0"), 0.1);
    out.push_back(mc);
    lines.push_back({name, m.line()});
  }
  return out;
}

// [body.shape] type = "fuselage" with [skin], [stringers], [floor], [columns] sub-tables
// (geometry/fuselage_shape.h). Values are checked here; how the parts fit together (a
// stringer crossing the floor, columns off the floor's lattice) is checked by the builder,
// whose errors name the same keys (app/case_builder.cpp).
void parse_fuselage(const Reader& r, const std::string& kind, double dx, const CaseConfig& c,
                    ShapeConfig& s) {
  r.allow({"type", "centre", "diameter", "skin", "stringers", "floor", "columns"},
          "for shape type 'fuselage'");
  if (kind != "elastic" && kind != "rigid_free" && kind != "rigid_prescribed")
    r.bad("type", "a fuselage is a moving body", "kind = 'elastic' (or a rigid moving kind)",
          "kind '" + kind + "'");
  FuselageShape& f = s.fuselage;
  s.centre = vec(r, "centre", "coordinates in m");
  f.diameter = num(r, "diameter", positive("the outer skin diameter in m"));
  s.outer_radius = 0.5 * f.diameter;
  auto sk = r.table("skin", "a [body.shape.skin] table with thickness and layers");
  if (!sk) r.missing("skin", "a [body.shape.skin] table with thickness (and layers)");
  sk->allow({"thickness", "layers"});
  f.skin_thickness = num(*sk, "thickness", positive("a positive skin thickness in m"));
  sk->check(f.skin_thickness < 0.25 * f.diameter, "thickness", "must be < diameter/4",
            "a thin skin in m", f.skin_thickness);
  const std::string le = "a whole number of layers in [2, 1000]";
  const auto l = sk->integer("layers", le);
  if (l && (*l < 2 || *l > 1000)) sk->bad("layers", "must be in [2, 1000]", le, std::to_string(*l));
  f.skin_layers =
      l ? static_cast<int>(*l) : std::max(2, static_cast<int>(std::lround(f.skin_thickness / dx)));
  s.inner_radius = s.outer_radius - f.skin_thickness;
  s.layers = f.skin_layers;
  // The body's spacing is the skin's (its finest part); it must be a supported ratio to the
  // water's like any body dx (docs/model.md §4).
  if (!c.fluid.blocks.empty()) {
    const double ratio = c.numerics.dx / f.skin_spacing();
    if (!(ratio >= 1.0 - 1e-9 && ratio <= kMaxSpacingRatio * (1.0 + 1e-9)))
      sk->bad("layers",
              "skin spacing thickness/layers = " + pretty(f.skin_spacing()) +
                  " m gives numerics.dx / spacing = " + pretty(ratio) + " outside [1, " +
                  pretty(kMaxSpacingRatio) + "]",
              "a water spacing 1-" + pretty(kMaxSpacingRatio) + "x the skin spacing",
              std::to_string(f.skin_layers));
  }
  if (auto st = r.table("stringers", "a [body.shape.stringers] table")) {
    st->allow({"count", "section", "height", "web_thickness", "flange_width", "flange_thickness",
               "offset_deg"});
    FuselageStringers& g = f.stringers;
    const std::string ce = "a whole number of stringers in [1, 1000]";
    const auto c = st->integer("count", ce);
    if (!c) st->missing("count", ce);
    if (*c < 1 || *c > 1000) st->bad("count", "must be in [1, 1000]", ce, std::to_string(*c));
    g.count = static_cast<int>(*c);
    g.section = st->choice("section", kSections).value_or("");
    if (g.section.empty()) st->missing("section", "\"I\" or \"L\"");
    g.height = num(*st, "height", positive("the height from the inner skin face in m"));
    g.web_thickness = num(*st, "web_thickness", positive("a positive web thickness in m"));
    g.flange_width = num(*st, "flange_width", positive("a positive flange width in m"));
    g.flange_thickness = num(*st, "flange_thickness", positive("a positive flange thickness in m"));
    g.offset_deg = num(*st, "offset_deg", any("an angle in degrees from +x, CCW"), 0.0);
    st->check(g.height < 0.5 * s.inner_radius, "height", "must be < inner radius / 2",
              "a stringer height in m", g.height);
  }
  if (auto fl = r.table("floor", "a [body.shape.floor] table")) {
    fl->allow({"height", "thickness", "dx"});
    FuselageFloor& g = f.floor;
    g.present = true;
    g.height = num(*fl, "height", any("the floor mid-plane's y relative to the centre in m"));
    g.thickness = num(*fl, "thickness", positive("a positive floor thickness in m"));
    g.dx = num(*fl, "dx", positive("a positive particle spacing in m"), f.skin_spacing());
    fl->check(std::abs(g.height) + 0.5 * g.thickness < s.inner_radius, "height",
              "the floor must lie inside the skin (|height| + thickness/2 < inner radius " +
                  pretty(s.inner_radius) + " m)",
              "a floor height in m inside the skin", g.height);
  }
  if (auto co = r.table("columns", "a [body.shape.columns] table")) {
    co->allow({"x", "width"});
    if (!f.floor.present)
      co->bad("x", "columns stand on the floor", "a [body.shape.floor] table as well");
    const std::string xe = "an array of column centre x positions relative to the centre in m";
    const auto xs = co->num_list("x", xe);
    if (!xs) co->missing("x", xe);
    if (xs->empty()) co->bad("x", "empty list", xe);
    f.columns.x = *xs;
    f.columns.width = num(*co, "width", positive("a positive column width in m"));
  }
}

ShapeConfig parse_shape(const Reader& body, const std::string& kind, double dx,
                        const CaseConfig& c) {
  auto r = body.table("shape", "a [body.shape] table with type and its keys");
  if (!r)
    body.missing("shape", "a [body.shape] table (type = " +
                              std::string("rectangle, disc, ring, polygon, tank or fuselage)"));
  ShapeConfig s;
  s.type = r->choice("type", kShapes).value_or("");
  if (s.type.empty())
    r->missing("type", "one of 'rectangle', 'disc', 'ring', 'polygon', 'tank', 'fuselage'");
  const std::string ctx = "for shape type '" + s.type + "'";
  if (s.type == "rectangle") {
    r->allow({"type", "min", "max"}, ctx);
    s.box = read_box(*r);
  } else if (s.type == "disc") {
    r->allow({"type", "centre", "radius"}, ctx);
    s.centre = vec(*r, "centre", "coordinates in m");
    s.radius = num(*r, "radius", positive("a positive radius in m"));
  } else if (s.type == "ring") {
    r->allow({"type", "centre", "inner_radius", "outer_radius", "layers"}, ctx);
    s.centre = vec(*r, "centre", "coordinates in m");
    s.inner_radius = num(*r, "inner_radius", non_negative("a radius >= 0 in m"));
    s.outer_radius = num(*r, "outer_radius", positive("a positive radius in m"));
    if (!(s.outer_radius > s.inner_radius))
      r->check(false, "outer_radius", "must exceed inner_radius = " + pretty(s.inner_radius),
               "an outer radius > inner radius in m", s.outer_radius);
    const auto l = r->integer("layers", "a whole number of layers in [1, 1000]");
    if (l && (*l < 1 || *l > 1000))
      r->bad("layers", "must be in [1, 1000]", "a whole number of layers in [1, 1000]",
             std::to_string(*l));
    s.layers = l ? static_cast<int>(*l) : 0;
    s.layers = ring_thickness_layers(s, dx);
  } else if (s.type == "polygon") {
    r->allow({"type", "vertices", "fill"}, ctx);
    // Particles laid along the faces by default for rigid bodies (a sloped face is a line,
    // not a staircase: the wedge's force ripple, docs/validation.md); the Cartesian lattice
    // for elastic ones, which refuse the face fill (its face/interior junction is not a
    // regular TL-SFPM neighbourhood, docs/model.md §3).
    const bool elastic = kind == "elastic";
    const std::string fill =
        r->choice("fill", kPolygonFills).value_or(elastic ? "cartesian" : "faces");
    if (elastic && fill == "faces")
      r->bad("fill",
             "an elastic (TL-SFPM) body cannot use the face fill yet: the junction between its "
             "face layers and the interior lattice is not a regular TL-SFPM neighbourhood (pairs "
             "at dx/2; docs/model.md §3, \"Polygon bodies\")",
             "fill = \"cartesian\" for an elastic body (or a rigid kind)", "\"faces\"");
    s.fill = fill == "faces" ? PolygonFill::Faces : PolygonFill::Cartesian;
    const std::string e = "an array of >= 3 vertices [[x, y], ...] in m";
    const auto v = r->rows("vertices", 2, e);
    if (!v) r->missing("vertices", e);
    if (v->size() < 3) r->bad("vertices", "too few vertices", e, std::to_string(v->size()));
    for (const auto& row : *v) s.vertices.push_back({row[0], row[1]});
    double a = 0.0;
    for (std::size_t i = 0, j = s.vertices.size() - 1; i < s.vertices.size(); j = i++)
      a += cross(s.vertices[j], s.vertices[i]);
    if (!(std::abs(a) > 0.0)) r->bad("vertices", "polygon has zero area", e);
    // Non-adjacent edges must not meet: a self-intersecting outline has no inside.
    const std::size_t nv = s.vertices.size();
    for (std::size_t i = 0; i < nv; ++i)
      for (std::size_t j = i + 1; j < nv; ++j) {
        if (j == i + 1 || (i == 0 && j == nv - 1)) continue;  // adjacent edges share a vertex
        if (segments_meet(s.vertices[i], s.vertices[(i + 1) % nv], s.vertices[j],
                          s.vertices[(j + 1) % nv]))
          r->bad("vertices",
                 "polygon edges " + std::to_string(i) + " and " + std::to_string(j) + " intersect",
                 "a simple (non-self-intersecting) polygon");
      }
  } else if (s.type == "fuselage") {
    parse_fuselage(*r, kind, dx, c, s);
  } else {  // tank
    r->allow({"type", "min", "max", "layers", "open_top"}, ctx);
    if (kind == "elastic" || kind == "rigid_free")
      r->bad("type", "a tank must be a rigid_fixed or rigid_prescribed body",
             "kind = 'rigid_fixed' on the body", "kind '" + kind + "'");
    s.box = read_box(*r);
    const auto l = r->integer("layers", "a whole number of wall layers in [1, 1000]");
    if (l && (*l < 1 || *l > 1000))
      r->bad("layers", "must be in [1, 1000]", "a whole number of wall layers in [1, 1000]",
             std::to_string(*l));
    s.layers = l ? static_cast<int>(*l) : kDefaultTankLayers;
    s.open_top = r->boolean("open_top").value_or(true);
  }
  return s;
}

BodyConfig parse_body(const Reader& r, const CaseConfig& c,
                      const std::vector<std::pair<std::string, int>>& mat_lines) {
  BodyConfig b;
  const auto name = r.string("name", "a body name");
  if (!name || name->empty()) r.missing("name", "a non-empty body name");
  b.name = *name;
  const std::string name_rule =
      "a body name of letters, digits, '_', '-', '.' (it names files and CSV columns), not "
      "starting with '.' and not 'fluid'";
  if (!file_safe_name(b.name))
    r.bad("name", "unusable as a file name", name_rule, "\"" + b.name + "\"");
  if (b.name == "fluid") r.bad("name", "'fluid' names the water's files", name_rule, "\"fluid\"");
  b.kind = r.choice("kind", kKinds).value_or("elastic");
  std::vector<std::string> keys{"name",      "kind",          "material", "dx",
                                "h_over_dx", "spacing_ratio", "velocity", "angular_velocity",
                                "gravity",   "shape"};
  if (b.kind == "elastic")
    keys.insert(keys.end(), {"scheme", "initial_profile", "mode_vf", "clamp", "failed_particles",
                             "pre_failed"});
  else
    keys.push_back("density");
  if (b.kind == "rigid_prescribed") keys.push_back("motion");
  if (b.kind == "rigid_free") keys.insert(keys.end(), {"mass", "inertia", "allow_rotation"});
  r.allow(keys, "for a body of kind '" + b.kind + "'");

  b.dx = num(r, "dx", positive("a positive particle spacing in m"), c.numerics.dx);
  // Water coarser than the structure (docs/model.md §4, "Bodies finer than the water"): the
  // body spacing as a ratio to the water's, numerics.dx / dx, in [1, kMaxSpacingRatio].
  const std::string ratio_rule = "a ratio numerics.dx / body dx in [1, " +
                                 pretty(kMaxSpacingRatio) + "] (the water at most " +
                                 pretty(kMaxSpacingRatio) + "x coarser than the body)";
  if (r.has("spacing_ratio")) {
    if (r.has("dx"))
      r.bad("spacing_ratio", "give either dx or spacing_ratio, not both",
            "spacing_ratio alone (body dx = numerics.dx / spacing_ratio)");
    const double ratio = num(r, "spacing_ratio", {1.0, kMaxSpacingRatio, false, false, ratio_rule});
    b.dx = c.numerics.dx / ratio;
  } else if (!c.fluid.blocks.empty()) {
    // An explicit dx must give a supported ratio too (1e-9: round-off of dx / ratio).
    const double ratio = c.numerics.dx / b.dx;
    r.check(ratio >= 1.0 - 1e-9 && ratio <= kMaxSpacingRatio * (1.0 + 1e-9), "dx",
            "spacing ratio numerics.dx / dx = " + pretty(ratio) + " outside [1, " +
                pretty(kMaxSpacingRatio) + "]",
            ratio_rule, b.dx);
  }
  b.h_over_dx =
      num(r, "h_over_dx", {1.0, 3.0, false, false, "a ratio h/dx in [1, 3]"}, c.numerics.h_over_dx);
  b.velocity = vec(r, "velocity", "velocities in m/s", Vec2{});
  b.angular_velocity = num(r, "angular_velocity", any("an angular velocity in rad/s"), 0.0);
  b.gravity = r.boolean("gravity").value_or(true);

  b.material = r.string("material", "the name of a [materials.<name>] table").value_or("");
  const MaterialConfig* mat = nullptr;
  if (!b.material.empty()) {
    mat = c.find_material(b.material);
    if (!mat) {
      std::vector<std::string> names;
      for (const auto& m : c.materials) names.push_back(m.name);
      const std::string near = case_detail::nearest(b.material, names);
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
      r.bad("material",
            "unknown material" + (near.empty() ? "" : " (did you mean '" + near + "'?)"),
            names.empty() ? "a [materials.<name>] table of that name (none defined)"
                          : "one of " + list,
            "\"" + b.material + "\"");
    }
  }
  if (b.kind == "elastic") {
    if (!mat)
      r.missing("material", "the name of a [materials.<name>] table (elastic bodies need one)");
    if (!(mat->youngs_modulus > 0.0)) {
      int ml = r.line("material");
      for (const auto& [n, l] : mat_lines)
        if (n == mat->name) ml = l;
      fail(r.source(), ml, "materials." + mat->name + ".youngs_modulus",
           "missing required key (material used by elastic body '" + b.name + "')",
           "a positive Young's modulus in Pa");
    }
    b.density = mat->density;
    b.scheme = r.choice("scheme", kSchemes).value_or("tl_sfpm");
    b.initial_profile = r.choice("initial_profile", kProfiles).value_or("");
    b.failed_particles = r.choice("failed_particles", kFailedParticles).value_or("lagrangian");
  } else {
    const auto d = r.number("density", "a positive density in kg/m^3");
    if (d) {
      r.check(*d > 0.0, "density", "must be > 0", "a positive density in kg/m^3", *d);
      b.density = *d;
    } else if (mat) {
      b.density = mat->density;
    } else if (b.kind == "rigid_free") {
      r.missing("density", "a density in kg/m^3 (or a material) for a rigid_free body");
    } else {
      b.density = c.fluid.density;
    }
    b.scheme = "tl_sfpm";
  }

  b.shape = parse_shape(r, b.kind, b.dx, c);
  if (b.shape.type == "fuselage") b.dx = b.shape.fuselage.skin_spacing();  // its finest part

  if (b.initial_profile == "cantilever_mode") {
    b.mode_vf = num(r, "mode_vf", any("the mode's free-end velocity amplitude in m/s"));
    if (b.shape.type != "rectangle")
      r.bad("initial_profile", "cantilever_mode needs a rectangle shape",
            "shape.type = 'rectangle'", "\"" + b.shape.type + "\"");
  } else if (r.has("mode_vf")) {
    r.bad("mode_vf", "only used with initial_profile = 'cantilever_mode'",
          "no mode_vf, or initial_profile = 'cantilever_mode'");
  }

  if (auto cl = r.table("clamp", "a [body.clamp] table with box, boxes and/or layers")) {
    cl->allow({"box", "boxes", "layers"});
    if (auto bx = cl->table("box", "an inline table {min = [x, y], max = [x, y]}")) {
      bx->allow({"min", "max", "velocity"});
      b.clamp.boxes.push_back(read_box(*bx));
      b.clamp.velocities.push_back(vec(*bx, "velocity", "the grip velocity in m/s", Vec2{}));
      if (cl->has("boxes"))
        cl->bad("boxes", "give either box (one region) or boxes (a list), not both",
                "boxes = [{min = [x, y], max = [x, y]}, ...] alone");
    }
    const std::string list = "an array of inline tables [{min = [x, y], max = [x, y]}, ...]";
    const std::vector<Reader> bxs = cl->table_array("boxes", list);
    if (cl->has("boxes") && bxs.empty()) cl->bad("boxes", "empty list", list);
    for (const Reader& bx : bxs) {
      bx.allow({"min", "max", "velocity"});
      b.clamp.boxes.push_back(read_box(bx));
      b.clamp.velocities.push_back(vec(bx, "velocity", "the grip velocity in m/s", Vec2{}));
    }
    if (auto ls = cl->int_list("layers", "an array of ring layer indices")) {
      if (b.shape.type != "ring")
        cl->bad("layers", "clamped layers need a ring shape",
                "clamp.box for shape '" + b.shape.type + "'");
      std::set<long> seen;
      for (long l : *ls) {
        if (l < 0 || l >= b.shape.layers || !seen.insert(l).second)
          cl->bad(
              "layers",
              l < 0 || l >= b.shape.layers ? "layer index out of range" : "duplicate layer index",
              "distinct indices in [0, " + std::to_string(b.shape.layers - 1) + "]",
              std::to_string(l));
        b.clamp.layers.push_back(static_cast<int>(l));
      }
    }
  }
  if (auto pf = r.table("pre_failed", "a [body.pre_failed] table with box or boxes")) {
    pf->allow({"box", "boxes"});
    if (!std::holds_alternative<JohnsonCookModel>(mat->model))
      r.bad("pre_failed", "only a material that can fail can start failed",
            "a body of a johnson_cook material", "material '" + mat->name + "'");
    const std::string list = "an array of inline tables [{min = [x, y], max = [x, y]}, ...]";
    if (auto bx = pf->table("box", "an inline table {min = [x, y], max = [x, y]}")) {
      bx->allow({"min", "max"});
      b.pre_failed.push_back(read_box(*bx));
      if (pf->has("boxes"))
        pf->bad("boxes", "give either box (one region) or boxes (a list), not both",
                "boxes = [{min = [x, y], max = [x, y]}, ...] alone");
    }
    const std::vector<Reader> bxs = pf->table_array("boxes", list);
    if (pf->has("boxes") && bxs.empty()) pf->bad("boxes", "empty list", list);
    for (const Reader& bx : bxs) {
      bx.allow({"min", "max"});
      b.pre_failed.push_back(read_box(bx));
    }
    if (b.pre_failed.empty()) pf->missing("box", "a box {min = [x, y], max = [x, y]} or boxes");
  }
  if (b.initial_profile == "cantilever_mode" && b.clamp.boxes.size() != 1)
    r.bad("initial_profile", "cantilever_mode needs exactly one clamped end",
          "a [body.clamp] table with box = {min, max}",
          std::to_string(b.clamp.boxes.size()) + " clamp boxes");

  if (b.kind == "rigid_prescribed") {
    const std::string e = "rows [t, vx, vy] (s, m/s) with increasing t >= 0";
    if (auto rows = r.rows("motion", 3, e)) {
      if (rows->empty()) r.bad("motion", "empty table", e);
      double prev = -kInf;
      for (const auto& row : *rows) {
        if (!(row[0] >= 0.0) || !(row[0] > prev))
          r.check(false, "motion", "times must be >= 0 and strictly increasing", e, row[0]);
        prev = row[0];
        b.motion.push_back({row[0], {row[1], row[2]}});
      }
    } else {
      b.motion.push_back({0.0, b.velocity});
    }
  }
  if (b.kind == "rigid_free") {
    if (auto m = r.number("mass", "a positive mass per length in kg/m")) {
      r.check(*m > 0.0, "mass", "must be > 0", "a positive mass per length in kg/m", *m);
      b.mass = *m;
    }
    if (auto i = r.number("inertia", "a positive moment of inertia in kg m^2/m")) {
      r.check(*i > 0.0, "inertia", "must be > 0", "a positive moment of inertia in kg m^2/m", *i);
      b.inertia = *i;
    }
    b.allow_rotation = r.boolean("allow_rotation").value_or(true);
  }
  return b;
}

OutputConfig parse_output(const Reader& root, const CaseConfig& c) {
  OutputConfig o;
  o.interval = c.numerics.end_time / 50.0;
  auto r = root.table("output", "an [output] table");
  if (!r) return o;
  r->allow({"interval", "probe_interval", "vtk", "vtk_precision", "vtk_compression", "plot",
            "probe", "snapshots", "snapshot_view", "skin_profile"});
  o.interval = num(*r, "interval", positive("a positive output interval in s"), o.interval);
  o.probe_interval =
      num(*r, "probe_interval", non_negative("a probe interval >= 0 in s (0 = every step)"), 0.0);
  o.vtk = r->boolean("vtk").value_or(true);
  o.vtk_precision = r->choice("vtk_precision", {"float32", "float64"}).value_or("float32");
  o.vtk_compression = r->choice("vtk_compression", {"none", "zlib"}).value_or("none");
  o.plot = r->choice("plot", kPlots).value_or("");
  if (o.plot == "dam_break" && !(c.numerics.gravity.y < 0.0))
    r->bad("plot", "the dam-break plot scales time by sqrt(g/a)",
           "gravity pointing down (numerics.gravity.y < 0), or another plot",
           "gravity " + vec_text(c.numerics.gravity));
  if (o.plot == "dam_break" && c.fluid.blocks.empty())
    r->bad("plot", "the dam-break plot needs the water column", "a [[fluid.block]]");
  const std::string snap_expect = "an increasing list of times in s in (0, numerics.end_time]";
  o.snapshots = r->num_list("snapshots", snap_expect).value_or(std::vector<double>{});
  for (std::size_t i = 0; i < o.snapshots.size(); ++i) {
    const double t = o.snapshots[i];
    const bool order_ok = i == 0 || t > o.snapshots[i - 1];
    if (!(t > 0.0 && t <= c.numerics.end_time * (1.0 + 1e-12)) || !order_ok)
      r->bad("snapshots",
             "element " + std::to_string(i) + " is " +
                 (order_ok ? "outside (0, end_time]" : "not after the one before it"),
             snap_expect + " (end_time " + pretty(c.numerics.end_time) + ")", pretty(t));
  }
  if (auto v = r->table("snapshot_view", "a table {min = [x, y], max = [x, y]} in m")) {
    v->allow({"min", "max"});
    if (o.snapshots.empty())
      r->bad("snapshot_view", "a view without snapshots", "output.snapshots = [t1, ...] as well");
    o.snapshot_view = read_box(*v);
  }
  // A body of the case (the error suggests the nearest name).
  auto known_body = [&](const Reader& rr, std::string_view key,
                        const std::string& name) -> const BodyConfig& {
    std::vector<std::string> bnames;
    for (const auto& b : c.bodies) {
      if (b.name == name) return b;
      bnames.push_back(b.name);
    }
    const std::string near = case_detail::nearest(name, bnames);
    rr.bad(key, "unknown body" + (near.empty() ? "" : " (did you mean '" + near + "'?)"),
           "the name of a [[body]]", "\"" + name + "\"");
  };
  if (auto sp = r->string("skin_profile", "the name of an elastic ring or fuselage [[body]]")) {
    const BodyConfig& b = known_body(*r, "skin_profile", *sp);
    if (b.kind != "elastic" || (b.shape.type != "ring" && b.shape.type != "fuselage"))
      r->bad("skin_profile",
             "the skin profile needs an elastic body of shape type 'ring' or 'fuselage'",
             "the name of an elastic ring or fuselage [[body]]",
             "\"" + *sp + "\" (" + b.kind + ", " + b.shape.type + ")");
    if (o.snapshots.empty())
      r->bad("skin_profile", "the skin profile is written at the snapshot times",
             "output.snapshots = [t1, t2, ...] as well");
    o.skin_profile = *sp;
  }
  const auto probes = r->table_array("probe", "[[output.probe]] tables with name and kind");
  std::set<std::string> names;
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const Reader& p = probes[i];
    ProbeConfig pc;
    pc.kind = p.choice("kind", kProbeKinds).value_or("");
    if (pc.kind.empty()) {
      std::string all;
      for (const std::string& k : kProbeKinds) all += (all.empty() ? "'" : ", '") + k + "'";
      p.missing("kind", "one of " + all);
    }
    const std::string ctx = "for probe kind '" + pc.kind + "'";
    const bool at_point = pc.kind == "body_pressure" || pc.kind == "body_displacement" ||
                          pc.kind == "body_strain" || pc.kind == "body_stress";
    const bool whole_body =
        pc.kind == "body_max_strain" || pc.kind == "keel_deflection" || pc.kind == "ovalisation";
    const bool two_points = pc.kind == "shortening" || pc.kind == "midspan_deflection";
    const bool on_body = at_point || whole_body || two_points;
    if (pc.kind == "pressure") p.allow({"name", "kind", "position"}, ctx);
    if (pc.kind == "surge_front" || pc.kind == "max_speed") p.allow({"name", "kind"}, ctx);
    if (pc.kind == "water_height") p.allow({"name", "kind", "x"}, ctx);
    if (pc.kind == "fluid_volume") p.allow({"name", "kind", "box"}, ctx);
    if (at_point) p.allow({"name", "kind", "body", "position"}, ctx);
    if (whole_body) p.allow({"name", "kind", "body"}, ctx);
    if (pc.kind == "shortening") p.allow({"name", "kind", "body", "position", "to"}, ctx);
    if (pc.kind == "midspan_deflection")
      p.allow({"name", "kind", "body", "position", "to", "at"}, ctx);
    pc.name = p.string("name", "a probe name").value_or(pc.kind + "_" + std::to_string(i));
    if (pc.name.empty()) p.bad("name", "empty name", "a non-empty probe name");
    if (!file_safe_name(pc.name))
      p.bad("name", "unusable as a CSV column name",
            "a probe name of letters, digits, '_', '-', '.'", "\"" + pc.name + "\"");
    // Column names in probes.csv (app/probes.h): some kinds write several.
    std::vector<std::string> cols{pc.name};
    if (pc.kind == "body_displacement") cols = {pc.name + "_x", pc.name + "_y"};
    if (pc.kind == "body_stress") cols = {pc.name + "_von_mises", pc.name + "_Pyy"};
    if (pc.kind == "body_max_strain") cols = {pc.name, pc.name + "_X", pc.name + "_Y"};
    if (pc.kind == "ovalisation") cols = {pc.name + "_dDv", pc.name + "_dDh"};
    for (const std::string& col : cols)
      if (col == "time" || col == "leaked_particles" || !names.insert(col).second)
        p.bad("name", "probes.csv column '" + col + "' clashes with another column",
              "a name no other probe column uses", "\"" + pc.name + "\"");
    auto point = [&](std::string_view key) {
      const Vec2 v = vec(p, key, "coordinates in m");
      if (!box_inside({v, v}, c.numerics.domain))
        p.bad(key, "outside the domain",
              "a point inside numerics.domain " + box_text(c.numerics.domain), vec_text(v));
      return v;
    };
    if (pc.kind == "pressure" || at_point || two_points) pc.position = point("position");
    if (two_points) pc.to = point("to");
    if (pc.kind == "midspan_deflection") pc.at = point("at");
    if (two_points && norm(pc.to - pc.position) <= 0.0)
      p.bad("to", "the same point as position", "a second point distinct from position",
            vec_text(pc.to));
    if (pc.kind == "water_height") {
      pc.x = num(p, "x", any("an x coordinate in m"));
      const Box& d = c.numerics.domain;
      p.check(pc.x >= d.min.x && pc.x <= d.max.x, "x", "outside the domain",
              "an x in [" + pretty(d.min.x) + ", " + pretty(d.max.x) + "]", pc.x);
    }
    if (pc.kind == "fluid_volume") {
      const auto bx = p.table("box", "an inline table {min = [x, y], max = [x, y]}");
      if (!bx) p.missing("box", "the region {min = [x, y], max = [x, y]} in m");
      bx->allow({"min", "max"});
      pc.box = read_box(*bx);
    }
    if (on_body) {
      const auto body = p.string("body", "the name of a [[body]]");
      if (!body) p.missing("body", "the name of a [[body]]");
      pc.body = *body;
      const BodyConfig& b = known_body(p, "body", pc.body);
      const bool needs_elastic =
          pc.kind == "body_strain" || pc.kind == "body_stress" || pc.kind == "body_max_strain";
      if (needs_elastic && b.kind != "elastic")
        p.bad("body", "probe kind '" + pc.kind + "' reads the strain or stress of an elastic body",
              "the name of an elastic [[body]]", "\"" + pc.body + "\" (" + b.kind + ")");
    }
    o.probes.push_back(pc);
  }
  return o;
}

CaseConfig parse_root(const toml::table& tbl, const std::string& source) {
  const Reader root(source, tbl, "", 1);
  CaseConfig c;
  c.source_path = source;
  const auto sv = root.integer("schema_version", "schema_version = 1");
  if (!sv) root.missing("schema_version", "schema_version = 1 (an integer)");
  if (*sv != kCaseSchemaVersion)
    root.bad("schema_version", "unsupported schema version", "1", std::to_string(*sv));
  c.schema_version = static_cast<int>(*sv);
  root.allow({"schema_version", "name", "numerics", "fluid", "materials", "body", "output"});
  const auto name = root.string("name", "a case name");
  if (!name || name->empty()) root.missing("name", "a non-empty case name (a string)");
  c.name = *name;
  // The default output folder is results/<name>.
  const bool folder_ok = c.name != "." && c.name != ".." && c.name.size() <= 128 &&
                         c.name.find('/') == std::string::npos &&
                         std::none_of(c.name.begin(), c.name.end(), [](char ch) {
                           return static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f;
                         });
  if (!folder_ok)
    root.bad("name", "unusable as a folder name (results/<name>)",
             "a name without '/' or control characters, not '.' or '..', at most 128 "
             "characters",
             "\"" + c.name + "\"");

  c.numerics = parse_numerics(root);
  std::vector<Reader> blocks;
  c.fluid = parse_fluid(root, c.numerics, blocks);
  std::vector<std::pair<std::string, int>> mat_lines;
  c.materials = parse_materials(root, mat_lines);

  const auto bodies = root.table_array("body", "[[body]] tables");
  std::set<std::string> body_names;
  for (const Reader& br : bodies) {
    BodyConfig b = parse_body(br, c, mat_lines);
    if (!body_names.insert(b.name).second)
      br.bad("name", "duplicate body name", "a name no other body uses", "\"" + b.name + "\"");
    const Box bb = shape_bounds(b.shape, b.dx);
    if (!box_inside(bb, c.numerics.domain)) {
      const auto sh = br.table("shape", "");
      fail(source, sh->line(), sh->path(),
           "body '" + b.name + "' (bounds " + box_text(bb) + ") lies outside the domain",
           "a shape inside numerics.domain " + box_text(c.numerics.domain));
    }
    c.bodies.push_back(std::move(b));
  }

  // Fluid blocks must lie inside a tank's inner box when the case has a tank.
  std::vector<Box> tanks;
  for (const auto& b : c.bodies)
    if (b.shape.type == "tank") tanks.push_back(b.shape.box);
  if (!tanks.empty())
    for (std::size_t i = 0; i < blocks.size(); ++i) {
      bool in = false;
      for (const Box& t : tanks) in = in || box_inside(c.fluid.blocks[i].box, t);
      if (!in)
        blocks[i].bad(
            "max",
            "fluid block " + box_text(c.fluid.blocks[i].box) + " lies outside the tank's inner box",
            "a block inside the tank's inner box " + box_text(tanks[0]));
    }

  // The absorbing zone lies along the walls of the case's tank and inside it.
  if (c.fluid.absorbing_zone.active()) {
    const auto fr = root.table("fluid", "");
    const auto zr = fr->table("absorbing_zone", "");
    if (tanks.empty())
      zr->bad("left", "the case has no tank",
              "a body with shape type = \"tank\" whose walls the zone lines", "no tank");
    if (tanks.size() > 1)
      zr->bad("left", "the case has " + std::to_string(tanks.size()) + " tanks",
              "exactly one tank body (the zone lines its walls)", "several tanks");
    const AbsorbingZoneConfig& a = c.fluid.absorbing_zone;
    const Box& t = tanks[0];
    const double wx = t.max.x - t.min.x, wy = t.max.y - t.min.y;
    for (const auto& [key, w, span] :
         {std::tuple{"left", a.left, wx}, std::tuple{"right", a.right, wx},
          std::tuple{"bottom", a.bottom, wy}, std::tuple{"top", a.top, wy}})
      zr->check(w < span, key, "wider than the tank's inner box (" + pretty(span) + " m)",
                "a width < " + pretty(span) + " m", w);
    zr->check(a.left + a.right < wx, "right", "left + right bands cover the whole tank width",
              "left + right < " + pretty(wx) + " m", a.left + a.right);
    zr->check(a.bottom + a.top < wy, "top", "bottom + top bands cover the whole tank height",
              "bottom + top < " + pretty(wy) + " m", a.bottom + a.top);
  }

  c.output = parse_output(root, c);

  if (c.fluid.blocks.empty() && c.bodies.empty())
    fail(source, 1, "case", "no particles: no [[fluid.block]] and no [[body]]",
         "at least one fluid block or body");
  return c;
}

// Every key path of the table with where it was given (CaseConfig::locations).
void record_locations(const toml::table& t, const std::string& prefix, const std::string& source,
                      std::map<std::string, std::string>& out) {
  for (auto&& [k, node] : t) {
    const std::string path =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    auto place = [&](const toml::source_region& r, const toml::source_region& fallback) {
      const toml::source_region& use = r.begin.line > 0 ? r : fallback;
      const std::string origin = case_detail::origin_of(use, source);
      return origin == source ? source + ":" + std::to_string(use.begin.line) : origin;
    };
    out[path] = place(node.source(), k.source());
    if (const toml::table* sub = node.as_table()) {
      record_locations(*sub, path, source, out);
    } else if (const toml::array* a = node.as_array()) {
      for (std::size_t i = 0; i < a->size(); ++i)
        if (const toml::table* e = a->get(i)->as_table()) {
          const std::string ep = path + "[" + std::to_string(i) + "]";
          out[ep] = place(e->source(), k.source());
          record_locations(*e, ep, source, out);
        }
    }
  }
}

}  // namespace

CaseConfig parse_case_string(const std::string& text, const std::string& source_name,
                             const std::vector<std::string>& overrides) {
  toml::table tbl;
  try {
    tbl = toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    fail(source_name, static_cast<int>(b.line), "(toml syntax)",
         std::string(e.description()) + " (column " + std::to_string(b.column) + ")", "valid TOML");
  }
  case_detail::apply_overrides(tbl, overrides);
  CaseConfig c = parse_root(tbl, source_name);
  c.overrides = overrides;
  record_locations(tbl, "", source_name, c.locations);
  return c;
}

CaseConfig load_case(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the case file; expected a readable TOML file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_case_string(ss.str(), path, overrides);
}

}  // namespace slamsph
