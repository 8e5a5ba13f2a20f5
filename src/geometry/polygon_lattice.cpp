#include "geometry/polygon_lattice.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slamsph {

bool point_in_polygon(Vec2 p, const std::vector<Vec2>& v) {
  bool inside = false;
  const std::size_t n = v.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = v[i], b = v[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double xc = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < xc) inside = !inside;
    }
  }
  return inside;
}

double polygon_area(const std::vector<Vec2>& v) {
  double s = 0.0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) s += cross(v[j], v[i]);
  return 0.5 * std::abs(s);
}

ParticleLattice polygon(const std::vector<Vec2>& vertices, double dx) {
  if (vertices.size() < 3) throw std::invalid_argument("polygon: need at least 3 vertices");
  if (!(dx > 0.0)) throw std::invalid_argument("polygon: dx must be > 0");
  Vec2 lo = vertices[0], hi = vertices[0];
  for (const Vec2& p : vertices) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const long nx = std::lround(std::ceil((hi.x - lo.x) / dx - 1e-9));
  const long ny = std::lround(std::ceil((hi.y - lo.y) / dx - 1e-9));
  ParticleLattice out;
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      const Vec2 p{lo.x + (static_cast<double>(i) + 0.5) * dx,
                   lo.y + (static_cast<double>(j) + 0.5) * dx};
      if (point_in_polygon(p, vertices)) out.add(p, dx * dx);
    }
  return out;
}

}  // namespace slamsph
