// Cell-centred Cartesian lattices filling an axis-aligned box (fluid blocks, rectangular
// bodies). Particles sit at min + (i+½)s per axis with n = round(side/dx) cells and
// s = side/n, so the lattice covers the box exactly (s = dx when the side is a multiple
// of dx, which case files should ensure) and the volumes sum to the box area.
#pragma once
#include "core/box.h"
#include "geometry/particle_lattice.h"

namespace slamsph {

// Number of cells of size ~dx along a side of length `len` (at least 1).
int lattice_cells(double len, double dx);

ParticleLattice fill_box(const Box& box, double dx);
inline ParticleLattice rectangle(const Box& box, double dx) {
  return fill_box(box, dx);
}

}  // namespace slamsph
