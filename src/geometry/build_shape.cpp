#include "geometry/build_shape.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/box_lattice.h"
#include "geometry/polar_lattice.h"
#include "geometry/polygon_lattice.h"
#include "geometry/tank_walls.h"

namespace slamsph {

namespace {
int ring_layers(const ShapeConfig& s, double dx) {
  if (s.layers > 0) return s.layers;
  return std::max(1, static_cast<int>(std::lround((s.outer_radius - s.inner_radius) / dx)));
}
int tank_layers(const ShapeConfig& s) {
  return s.layers > 0 ? s.layers : 4;
}
}  // namespace

ParticleLattice build_shape(const ShapeConfig& s, double dx) {
  if (s.type == "rectangle") return fill_box(s.box, dx);
  if (s.type == "disc") return disc(s.centre, s.radius, dx);
  if (s.type == "ring") return ring(s.centre, s.inner_radius, s.outer_radius, ring_layers(s, dx));
  if (s.type == "polygon") return polygon(s.vertices, dx);
  if (s.type == "tank") return tank_walls(s.box, dx, tank_layers(s), s.open_top);
  throw std::invalid_argument("build_shape: unknown shape type '" + s.type + "'");
}

Box shape_bounds(const ShapeConfig& s, double dx) {
  if (s.type == "rectangle") return s.box;
  if (s.type == "disc") {
    const Vec2 r{s.radius, s.radius};
    return {s.centre - r, s.centre + r};
  }
  if (s.type == "ring") {
    const Vec2 r{s.outer_radius, s.outer_radius};
    return {s.centre - r, s.centre + r};
  }
  if (s.type == "polygon") {
    if (s.vertices.empty()) return {};
    Box b{s.vertices[0], s.vertices[0]};
    for (const Vec2& p : s.vertices) {
      b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y)};
      b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y)};
    }
    return b;
  }
  if (s.type == "tank") {
    const double w = tank_layers(s) * dx;
    return {{s.box.min.x - w, s.box.min.y - w},
            {s.box.max.x + w, s.open_top ? s.box.max.y : s.box.max.y + w}};
  }
  throw std::invalid_argument("shape_bounds: unknown shape type '" + s.type + "'");
}

}  // namespace slamsph
