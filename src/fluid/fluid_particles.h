// Structure-of-arrays storage of the water particles (style.md §4).
#pragma once
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace slamsph {

struct FluidParticles {
  std::vector<Vec2> x;           // position [m]
  std::vector<Vec2> v;           // velocity [m/s]
  std::vector<Vec2> a;           // acceleration [m/s^2]
  std::vector<double> rho;       // density [kg/m^3]
  std::vector<double> drho;      // density rate [kg/m^3/s]
  std::vector<double> p;         // pressure [Pa]
  std::vector<double> m;         // mass per unit length [kg/m]
  std::vector<std::int64_t> id;  // stable particle id (survives reordering)
  // Kick–drift–kick integrator state: velocity and density after the first half kick.
  std::vector<Vec2> v_half;
  std::vector<double> rho_half;
  std::vector<std::uint8_t> crossed;  // 1 once the particle was found inside a solid
  std::vector<double> volume;         // m/rho, refreshed by each rate pass (scratch)

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    x.resize(n);
    v.resize(n);
    a.resize(n);
    rho.resize(n);
    drho.resize(n);
    p.resize(n);
    m.resize(n);
    id.resize(n);
    v_half.resize(n);
    rho_half.resize(n);
    crossed.resize(n);
    volume.resize(n);
  }
  // Reorders every field: new[k] = old[perm[k]] (used to keep memory in cell order).
  template <class Index>
  void permute(const std::vector<Index>& perm) {
    auto apply = [&](auto& f) {
      auto old = f;
      for (std::size_t k = 0; k < perm.size(); ++k) f[k] = old[perm[k]];
    };
    apply(x);
    apply(v);
    apply(a);
    apply(rho);
    apply(drho);
    apply(p);
    apply(m);
    apply(id);
    apply(v_half);
    apply(rho_half);
    apply(crossed);
  }
};

}  // namespace slamsph
