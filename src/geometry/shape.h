// The description of a body's shape that the geometry builders turn into particles
// (geometry/build_shape.h). Plain data: the case parser fills it, geometry never sees the
// case format (io/).
#pragma once
#include <string>
#include <vector>

#include "core/box.h"
#include "core/vec.h"
#include "geometry/fuselage_shape.h"
#include "geometry/polygon_lattice.h"

namespace slamsph {

struct ShapeConfig {
  // "rectangle" (box), "disc" (centre, radius), "ring" (centre, inner/outer radius,
  // layers through the thickness), "polygon" (vertices), "tank" (inner box, wall layers,
  // open top), "fuselage" (centre and `fuselage`: skin, stringers, floor, columns).
  std::string type;
  Box box;
  Vec2 centre;
  double radius = 0.0;
  double inner_radius = 0.0;
  double outer_radius = 0.0;
  int layers = 0;  // ring: layers through the thickness; tank: wall layers (default 4)
  std::vector<Vec2> vertices;
  // polygon: particles laid along the faces or the Cartesian lattice (geometry/polygon_lattice.h)
  PolygonFill fill = PolygonFill::Cartesian;
  bool open_top = true;  // tank
  FuselageShape fuselage;
};

}  // namespace slamsph
