#include "fluid/hydrostatic_init.h"

#include <algorithm>
#include <cmath>

namespace slamsph {

void append_hydrostatic_block(FluidParticles& f, const std::vector<Vec2>& pts, double dx,
                              double surface, Vec2 gravity, const TaitEos& eos) {
  const std::size_t n0 = f.size();
  f.resize(n0 + pts.size());
  const double g = std::abs(gravity.y);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const std::size_t i = n0 + k;
    const double depth = std::max(0.0, surface - pts[k].y);
    const double p = eos.rho0 * g * depth;
    f.x[i] = pts[k];
    f.v[i] = Vec2{};
    f.a[i] = Vec2{};
    f.p[i] = p;
    f.rho[i] = eos.density(p);
    f.drho[i] = 0.0;
    f.m[i] = f.rho[i] * dx * dx;
    f.id[i] = static_cast<std::int64_t>(i);
  }
}

}  // namespace slamsph
