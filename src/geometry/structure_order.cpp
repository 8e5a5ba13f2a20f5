#include "geometry/structure_order.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace slamsph {
namespace {

// Index of cell (cx, cy) along the Hilbert curve that fills a 2^order × 2^order grid: at
// each level from the coarsest, the quadrant's position along the curve (0..3) and the
// rotation/reflection that maps the quadrant onto the standard orientation.
std::uint64_t hilbert_index(std::uint32_t cx, std::uint32_t cy, int order) {
  std::uint64_t d = 0;
  for (std::uint32_t s = std::uint32_t{1} << (order - 1); s > 0; s >>= 1) {
    const std::uint32_t rx = (cx & s) ? 1 : 0, ry = (cy & s) ? 1 : 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {  // rotate the quadrant so that the curve enters and leaves as at the top
      if (rx == 1) {
        cx = s - 1 - (cx & (s - 1));
        cy = s - 1 - (cy & (s - 1));
      }
      std::swap(cx, cy);
    }
    cx &= s - 1;
    cy &= s - 1;
  }
  return d;
}

}  // namespace

std::vector<std::size_t> hilbert_order(std::span<const Vec2> x, double cell) {
  if (!(cell > 0.0)) throw std::invalid_argument("hilbert_order: cell must be > 0");
  std::vector<std::size_t> p(x.size());
  std::iota(p.begin(), p.end(), std::size_t{0});
  if (x.size() < 2) return p;
  Vec2 lo = x[0], hi = x[0];
  for (const Vec2& q : x) {
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
  }
  // Cells centred on the lowest point, so that points of a lattice of spacing `cell` sit
  // at cell centres, not on cell edges where round-off would pick the cell.
  lo = lo - Vec2{0.5 * cell, 0.5 * cell};
  const double cells = std::max(hi.x - lo.x, hi.y - lo.y) / cell + 1.0;
  int order = 1;
  while (order < 31 && static_cast<double>(std::uint32_t{1} << order) < cells) ++order;
  const double top = static_cast<double>((std::uint32_t{1} << order) - 1);
  auto coord = [&](double v, double v0) {
    return static_cast<std::uint32_t>(std::clamp(std::floor((v - v0) / cell), 0.0, top));
  };
  std::vector<std::uint64_t> key(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    key[i] = hilbert_index(coord(x[i].x, lo.x), coord(x[i].y, lo.y), order);
  std::stable_sort(p.begin(), p.end(),
                   [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  return p;
}

ParticleLattice ordered_along_structure(const ParticleLattice& lat, double dx) {
  double cell = dx;
  for (double d : lat.spacing)
    if (d > 0.0) cell = std::min(cell, d);
  return lat.permuted(hilbert_order(lat.x, cell));
}

}  // namespace slamsph
