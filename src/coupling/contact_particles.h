// The fluid's view of every solid particle, tank walls and bodies alike (spec §4): the
// solid particles are the fluid's boundary particles. The driver gathers this from the
// bodies before the fluid pass and scatters `force` back afterwards.
#pragma once
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace slamsph {

struct ContactParticles {
  std::vector<Vec2> x;               // position [m]
  std::vector<Vec2> v;               // velocity [m/s]
  std::vector<Vec2> a;               // acceleration used in the virtual pressure [m/s^2]
  std::vector<double> volume;        // current particle volume [m^2]
  std::vector<double> p;             // virtual pressure p' [Pa] (spec §4)
  std::vector<double> rho;           // virtual density rho' from the inverse EOS [kg/m^3]
  std::vector<Vec2> v_noslip;        // mirrored velocity for viscous terms (Eq. 14) [m/s]
  std::vector<std::uint8_t> wetted;  // 1 if it has fluid neighbours (takes part)
  std::vector<Vec2> normal;          // outward unit surface normal; zero inside a body (leak check)
  std::vector<Vec2> force;           // total fluid force on the particle [N/m]
  std::vector<Vec2> force_viscous;   // its viscous part [N/m]
  std::vector<std::uint32_t> body;   // owning body index
  std::vector<std::uint32_t> local;  // index inside the body (a ghost: its parent's index)
  // Ghost layers of thin bodies (coupling/ghost_layers.h): a ghost acts only on fluid
  // particles on its parent's side, dot(x_f - anchor, normal) > 0; anchor = parent position.
  std::vector<std::uint8_t> ghost;
  std::vector<Vec2> anchor;

  std::size_t size() const { return x.size(); }
  // Whether fluid particle at xf may interact with contact particle s.
  bool faces(std::size_t s, Vec2 xf) const {
    return !ghost[s] || dot(xf - anchor[s], normal[s]) > 0.0;
  }
  void resize(std::size_t n) {
    x.resize(n);
    v.resize(n);
    a.resize(n);
    volume.resize(n);
    p.resize(n);
    rho.resize(n);
    v_noslip.resize(n);
    wetted.resize(n);
    normal.resize(n);
    force.resize(n);
    force_viscous.resize(n);
    body.resize(n);
    local.resize(n);
    ghost.resize(n);
    anchor.resize(n);
  }
};

}  // namespace slamsph
