// Counts fluid particles found inside a solid (spec §4, thin structures): a fluid particle
// is inside when its nearest solid neighbour is an interior particle (zero normal) or
// lies on the far side of that particle's surface by more than a quarter spacing. With
// steps far shorter than a particle spacing, a particle crossing even a two-layer skin
// must pass such a state. Flags are sticky (FluidParticles::crossed).
#pragma once
#include "core/cell_grid.h"
#include "core/parallel.h"
#include "coupling/contact_particles.h"
#include "fluid/fluid_particles.h"

namespace slamsph {

// Updates f.crossed and returns how many fluid particles have ever crossed.
long update_leak_flags(FluidParticles& f, const ContactParticles& c, const NeighbourList& fc,
                       const Executor& exec);

}  // namespace slamsph
