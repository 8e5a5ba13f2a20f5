// Cartesian lattice points inside a simple polygon (either orientation): the cell-centred
// dx lattice over the polygon's bounding box, keeping the cell centres inside the polygon
// (even–odd rule). Each particle has volume dx²; the total converges to the polygon area
// as dx → 0 and is exact for axis-aligned rectangles whose sides are multiples of dx.
#pragma once
#include <vector>

#include "geometry/particle_lattice.h"

namespace slamsph {

bool point_in_polygon(Vec2 p, const std::vector<Vec2>& vertices);
double polygon_area(const std::vector<Vec2>& vertices);  // unsigned
ParticleLattice polygon(const std::vector<Vec2>& vertices, double dx);

}  // namespace slamsph
