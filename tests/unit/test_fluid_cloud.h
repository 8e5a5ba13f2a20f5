// A disordered, non-uniform cloud of water particles for the fluid pass tests: nx by ny
// lattice sites 1 cm apart, each moved by up to `jitter` spacings, with random velocities,
// densities, pressures and masses.
#pragma once
#include <cstdint>
#include <random>

#include "fluid/fluid_particles.h"

namespace slamsph::test {

inline FluidParticles disordered_cloud(unsigned seed, int nx, int ny, double jitter_max) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-jitter_max, jitter_max), u(-1.0, 1.0);
  const double dx = 0.01;
  FluidParticles f;
  std::int64_t id = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      f.resize(f.size() + 1);
      const std::size_t k = f.size() - 1;
      f.x[k] = {(i + 0.5 + jitter(rng)) * dx, (j + 0.5 + jitter(rng)) * dx};
      f.v[k] = {0.5 * u(rng), 0.5 * u(rng)};
      f.rho[k] = 1000.0 * (1.0 + 0.01 * u(rng));
      f.p[k] = 2.0e4 * u(rng);
      f.m[k] = f.rho[k] * dx * dx * (1.0 + 0.1 * u(rng));
      f.id[k] = id++;
    }
  return f;
}

}  // namespace slamsph::test
