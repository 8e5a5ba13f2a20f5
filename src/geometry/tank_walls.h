// Tank walls as `layers` rows of cell-centred dummy particles outside an inner box: the
// bottom, both sides and (closed tank) the top, corners filled. The wall particles'
// cells tile the band between the inner box and the inner box grown by layers·dx, so the
// wall surface seen by the fluid is exactly the inner box boundary. Along a wall the
// spacing is side/round(side/dx) (= dx when the inner box is a multiple of dx); through
// the thickness it is dx. layer = 0 for the row touching the fluid, increasing outwards.
#pragma once
#include "core/box.h"
#include "geometry/particle_lattice.h"

namespace slamsph {

ParticleLattice tank_walls(const Box& inner, double dx, int layers, bool open_top);

}  // namespace slamsph
