#include "geometry/tank_walls.h"

#include <algorithm>
#include <stdexcept>

#include "geometry/box_lattice.h"

namespace slamsph {

ParticleLattice tank_walls(const Box& inner, double dx, int layers, bool open_top) {
  if (layers < 1) throw std::invalid_argument("tank_walls: layers must be >= 1");
  const double wx = inner.max.x - inner.min.x, wy = inner.max.y - inner.min.y;
  if (!(wx > 0.0) || !(wy > 0.0)) throw std::invalid_argument("tank_walls: empty inner box");
  const int nx = lattice_cells(wx, dx), ny = lattice_cells(wy, dx);
  const double sx = wx / nx, sy = wy / ny;
  ParticleLattice out;
  // Columns across the full width: `layers` corner columns, nx interior, `layers` corner.
  auto column_x = [&](int c, int& layer) {
    if (c < layers) {
      layer = layers - 1 - c;
      return inner.min.x - (layers - c - 0.5) * dx;
    }
    if (c < layers + nx) {
      layer = -1;
      return inner.min.x + (c - layers + 0.5) * sx;
    }
    layer = c - layers - nx;
    return inner.max.x + (layer + 0.5) * dx;
  };
  const int ncol = nx + 2 * layers;
  // Bottom (with corners): rows k = 0 (touching the fluid) .. layers-1.
  for (int k = layers - 1; k >= 0; --k) {
    const double y = inner.min.y - (k + 0.5) * dx;
    for (int c = 0; c < ncol; ++c) {
      int lc = 0;
      const double x = column_x(c, lc);
      const double wxc = (lc < 0) ? sx : dx;
      out.add({x, y}, wxc * dx, lc < 0 ? k : std::max(k, lc));
    }
  }
  // Sides, over the inner height.
  for (int j = 0; j < ny; ++j) {
    const double y = inner.min.y + (j + 0.5) * sy;
    for (int k = layers - 1; k >= 0; --k) out.add({inner.min.x - (k + 0.5) * dx, y}, dx * sy, k);
    for (int k = 0; k < layers; ++k) out.add({inner.max.x + (k + 0.5) * dx, y}, dx * sy, k);
  }
  // Lid (with corners).
  if (!open_top) {
    for (int k = 0; k < layers; ++k) {
      const double y = inner.max.y + (k + 0.5) * dx;
      for (int c = 0; c < ncol; ++c) {
        int lc = 0;
        const double x = column_x(c, lc);
        const double wxc = (lc < 0) ? sx : dx;
        out.add({x, y}, wxc * dx, lc < 0 ? k : std::max(k, lc));
      }
    }
  }
  return out;
}

}  // namespace slamsph
