#include "coupling/virtual_pressure.h"

#include <cmath>

namespace slamsph {

void compute_virtual_state(ContactParticles& c, const FluidParticles& f, const NeighbourList& cf,
                           const Kernel& kernel, const TaitEos& eos, Vec2 gravity,
                           const Executor& exec, VirtualSubset subset,
                           const std::vector<std::uint8_t>* fixed) {
  const auto one = [&](std::size_t s) {
    double sum_w = 0.0, sum_pw = 0.0;
    Vec2 sum_rrw, sum_vw;
    const Vec2 xs = c.x[s];
    for (std::uint32_t k = cf.start[s]; k < cf.start[s + 1]; ++k) {
      const std::uint32_t j = cf.index[k];
      if (!c.faces(s, f.x[j])) continue;
      const Vec2 r = xs - f.x[j];
      const double w = kernel.w(std::sqrt(norm2(r)));
      if (w <= 0.0) continue;
      sum_w += w;
      sum_pw += f.p[j] * w;
      sum_rrw += (f.rho[j] * w) * r;
      sum_vw += w * f.v[j];
    }
    if (sum_w <= 0.0) {
      c.wetted[s] = 0;
      c.p[s] = 0.0;
      c.rho[s] = eos.rho0;
      c.v_noslip[s] = c.v[s];
      return;
    }
    c.wetted[s] = 1;
    c.p[s] = (sum_pw + dot(gravity - c.a[s], sum_rrw)) / sum_w;
    // Keep the inverse EOS defined under strong suction (p > -stiffness).
    const double p_min = -0.99 * eos.stiffness();
    c.rho[s] = eos.density(c.p[s] > p_min ? c.p[s] : p_min);
    c.v_noslip[s] = 2.0 * c.v[s] - sum_vw / sum_w;
  };
  // Split by pairs (Executor::for_each_weighted): the wetted stretch of a surface is short. A
  // pair (a kernel value) costs about 2 contact particles without pairs (which still write
  // their dry state). One loop per subset: each learns its own split.
  const std::uint32_t* start = cf.start.data();
  if (subset == VirtualSubset::All || (!fixed && subset == VirtualSubset::Moving)) {
    exec.for_each_weighted(
        c.size(), start, [&](std::size_t s) { one(s); }, 2);
  } else if (!fixed) {
    return;  // no particle is fixed
  } else if (subset == VirtualSubset::Fixed) {
    exec.for_each_weighted(
        c.size(), start,
        [&](std::size_t s) {
          if ((*fixed)[s]) one(s);
        },
        2);
  } else {
    exec.for_each_weighted(
        c.size(), start,
        [&](std::size_t s) {
          if (!(*fixed)[s]) one(s);
        },
        2);
  }
}

}  // namespace slamsph
