#include "fluid/gsph_fluid_rates.h"

#include <cmath>

#include "fluid/riemann_solver.h"

namespace slamsph {

namespace {

template <bool kViscous>
void rates_impl(FluidParticles& f, const NeighbourList& ff, const Kernel& kernel,
                const GsphParams& prm, const Executor& exec) {
  const double support2 = kernel.support() * kernel.support();
  const double eta2 = 0.01 * kernel.h() * kernel.h();  // Morris regulariser
  const Vec2* x = f.x.data();
  const Vec2* v = f.v.data();
  const double* rho = f.rho.data();
  const double* p = f.p.data();
  const double* m = f.m.data();
  exec.for_each(f.size(), [&](std::size_t i) {
    const Vec2 xi = x[i], vi = v[i];
    const double rhoi = rho[i], pi = p[i];
    Vec2 acc;
    double drho = 0.0;
    for (std::uint32_t k = ff.start[i]; k < ff.start[i + 1]; ++k) {
      const std::uint32_t j = ff.index[k];
      const Vec2 dx = xi - x[j];
      const double r2 = norm2(dx);
      if (r2 >= support2 || r2 == 0.0) continue;
      const double r = std::sqrt(r2);
      const double dwr = kernel.dw_over_r(r);  // grad_i W_ij = dwr * dx
      const Vec2 e = dx * (-1.0 / r);          // from i to j
      const double rhoj = rho[j];
      const RiemannState L{rhoi, dot(vi, e), pi};
      const RiemannState R{rhoj, dot(v[j], e), p[j]};
      const double dp_static = 0.5 * (rhoi + rhoj) * dot(prm.gravity, dx);
      const RiemannStar s = solve_riemann(L, R, prm.c0, prm.omega, dp_static);
      const double vj_over = m[j] / rhoj;  // V_j
      // (v_i - v*) . grad W = (U_L - U*) e . (dwr dx) = -(U_L - U*) dwr r
      drho += vj_over * (L.u - s.u) * (-dwr * r);
      acc += (-2.0 * m[j] * s.p / (rhoi * rhoj) * dwr) * dx;
      if constexpr (kViscous) {
        // Morris et al. 1997: sum m_j (mu_i + mu_j)/(rho_i rho_j) (r.gradW)/(r^2+eta^2) v_ij
        const double coef = m[j] * prm.viscosity * (rhoi + rhoj) / (rhoi * rhoj) * dwr * r2 /
                            (r2 + eta2);
        acc += coef * (vi - v[j]);
      }
    }
    f.drho[i] = 2.0 * rhoi * drho;
    f.a[i] = acc + prm.gravity;
  });
}

}  // namespace

void compute_gsph_fluid_rates(FluidParticles& f, const NeighbourList& ff, const Kernel& kernel,
                              const GsphParams& prm, const Executor& exec) {
  if (prm.viscosity > 0.0)
    rates_impl<true>(f, ff, kernel, prm, exec);
  else
    rates_impl<false>(f, ff, kernel, prm, exec);
}

}  // namespace slamsph
