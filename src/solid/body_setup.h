// Everything setup_body (solid/body_dynamics.h) needs to turn a particle lattice into a
// body, as plain physics values: the case builder (app/case_builder.h) translates the case
// file into this, tests fill it directly. Solids never see the case format (io/).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/box.h"
#include "core/kernel.h"
#include "core/vec.h"
#include "solid/body_kind.h"
#include "solid/solid_body.h"

namespace slamsph {

// Parameters of an elastic body's material (spec §3, plane strain; the law and its own
// parameters in `model`, solid/materials/material_law.h).
struct ElasticMaterialInput {
  std::string name;  // for messages
  MaterialModel model = SvkModel{};
  double density = 0.0;         // [kg/m^3] (0: the particles' rho0)
  double youngs_modulus = 0.0;  // [Pa]
  double poisson_ratio = 0.0;   // [-]
  double av_alpha = 1.0;        // Monaghan artificial viscosity α [-] (spec §3)
  double av_beta = 0.0;         // Monaghan artificial viscosity β [-]
  double hourglass = 0.1;       // hourglass control coefficient [-] (0 = off)
};

// Initial velocity of the first bending mode of a cantilever (Gray et al. 2001,
// solid/cantilever_mode.h) clamped at x = clamp_edge with its free end at clamp_edge + length.
struct CantileverModeInput {
  double clamp_edge = 0.0;  // [m]
  double length = 0.0;      // [m]
  double vf = 0.0;          // mode amplitude parameter V_f [-]
};

struct BodySetup {
  std::string name;
  BodyKind kind = BodyKind::Elastic;
  SolidScheme scheme = SolidScheme::TlSfpm;  // elastic only
  bool eulerian_switch = false;              // failed particles leave the TL sums (elastic)
  double dx = 0.0;                           // particle spacing [m]
  double h_over_dx = 1.3;                    // smoothing length ratio [-]
  KernelType kernel = KernelType::WendlandC2;
  double solid_cfl = 0.5;              // solid CFL number [-] (spec §3)
  bool gravity = true;                 // the body feels gravity
  Vec2 velocity;                       // initial velocity [m/s]
  double angular_velocity = 0.0;       // initial angular velocity about the centre of mass [rad/s]
  std::vector<Box> clamp_boxes;        // particles inside any box are held fixed
  std::vector<Vec2> clamp_velocities;  // per box, the grip velocity (empty or 0: fixed) [m/s]
  std::vector<int> clamp_layers;       // ring layers held fixed (0 = innermost)
  // Particles inside any box start failed (a pre-cut breach; a law with a `failed` history
  // field, solid/eulerian_failed_interaction.h).
  std::vector<Box> pre_failed_boxes;
  std::optional<CantileverModeInput> cantilever_mode;  // elastic only
  std::vector<PrescribedVelocity> motion;              // rigid_prescribed velocity table
  std::optional<double> mass;                          // rigid_free [kg/m]
  std::optional<double> inertia;                       // rigid_free [kg m^2/m]
  bool allow_rotation = true;                          // rigid_free
  std::optional<ElasticMaterialInput> material;        // required for elastic bodies
};

}  // namespace slamsph
