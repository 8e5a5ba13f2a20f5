// In-memory form of a case file (schema_version 1). Every field has its resolved value
// after parsing: defaults are filled in by the parser and written back out in
// case.resolved.toml. docs/case_format.md documents every key; SI units throughout.
#pragma once
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/box.h"
#include "core/kernel.h"
#include "core/vec.h"
#include "coupling/force_correction_kind.h"
#include "coupling/wall_acceleration_kind.h"
#include "fluid/fluid_integrator_kind.h"
#include "geometry/shape.h"
#include "solid/materials/material_law.h"

namespace slamsph {

struct NumericsConfig {
  double dx = 0.0;         // fluid particle spacing [m] (required)
  double h_over_dx = 1.3;  // smoothing length ratio [-]
  KernelType kernel = KernelType::WendlandC2;
  double cfl = 0.25;               // fluid acoustic CFL number [-] (spec §2)
  double acceleration_cfl = 0.25;  // fluid step bound factor · sqrt(h/max|a|); 0: off [-]
  double solid_cfl = 0.5;          // solid CFL number [-] (spec §3)
  double end_time = 0.0;           // [s] (required)
  Vec2 gravity{0.0, -9.81};        // [m/s^2]
  double neighbour_skin = 0.2;     // Verlet skin as a fraction of the kernel support [-]
  bool substep_average = true;     // fluid sees sub-step averaged body kinematics (spec §6)
  // Acceleration of a sub-cycled elastic body in the contact's static term (docs/model.md §4).
  WallAcceleration wall_acceleration = WallAcceleration::BodyMean;
  bool dual_time_stepping = true;  // sub-cycle solids inside a fluid step (spec §6)
  // How sub-cycled elastic bodies get dt/2 (F_n+1 - F_n) (coupling/fluid_force_correction.h).
  FluidForceCorrection fluid_force_correction = FluidForceCorrection::Kick;
  double dt_floor = 1e-9;  // a step below this is divergence [s]
  // Fluid time integrator (fluid/fluid_integrator_kind.h, docs/model.md §5).
  FluidIntegrator fluid_integrator = FluidIntegrator::KickDriftKick;
  Box domain;  // a particle leaving this box is divergence [m] (required)
};

struct FluidBlockConfig {
  Box box;               // filled with particles on a dx lattice, centred in cells [m]
  double surface = 0.0;  // still free-surface height for hydrostatic init [m] (default box.max.y)
};

// Absorbing (damping) zone along chosen walls of the case's tank (fluid/absorbing_zone.h,
// docs/case_format.md [fluid.absorbing_zone]).
struct AbsorbingZoneConfig {
  // Band width per wall of the tank's inner box [m]; 0 = no zone at that wall.
  double left = 0.0, right = 0.0, bottom = 0.0, top = 0.0;
  double strength = 10.0;  // σ at the wall = strength · c0 / width [-]
  bool active() const { return left > 0.0 || right > 0.0 || bottom > 0.0 || top > 0.0; }
};

struct FluidConfig {
  double density = 1000.0;     // rest density rho0 [kg/m^3]
  double sound_speed = 0.0;    // artificial sound speed c0 [m/s] (required)
  double gamma = 7.0;          // Tait exponent [-]
  double limiter_omega = 3.0;  // low-dissipation limiter ω (spec §2) [-]
  double viscosity = 0.0;      // kinematic viscosity (0 = inviscid) [m^2/s]
  // Lowest contact pressure p* (gauge) before the water separates from a solid (spec §4,
  // docs/model.md §4): one atmosphere below ambient; 0 = no suction (no adhesion) [Pa].
  double cavitation_pressure = -101325.0;
  // Static-state (hydrostatic) term in the Riemann U* of fluid pairs and of the contact
  // (docs/model.md §2): right at rest under gravity, wrong away from it (free fall).
  bool hydrostatic_correction = true;
  // Short-range fluid-solid barrier (docs/model.md §4): a repulsion inside half the rest
  // distance of a fluid and a body particle; false only to show what it prevents.
  bool contact_barrier = true;
  AbsorbingZoneConfig absorbing_zone;
  std::vector<FluidBlockConfig> blocks;
};

struct MaterialConfig {
  std::string name;
  // "svk" (St Venant–Kirchhoff), "j2_linear_hardening" (with yield_stress and
  // hardening_modulus) or "johnson_cook" (flow stress, EOS, heating, failure; optionally
  // from a preset), parsed into the typed model (solid/materials/material_law.h).
  MaterialModel model = SvkModel{};
  double density = 0.0;         // [kg/m^3]
  double youngs_modulus = 0.0;  // [Pa]
  double poisson_ratio = 0.0;   // [-]
  double av_alpha = 1.0;        // Monaghan artificial viscosity α [-] (spec §3)
  double av_beta = 0.0;         // Monaghan artificial viscosity β [-]
  double hourglass = 0.1;       // hourglass control coefficient [-] (0 = off)
};

struct ClampConfig {
  // Particles inside any box are held fixed. `box = {...}` in the case gives one box,
  // `boxes = [{...}, ...]` several (e.g. a plate clamped at both ends).
  std::vector<Box> boxes;
  // Per box: the velocity its particles are moved at [m/s] (`velocity = [vx, vy]` in the
  // box's table; 0 = held fixed). A prescribed grip motion, e.g. a specimen pulled apart.
  std::vector<Vec2> velocities;
  std::vector<int> layers;  // ring layers held fixed (0 = innermost)
};

struct MotionPoint {
  double t = 0.0;  // [s]
  Vec2 v;          // [m/s]
};

struct BodyConfig {
  std::string name;
  // "elastic", "rigid_fixed", "rigid_prescribed", "rigid_free"
  std::string kind = "elastic";
  std::string scheme = "tl_sfpm";  // elastic only: "tl_sfpm" or "tlsph" (full support)
  std::string material;            // name of a [materials.*] table; rigid bodies: density only
  // Particle density [kg/m^3]: elastic = the material's; rigid = `density` on the body, else
  // the material's, else (rigid_fixed / rigid_prescribed only) fluid.density.
  double density = 0.0;
  ShapeConfig shape;
  double dx = 0.0;                // particle spacing [m] (default numerics.dx)
  double h_over_dx = 0.0;         // default numerics.h_over_dx
  Vec2 velocity;                  // initial velocity [m/s]
  double angular_velocity = 0.0;  // initial angular velocity [rad/s]
  // Optional initial velocity profile: "" or "cantilever_mode" (Gray et al. 2001, with
  // mode_vf and the clamp's free end at shape.box.max.x).
  std::string initial_profile;
  // Failed particles (a material with failure): "lagrangian" keeps them in the
  // total-Lagrangian sums; "eulerian" switches them to current-configuration pairs
  // (solid/eulerian_failed_interaction.h; experimental, docs/model.md §7).
  std::string failed_particles = "lagrangian";
  double mode_vf = 0.0;
  ClampConfig clamp;
  // Particles inside any of these boxes (reference coordinates) start failed: a pre-cut
  // crack or breach (`[body.pre_failed] box = {...}` or `boxes = [...]`; a Johnson–Cook
  // material only, docs/case_format.md).
  std::vector<Box> pre_failed;
  std::vector<MotionPoint> motion;  // rigid_prescribed: velocity table (linear in t)
  std::optional<double> mass;       // rigid_free: [kg/m] (default density × area)
  std::optional<double> inertia;    // rigid_free: [kg m^2/m] (default from particles)
  bool allow_rotation = true;       // rigid_free
  bool gravity = true;              // body feels gravity
};

struct ProbeConfig {
  std::string name;
  // "pressure" (kernel-weighted at position), "surge_front" (largest fluid x),
  // "water_height" (at x), "max_speed" (largest fluid particle speed),
  // "fluid_volume" (water volume m/rho inside box, e.g. what entered a breached hull),
  // "body_pressure" (attached to body surface near position),
  // "body_displacement" (displacement of the body particle nearest position);
  // structural (app/probes.h): "body_strain", "body_stress" (at position),
  // "body_max_strain", "keel_deflection", "ovalisation" (whole body), "shortening"
  // (position → to), "midspan_deflection" (chord position → to, point at).
  std::string kind;
  Vec2 position;
  Vec2 to;  // shortening, midspan_deflection: second end [m]
  Vec2 at;  // midspan_deflection: the point whose deflection is measured [m]
  double x = 0.0;
  Box box;  // fluid_volume: the region [m]
  std::string body;
};

struct OutputConfig {
  double interval = 0.0;        // VTK interval [s] (default end_time/50)
  double probe_interval = 0.0;  // probes.csv interval [s] (0 = every fluid step)
  bool vtk = true;
  std::string vtk_precision = "float32";  // real fields in the .vtp files: "float32", "float64"
  std::string vtk_compression = "none";   // "none" or "zlib"
  std::string plot;  // "" or "cylinder_entry", "dam_break", "plate", "gate", "structure"
  std::vector<ProbeConfig> probes;
  // Times [s] of field snapshots (snapshots/*.png, app/snapshots.h), increasing, in
  // (0, end_time]; each is taken at the first fluid step at or after it.
  std::vector<double> snapshots;
  // The region drawn [m]; empty (min = max) = around the elastic bodies.
  Box snapshot_view;
  bool has_snapshot_view() const { return snapshot_view.max.x > snapshot_view.min.x; }
  // Body whose skin mid-surface P_yy against the angle is written at each snapshot time
  // ("" = none; a ring-shaped elastic body).
  std::string skin_profile;
};

struct CaseConfig {
  int schema_version = 1;
  std::string name;
  std::string source_path;             // the file it came from (for messages)
  std::vector<std::string> overrides;  // command-line "KEY=VALUE" applied to it (--set)
  // Where each key path of the file was given ("case.toml:12" or "--set KEY=VALUE"), so that
  // checks after parsing (particle counts, overlaps, stiffness) name file, line and key.
  std::map<std::string, std::string> locations;
  NumericsConfig numerics;
  FluidConfig fluid;
  std::vector<MaterialConfig> materials;
  std::vector<BodyConfig> bodies;
  OutputConfig output;

  // "<file>:<line>: <key>" for a key path such as "body[1].shape": the key's own location,
  // else that of its nearest enclosing table, else the file.
  std::string where(const std::string& key) const {
    for (std::string k = key;;) {
      if (auto it = locations.find(k); it != locations.end()) return it->second + ": " + key;
      const std::size_t cut = k.find_last_of(".[");
      if (cut == std::string::npos || cut == 0) break;
      k.resize(cut);
    }
    return source_path + ":1: " + key;
  }

  const MaterialConfig* find_material(const std::string& n) const {
    for (const auto& m : materials)
      if (m.name == n) return &m;
    return nullptr;
  }
};

}  // namespace slamsph
