#include "geometry/box_lattice.h"

#include <cmath>
#include <stdexcept>

namespace slamsph {

int lattice_cells(double len, double dx) {
  if (!(dx > 0.0)) throw std::invalid_argument("lattice spacing must be > 0");
  const long n = std::lround(len / dx);
  return n < 1 ? 1 : static_cast<int>(n);
}

ParticleLattice fill_box(const Box& box, double dx) {
  const double wx = box.max.x - box.min.x, wy = box.max.y - box.min.y;
  if (!(wx > 0.0) || !(wy > 0.0)) throw std::invalid_argument("fill_box: empty box");
  const int nx = lattice_cells(wx, dx), ny = lattice_cells(wy, dx);
  const double sx = wx / nx, sy = wy / ny;
  ParticleLattice out;
  const std::size_t n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  out.x.reserve(n);
  out.volume.reserve(n);
  out.layer.reserve(n);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      out.add({box.min.x + (i + 0.5) * sx, box.min.y + (j + 0.5) * sy}, sx * sy);
  return out;
}

}  // namespace slamsph
