// Where every solid particle sits in the fluid's contact set (spec §4): the particles of
// body 0, then body 1, ..., then the ghost layers behind thin bodies
// (coupling/ghost_layers.h). The layout is planned from the reference configuration and
// re-planned around failed particles when a body's failed set grows
// (coupling/failure_zone_ghosts.h); before each fluid pass the bodies' current state is gathered
// into the contact set, and after it the fluid force on each contact particle is scattered back to
// its body particle (a ghost's force to its parent, so momentum stays exact).
#pragma once
#include <cstdint>
#include <vector>

#include "core/vec.h"
#include "coupling/contact_particles.h"
#include "coupling/ghost_layers.h"
#include "solid/solid_body.h"

namespace slamsph {

struct ContactGhost {
  std::uint32_t body = 0;
  GhostSpec spec;  // a slot: spec.parent only; depth and weight are set at each gather
  // -1: a reference ghost (spec fixed). j >= 0: slot j of a particle near a failure, placed
  // from the current configuration (coupling/failure_zone_ghosts.h).
  std::int32_t slot = -1;
};

struct ContactLayout {
  std::vector<std::vector<Vec2>> ref_normals;  // per body: reference outward normals N
  std::vector<std::size_t> offset;   // first contact index of each body; back() = first ghost
  std::vector<ContactGhost> ghosts;  // stored after all real contact particles
  // The reference plan, kept for re-planning; what it was planned for.
  std::vector<ContactGhost> reference_ghosts;
  double support = 0.0, ghost_spacing = 0.0;
  // Per body: the failed count the ghosts are planned for, and the failure zone of those
  // failed particles (coupling/failure_zone_ghosts.h; empty without failures).
  std::vector<std::size_t> planned_failed;
  std::vector<std::vector<std::uint8_t>> zone;

  std::size_t first_ghost() const { return offset.back(); }
  std::size_t size() const { return offset.back() + ghosts.size(); }
};

// Offsets of the bodies and the ghost layers they need for a kernel of support `support`;
// ref_normals[b] are body b's reference surface normals (coupling/surface_normals.h).
// fluid_dx: the water's spacing; ghost cells behind a body finer than the water are half of
// it deep (coupling/ghost_layers.h; 0 = one ghost per missing body layer).
ContactLayout plan_contact_layout(const std::vector<SolidBody>& bodies,
                                  std::vector<std::vector<Vec2>> ref_normals, double support,
                                  double fluid_dx = 0.0);

// Re-plans the ghosts of every elastic body whose failed count differs from the one the
// layout was planned for: the reference ghosts of its failure-zone particles are replaced by
// slots placed in the current configuration, the failed particles' dropped
// (coupling/failure_zone_ghosts.h). A function of the failed flags only (a resumed run
// re-plans the same layout). Returns true if the layout changed: the contact set must then
// be re-initialised (init_contact_particles) and the fluid–contact lists rebuilt.
bool replan_around_failures(ContactLayout& layout, const std::vector<SolidBody>& bodies);

// Sizes `contact` to the layout and fills its fixed fields (body, local, ghost).
void init_contact_particles(ContactParticles& contact, const ContactLayout& layout);

// Copies the bodies' current position, velocity, acceleration and volume into the contact
// set, with the current outward normal: n ∝ F^-T N for elastic bodies (Nanson), N rotated
// by the body's angle for moving rigid bodies; in the failure zone the layout was last planned
// for (replan_around_failures), the current colour gradient (coupling/surface_normals.h). Ghosts
// follow their parent along its normal, with their weight times its volume; slots at the depth and
// weight the current configuration asks for. Failed particles are marked as debris.
// refresh_fixed = false leaves the entries of rigid_fixed bodies and their ghosts as they are:
// such a body never moves (advance_rigid keeps x and zeroes v and a), so once gathered after
// a step they stay valid until the contact set is re-planned (FsiStepper).
void gather_body_state(ContactParticles& contact, const ContactLayout& layout,
                       const std::vector<SolidBody>& bodies, bool refresh_fixed = true);

// body.f_fluid = the contact force on each of its particles plus that of its ghosts.
void scatter_contact_forces(const ContactParticles& contact, const ContactLayout& layout,
                            std::vector<SolidBody>& bodies);

}  // namespace slamsph
