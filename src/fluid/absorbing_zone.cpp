#include "fluid/absorbing_zone.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "fluid/hydrostatic_init.h"

namespace slamsph {

double absorbing_rate(const AbsorbingZone& z, Vec2 x) {
  // Distance from each wall face into the tank.
  const std::array<double, 4> d{x.x - z.inner.min.x, z.inner.max.x - x.x, x.y - z.inner.min.y,
                                z.inner.max.y - x.y};
  double sigma = 0.0;
  for (int w = 0; w < 4; ++w) {
    if (!(z.width[w] > 0.0) || d[w] >= z.width[w]) continue;
    const double q = 1.0 - std::max(d[w], 0.0) / z.width[w];
    sigma = std::max(sigma, z.sigma_wall[w] * q * q);
  }
  return sigma;
}

double absorbing_reference_density(const AbsorbingZone& z, const TaitEos& eos, Vec2 x) {
  // Gravity along −y (the tank's vertical); the depth below the still surface.
  return eos.density(hydrostatic_pressure(z.surface - x.y, std::abs(z.gravity.y), eos));
}

Vec2 apply_absorbing_zone(FluidParticles& f, const AbsorbingZone& z, const TaitEos& eos, double dt,
                          const Executor& exec) {
  if (!z.active()) return {};
  return exec.sum_of<Vec2>(f.size(), [&](std::size_t i) {
    const double sigma = absorbing_rate(z, f.x[i]);
    if (sigma == 0.0) return Vec2{};
    const double decay = std::exp(-sigma * dt);
    const double rho_h = absorbing_reference_density(z, eos, f.x[i]);
    const Vec2 v0 = f.v[i];
    f.v[i] = decay * v0;
    f.rho[i] = rho_h + decay * (f.rho[i] - rho_h);
    f.p[i] = eos.pressure(f.rho[i]);
    return f.m[i] * (f.v[i] - v0);
  });
}

}  // namespace slamsph
