// Umbrella header for the geometry builders (pure functions returning ParticleLattice).
#pragma once
#include "geometry/box_lattice.h"
#include "geometry/build_shape.h"
#include "geometry/fuselage_section.h"
#include "geometry/particle_lattice.h"
#include "geometry/polar_lattice.h"
#include "geometry/polygon_lattice.h"
#include "geometry/remove_overlap.h"
#include "geometry/shape_bounds.h"
#include "geometry/structure_order.h"
#include "geometry/tank_walls.h"
