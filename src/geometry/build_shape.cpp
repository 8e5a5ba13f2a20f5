#include "geometry/build_shape.h"

#include <stdexcept>

#include "geometry/box_lattice.h"
#include "geometry/fuselage_section.h"
#include "geometry/polar_lattice.h"
#include "geometry/polygon_lattice.h"
#include "geometry/tank_walls.h"

namespace slamsph {

ParticleLattice build_shape(const ShapeConfig& s, double dx) {
  if (s.type == "rectangle") return fill_box(s.box, dx);
  if (s.type == "disc") return disc(s.centre, s.radius, dx);
  if (s.type == "ring")
    return ring(s.centre, s.inner_radius, s.outer_radius, ring_thickness_layers(s, dx));
  if (s.type == "polygon") return polygon(s.vertices, dx, s.fill);
  if (s.type == "fuselage") return fuselage_section(s.centre, s.fuselage);
  if (s.type == "tank") return tank_walls(s.box, dx, tank_wall_layers(s), s.open_top);
  throw std::invalid_argument("build_shape: unknown shape type '" + s.type + "'");
}

}  // namespace slamsph
