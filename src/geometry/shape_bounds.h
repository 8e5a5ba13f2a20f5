// Axis-aligned bounding box of the cells of the particles a shape produces (tank: including
// its wall layers, no lid when open) — lets the case validator check that a body lies
// inside the domain without building it. Header-only so io/ can use it without linking
// the geometry library.
#pragma once
#include <algorithm>
#include <cmath>

#include "geometry/shape.h"

namespace slamsph {

// Tank wall layers when shape.layers is 0.
inline constexpr int kDefaultTankLayers = 4;
inline int tank_wall_layers(const ShapeConfig& s) {
  return s.layers > 0 ? s.layers : kDefaultTankLayers;
}
// Ring layers through the thickness when shape.layers is 0: round(thickness/dx), >= 1.
inline int ring_thickness_layers(const ShapeConfig& s, double dx) {
  if (s.layers > 0) return s.layers;
  return std::max(1, static_cast<int>(std::lround((s.outer_radius - s.inner_radius) / dx)));
}

// Unknown types give an empty box at the origin.
inline Box shape_bounds(const ShapeConfig& s, double dx) {
  if (s.type == "rectangle") return s.box;
  if (s.type == "fuselage") {
    const double r = 0.5 * s.fuselage.diameter;
    return {s.centre - Vec2{r, r}, s.centre + Vec2{r, r}};
  }
  if (s.type == "disc" || s.type == "ring") {
    const double r = s.type == "disc" ? s.radius : s.outer_radius;
    return {s.centre - Vec2{r, r}, s.centre + Vec2{r, r}};
  }
  if (s.type == "polygon" && !s.vertices.empty()) {
    Box b{s.vertices[0], s.vertices[0]};
    for (const Vec2& p : s.vertices) {
      b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y)};
      b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y)};
    }
    return b;
  }
  if (s.type == "tank") {
    const double w = tank_wall_layers(s) * dx;
    return {{s.box.min.x - w, s.box.min.y - w},
            {s.box.max.x + w, s.open_top ? s.box.max.y : s.box.max.y + w}};
  }
  return {};
}

}  // namespace slamsph
