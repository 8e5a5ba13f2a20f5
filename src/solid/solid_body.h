// A solid body: tank walls, rigid bodies and elastic structures share this storage, so
// the fluid sees all of them through one contact path (spec §4). Elastic bodies are
// total-Lagrangian (spec §3): X is the reference configuration, fixed after setup.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/cell_grid.h"
#include "core/kernel.h"
#include "core/vec.h"

namespace slamsph {

enum class BodyKind { Elastic, RigidFixed, RigidPrescribed, RigidFree };
enum class SolidScheme { TlSfpm, TlSph };

// Rigid-body state (free or prescribed motion), about the centre of mass.
struct RigidState {
  double mass = 0.0;      // [kg/m]
  double inertia = 0.0;   // about the centre of mass [kg m^2/m]
  Vec2 com;               // centre of mass [m]
  Vec2 com0;              // initial centre of mass [m]
  double angle = 0.0;     // rotation from the reference [rad]
  Vec2 vel;               // [m/s]
  double omega = 0.0;     // [rad/s]
  Vec2 acc;               // [m/s^2]
  double alpha = 0.0;     // [rad/s^2]
  bool allow_rotation = true;
};

struct SolidBody {
  std::string name;
  BodyKind kind = BodyKind::RigidFixed;
  SolidScheme scheme = SolidScheme::TlSfpm;
  double dx = 0.0;       // particle spacing [m]
  Kernel kernel;         // body's own kernel (h = h_over_dx * dx)
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
  std::vector<std::uint8_t> clamped;  // 1 = held fixed
  std::vector<int> layer;     // ring layer through the thickness (-1 if none)

  RigidState rigid;  // used by rigid kinds

  std::size_t size() const { return X.size(); }
  bool is_elastic() const { return kind == BodyKind::Elastic; }
  // Current particle volume (elastic bodies: V0 det F; rigid: V0).
  double volume(std::size_t i) const;
};

}  // namespace slamsph
