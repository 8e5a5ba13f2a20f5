// A solid body: tank walls, rigid bodies and elastic structures share this storage, so
// the fluid sees all of them through one contact path (spec §4). Elastic bodies are
// total-Lagrangian (spec §3): X is the reference configuration, fixed after setup.
//
// Elastic state is filled by setup_body (solid/body_dynamics.h); the reference pairs and
// gradient weights are a separate value, SolidTopology (solid/solid_topology.h).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/cell_grid.h"
#include "core/field_registry.h"
#include "core/kernel.h"
#include "core/vec.h"
#include "solid/body_kind.h"
#include "solid/eulerian_state.h"
#include "solid/materials/material_law_choice.h"
#include "solid/solid_topology.h"
#include "solid/substep_workspace.h"

namespace slamsph {

// Rigid-body state (free or prescribed motion), about the centre of mass.
struct RigidState {
  double mass = 0.0;     // [kg/m]
  double inertia = 0.0;  // about the centre of mass [kg m^2/m]
  Vec2 com;              // centre of mass [m]
  Vec2 com0;             // initial centre of mass [m]
  double angle = 0.0;    // rotation from the reference [rad]
  Vec2 vel;              // [m/s]
  double omega = 0.0;    // [rad/s]
  Vec2 acc;              // [m/s^2]
  double alpha = 0.0;    // [rad/s^2]
  bool allow_rotation = true;
};

// One row of a prescribed-velocity table (rigid_prescribed), linear in t, held at ends.
struct PrescribedVelocity {
  double t = 0.0;  // [s]
  Vec2 v;          // [m/s]
};

// Material of an elastic body, resolved at setup (spec §3).
struct SolidMaterial {
  MaterialLaw law;              // stress update (solid/materials/material_law.h)
  double density = 0.0;         // [kg/m^3]
  double youngs_modulus = 0.0;  // [Pa]
  double poisson_ratio = 0.0;   // [-]
  double av_alpha = 1.0;        // Monaghan artificial viscosity α [-]
  double av_beta = 0.0;         // Monaghan artificial viscosity β [-]
  double hourglass = 0.0;       // hourglass control coefficient [-] (0 = off)
  double sound_speed = 0.0;     // P-wave speed sqrt(E(1-ν)/(ρ(1+ν)(1-2ν))) [m/s]
};

struct SolidBody {
  std::string name;
  BodyKind kind = BodyKind::RigidFixed;
  SolidScheme scheme = SolidScheme::TlSfpm;
  double dx = 0.0;  // particle spacing [m]; the finest one for a body of parts
  Kernel kernel;    // body's own kernel (h = h_over_dx * dx)
  bool feels_gravity = true;

  // Per particle.
  std::vector<Vec2> X;        // reference position [m]
  std::vector<Vec2> x;        // current position [m]
  std::vector<Vec2> v;        // velocity [m/s]
  std::vector<Vec2> a;        // acceleration [m/s^2]
  std::vector<double> m;      // mass [kg/m]
  std::vector<double> V0;     // reference volume [m^2]
  std::vector<double> rho0;   // reference density [kg/m^3]
  std::vector<Vec2> f_fluid;  // fluid force on the particle, held over sub-steps [N/m]
  // Part of the fluid's impulse not yet given to the particle (app/dual_time_stepping.h:
  // a sub-cycled elastic body receives the end-of-step correction over later steps) [N s/m].
  std::vector<Vec2> impulse_due;
  std::vector<std::uint8_t> clamped;    // 1 = clamped: moved at clamp_velocity, not by forces
  std::vector<Vec2> clamp_velocity;     // velocity of a clamped particle (0: held fixed) [m/s]
  std::vector<int> layer;               // ring layer through the thickness (-1 if none)
  std::vector<std::uint32_t> part;      // part id (index into part_names; 0 for one-part bodies)
  std::vector<double> spacing;          // the particle's own spacing (parts may differ) [m]
  std::vector<std::string> part_names;  // name per part id (a fuselage: skin, stringers, ...)

  RigidState rigid;                        // used by rigid kinds
  std::vector<PrescribedVelocity> motion;  // rigid_prescribed velocity table

  // Elastic state (empty for rigid kinds).
  std::vector<Mat2> F;      // deformation gradient [-]
  std::vector<Mat2> P;      // first Piola–Kirchhoff stress [Pa]
  std::vector<double> e;    // specific internal energy [J/kg]
  std::vector<Vec2> f_int;  // internal (stress + viscosity + hourglass) force [N/m]
  std::vector<Vec2> f_av;   // its artificial-viscosity part [N/m]
  std::vector<Vec2> f_hg;   // its hourglass-control part [N/m]
  MaterialHistory history;  // the law's per-particle history fields (none for SVK)
  // C with F = F_kin C, F_kin = Σ_j (x_j − x_i) ⊗ ∇W⁰_ij of the current topology [-]
  // (elastic bodies). The identity until the Eulerian switch rebuilds the topology around
  // failed particles; then F_kin⁻¹ F at the rebuild, so that F (and the stress and energy
  // with it) stays continuous and changes as F_kin does from there on: F = (F_kin F_kin,s⁻¹) F_s,
  // the kinematic deformation since the rebuild times F then (solid/eulerian_failed_interaction.h).
  std::vector<Mat2> F_rebase;
  std::uint64_t F_rebase_failed = 0;  // the failed count F_rebase was last set for

  // Reference pairs and gradient weights (solid/solid_topology.h), built at set-up from X;
  // the solid operators take it as an explicit argument.
  SolidTopology topology;

  SubstepWorkspace substep;  // scratch of the fused sub-step (not state)

  // Lagrangian → Eulerian switch of failed particles (solid/eulerian_failed_interaction.h;
  // derived from the law's `failed` history, not state). `eulerian_switch = false` keeps
  // failed particles in the total-Lagrangian sums (the behaviour before the switch; tests).
  EulerianState eulerian;
  bool eulerian_switch = true;

  SolidMaterial material;  // elastic bodies
  double cfl = 0.5;        // solid CFL number (spec §3), from NumericsConfig::solid_cfl
  int last_substeps = 0;   // sub-steps taken by the last advance_body call

  // Energy accumulators since setup [J/m].
  double dissipated = 0.0;       // work removed by artificial viscosity
  double hourglass_work = 0.0;   // work done against the hourglass control (its potential
                                 // is reported by body_energies; this is a cross-check)
  double external_work = 0.0;    // work done by gravity and the fluid force (rigid_prescribed:
                                 // the fluid force only; rigid_fixed: none)
  double clamp_work = 0.0;       // work done on the body by moving clamps (their reactions)
  double switch_released = 0.0;  // hourglass potential removed by the Eulerian switch's
                                 // topology rebuilds (solid/eulerian_failed_interaction.h)

  // The per-particle field list (core/field_registry.h). Reference data (X, m, V0, rho0,
  // clamps, layers; the topology) is rebuilt from the case by setup_body, so it is not persistent;
  // f_av and f_hg are recomputed before every use inside a sub-step. Fields flagged vtk
  // are written as they are (F and P only for elastic bodies, where they have one value per
  // particle); derived output (displacement, strains, Cauchy stress and its invariants)
  // comes from solid_output_fields (solid/body_dynamics.h).
  template <class Self, class F>
  static void visit_fields(Self& s, F&& f) {
    f(FieldSpec{"position", "m", true, false}, s.x);  // the VTK points
    f(FieldSpec{"velocity", "m/s", true, true}, s.v);
    f(FieldSpec{"acceleration", "m/s^2", true, false}, s.a);
    f(FieldSpec{"fluid_force", "N/m", true, true}, s.f_fluid);
    f(FieldSpec{"fluid_impulse_due", "N s/m", true, false}, s.impulse_due);
    f(FieldSpec{"deformation_gradient", "-", true, true}, s.F);
    f(FieldSpec{"pk1_stress", "Pa", true, true}, s.P);
    f(FieldSpec{"deformation_gradient_rebase", "-", true, false}, s.F_rebase);
    f(FieldSpec{"specific_internal_energy", "J/kg", true, false}, s.e);
    f(FieldSpec{"internal_force", "N/m", true, false}, s.f_int);
    f(FieldSpec{"viscous_force", "N/m", false, false}, s.f_av);
    f(FieldSpec{"hourglass_force", "N/m", false, false}, s.f_hg);
    f(FieldSpec{"reference_position", "m", false, false}, s.X);
    f(FieldSpec{"mass", "kg/m", false, false}, s.m);
    f(FieldSpec{"reference_volume", "m^2", false, false}, s.V0);
    f(FieldSpec{"reference_density", "kg/m^3", false, false}, s.rho0);
    f(FieldSpec{"clamped", "-", false, false}, s.clamped);
    f(FieldSpec{"layer", "-", false, false}, s.layer);
    f(FieldSpec{"part", "-", false, true}, s.part);
    f(FieldSpec{"spacing", "m", false, false}, s.spacing);
    // The material law's history fields, under the names the law declares
    // (solid/materials/material_law.h), written to VTK if the law marks them for output.
    for (std::size_t k = 0; k < s.history.fields.size(); ++k)
      f(FieldSpec{s.history.fields[k].name, s.history.fields[k].unit, true,
                  s.history.fields[k].output},
        s.history.values[k]);
  }
  // The body's state that is not per particle: rigid motion and energy accumulators.
  template <class Self, class F>
  static void visit_scalars(Self& s, F&& f) {
    f("rigid_mass", s.rigid.mass);
    f("rigid_inertia", s.rigid.inertia);
    f("rigid_com", s.rigid.com);
    f("rigid_com0", s.rigid.com0);
    f("rigid_angle", s.rigid.angle);
    f("rigid_velocity", s.rigid.vel);
    f("rigid_omega", s.rigid.omega);
    f("rigid_acceleration", s.rigid.acc);
    f("rigid_alpha", s.rigid.alpha);
    f("dissipated", s.dissipated);
    f("hourglass_work", s.hourglass_work);
    f("external_work", s.external_work);
    f("clamp_work", s.clamp_work);
    f("switch_released", s.switch_released);
    f("last_substeps", s.last_substeps);
    f("material_updates", s.history.updates);
    f("deformation_gradient_rebase_failed", s.F_rebase_failed);
  }

  std::size_t size() const { return X.size(); }
  bool is_elastic() const { return kind == BodyKind::Elastic; }
  // Current particle volume (elastic bodies: V0 det F; rigid: V0).
  double volume(std::size_t i) const;
  // The kinematic deformation gradient of the current topology, F C⁻¹ (F_rebase): what the
  // hourglass control compares the pair vectors with.
  Mat2 kinematic_F(std::size_t i) const {
    return eulerian.active ? F[i] * inverse(F_rebase[i]) : F[i];
  }
  // The stress conjugate to the kinematic F, P Cᵀ (P : Ḟ = P Cᵀ : Ḟ_kin for F = F_kin C):
  // what the total-Lagrangian pair force takes, so that its power is the stress power.
  Mat2 kinematic_P(std::size_t i) const {
    return eulerian.active ? P[i] * transpose(F_rebase[i]) : P[i];
  }
};

}  // namespace slamsph
