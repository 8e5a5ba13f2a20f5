// Where every solid particle sits in the fluid's contact set (spec §4): the particles of
// body 0, then body 1, ..., then the ghost layers behind thin bodies
// (coupling/ghost_layers.h). The layout is planned once from the reference configuration;
// before each fluid pass the bodies' current state is gathered into the contact set, and
// after it the fluid force on each contact particle is scattered back to its body particle
// (a ghost's force to its parent, so momentum stays exact).
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
  GhostSpec spec;
};

struct ContactLayout {
  std::vector<std::vector<Vec2>> ref_normals;  // per body: reference outward normals N
  std::vector<std::size_t> offset;   // first contact index of each body; back() = first ghost
  std::vector<ContactGhost> ghosts;  // stored after all real contact particles

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

// Sizes `contact` to the layout and fills its fixed fields (body, local, ghost).
void init_contact_particles(ContactParticles& contact, const ContactLayout& layout);

// Copies the bodies' current position, velocity, acceleration and volume into the contact
// set, with the current outward normal: n ∝ F^-T N for elastic bodies (Nanson), N rotated
// by the body's angle for moving rigid bodies. Ghosts follow their parent along its normal, with
// their weight times its volume.
void gather_body_state(ContactParticles& contact, const ContactLayout& layout,
                       const std::vector<SolidBody>& bodies);

// body.f_fluid = the contact force on each of its particles plus that of its ghosts.
void scatter_contact_forces(const ContactParticles& contact, const ContactLayout& layout,
                            std::vector<SolidBody>& bodies);

}  // namespace slamsph
