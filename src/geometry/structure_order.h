// The order in which a body's particles are stored (issue 13, docs/model.md §3 "Particle
// order"). The builders lay a structure out part by part and layer by layer (a ring: all of
// layer 0, then layer 1, ...), so the partners of a particle in the next layer are a whole
// layer away in memory and a thread's contiguous share of the particles (core/parallel.h,
// Team::share) is a set of layers, every one of whose pairs with the other share crosses
// between the cores at every sub-step. Ordered along a Hilbert curve over the reference
// positions instead, the partners of a particle are stored near it and a share is a compact
// piece of the structure that touches the other share only where the curve's halves meet.
// The order changes nothing but the summation order of the pair sums (round-off).
#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "core/vec.h"
#include "geometry/particle_lattice.h"

namespace slamsph {

// Permutation p (new index k holds old particle p[k]) that sorts the points by the Hilbert
// index of the square cell of side `cell` [m] (> 0) that holds them, over their bounding
// box; points in one cell keep their relative order. Deterministic.
std::vector<std::size_t> hilbert_order(std::span<const Vec2> x, double cell);

// `lat` in Hilbert order on cells of its finest spacing (`dx` where a particle has none).
ParticleLattice ordered_along_structure(const ParticleLattice& lat, double dx);

}  // namespace slamsph
