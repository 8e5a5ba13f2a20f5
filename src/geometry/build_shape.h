// Dispatch from a case file's [body.shape] to the geometry builders:
// rectangle → fill_box(box), disc → disc(centre, radius), ring → ring(centre, inner_radius,
// outer_radius, layers; layers 0 → round(thickness/dx)), polygon → polygon(vertices, fill),
// tank → tank_walls(box as the inner box, layers; 0 → 4, open_top),
// fuselage → fuselage_section(centre, fuselage) (its own spacings; dx unused).
#pragma once
#include "geometry/particle_lattice.h"
#include "geometry/shape.h"
#include "geometry/shape_bounds.h"

namespace slamsph {

ParticleLattice build_shape(const ShapeConfig& shape, double dx);  // throws std::invalid_argument
// (FuselageShapeError, naming the shape key, for a fuselage)

}  // namespace slamsph
