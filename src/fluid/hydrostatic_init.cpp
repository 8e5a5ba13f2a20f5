#include "fluid/hydrostatic_init.h"

#include <algorithm>
#include <cmath>

namespace slamsph {

double hydrostatic_pressure(double depth, double g, const TaitEos& eos) {
  // Using rho0 g z instead leaves a 1 % density mismatch at 0.5 m depth (c0 = 20 m/s) that
  // the static-state term of the Riemann U* (riemann_solver.h) turns into a density drift.
  const double B = eos.stiffness(), gm = eos.gamma, z = std::max(0.0, depth);
  return B * (std::pow(1.0 + (gm - 1.0) / gm * eos.rho0 * g * z / B, gm / (gm - 1.0)) - 1.0);
}

void append_hydrostatic_block(FluidParticles& f, const std::vector<Vec2>& pts, double dx,
                              double surface, Vec2 gravity, const TaitEos& eos) {
  const std::size_t n0 = f.size();
  f.resize(n0 + pts.size());
  const double g = std::abs(gravity.y);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const std::size_t i = n0 + k;
    const double p = hydrostatic_pressure(surface - pts[k].y, g, eos);
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
