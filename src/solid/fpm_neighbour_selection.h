// Selected neighbour sets S_i of the TL-SFPM gradient (spec §3, paper Fig. 2), chosen once
// from the reference positions X:
//  - interior particle: its 4 nearest particles;
//  - boundary particle: itself plus its 3 nearest (itself adds nothing to the gradient,
//    Eq. 7, so only the 3 nearest are stored);
//  - corner particle: its 3 nearest, which on a lattice include the diagonal (Eq. 8).
// Boundary detection: the centroid of the neighbours within 1.5 dx lies more than
// 0.25 dx from the particle (0 for an interior lattice point, 0.6 dx on a straight edge,
// 0.94 dx at a corner; robust to ~20 % lattice perturbation and to polar layers).
// Ties in distance are broken by index, so the sets are deterministic. If the chosen set is
// nearly collinear (smallest/largest eigenvalue of M_i below 0.05) the next nearest are
// added until it is not. Throws std::invalid_argument for a particle with no usable set
// (e.g. a single row of particles).
#pragma once
#include <span>

#include "core/cell_grid.h"
#include "core/vec.h"

namespace slamsph {

class Executor;

void select_fpm_sets(std::span<const Vec2> X, double dx, const Executor& exec, NeighbourList& sets);

// The same with each particle's own spacing (a body of parts with different spacings):
// particle i's candidate radius, boundary test and weight use spacing[i], so a particle of
// a coarse part next to a fine one selects among the fine particles within its own reach.
void select_fpm_sets(std::span<const Vec2> X, std::span<const double> spacing, const Executor& exec,
                     NeighbourList& sets);

}  // namespace slamsph
