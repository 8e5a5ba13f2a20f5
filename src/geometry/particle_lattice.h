// Output of the geometry builders: particle positions with the area each particle stands
// for (its volume per unit length, m^2), for layered shapes its layer index and, for shapes
// made of parts (a fuselage section), its part id and own particle spacing. Builders
// are pure functions (style.md §7); compose them by appending lattices.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace slamsph {

struct ParticleLattice {
  std::vector<Vec2> x;              // position [m]
  std::vector<double> volume;       // area represented by the particle [m^2]
  std::vector<int> layer;           // layer index (0 = innermost / nearest the surface), -1 if none
  std::vector<std::uint32_t> part;  // part id (0 for one-part shapes)
  std::vector<double> spacing;      // the particle's own spacing [m] (0: the body's dx)

  std::size_t size() const { return x.size(); }
  void add(Vec2 p, double v, int l = -1, std::uint32_t part_id = 0, double dx = 0.0) {
    x.push_back(p);
    volume.push_back(v);
    layer.push_back(l);
    part.push_back(part_id);
    spacing.push_back(dx);
  }
  void append(const ParticleLattice& o) {
    x.insert(x.end(), o.x.begin(), o.x.end());
    volume.insert(volume.end(), o.volume.begin(), o.volume.end());
    layer.insert(layer.end(), o.layer.begin(), o.layer.end());
    part.insert(part.end(), o.part.begin(), o.part.end());
    spacing.insert(spacing.end(), o.spacing.begin(), o.spacing.end());
  }
  // The particles in the order p (new index k holds particle p[k]), every field moved
  // together; kept next to add() and append() so that a new field is moved too.
  ParticleLattice permuted(const std::vector<std::size_t>& p) const {
    ParticleLattice out;
    for (std::size_t k : p) out.add(x.at(k), volume.at(k), layer.at(k), part.at(k), spacing.at(k));
    return out;
  }
  double total_volume() const {
    double s = 0.0;
    for (double v : volume) s += v;
    return s;
  }
};

}  // namespace slamsph
