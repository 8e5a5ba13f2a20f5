// The fluid's view of every solid particle, tank walls and bodies alike (spec §4): the
// solid particles are the fluid's boundary particles. The driver gathers this from the
// bodies before the fluid pass and scatters `force` back afterwards.
#pragma once
#include <cstdint>
#include <vector>

#include "core/field_registry.h"
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
  // 1 for a failed particle of an elastic body: it still pushes on the water (compression
  // only) but is debris, not a wall, so the leak counter does not judge by it
  // (coupling/failure_zone_ghosts.h). Set at each gather.
  std::vector<std::uint8_t> debris;

  std::size_t size() const { return x.size(); }
  // Whether fluid particle at xf may interact with contact particle s.
  bool faces(std::size_t s, Vec2 xf) const {
    return !ghost[s] || dot(xf - anchor[s], normal[s]) > 0.0;
  }
  // The field list. body, local and ghost are the layout (coupling/contact_layout.h),
  // rebuilt from the case; the rest is the state of the last rate evaluation, which the
  // outputs between steps read (contact pressure, wetted flags).
  template <class Self, class F>
  static void visit_fields(Self& s, F&& f) {
    f(FieldSpec{"position", "m", true, false}, s.x);
    f(FieldSpec{"velocity", "m/s", true, false}, s.v);
    f(FieldSpec{"acceleration", "m/s^2", true, false}, s.a);
    f(FieldSpec{"volume", "m^2", true, false}, s.volume);
    f(FieldSpec{"pressure", "Pa", true, false}, s.p);
    f(FieldSpec{"density", "kg/m^3", true, false}, s.rho);
    f(FieldSpec{"velocity_noslip", "m/s", true, false}, s.v_noslip);
    f(FieldSpec{"wetted", "-", true, false}, s.wetted);
    f(FieldSpec{"normal", "-", true, false}, s.normal);
    f(FieldSpec{"force", "N/m", true, false}, s.force);
    f(FieldSpec{"force_viscous", "N/m", true, false}, s.force_viscous);
    f(FieldSpec{"body", "-", false, false}, s.body);
    f(FieldSpec{"local", "-", false, false}, s.local);
    f(FieldSpec{"ghost", "-", false, false}, s.ghost);
    f(FieldSpec{"anchor", "m", true, false}, s.anchor);
    f(FieldSpec{"debris", "-", false, false}, s.debris);
  }
  void resize(std::size_t n) { resize_fields(*this, n); }
};

}  // namespace slamsph
