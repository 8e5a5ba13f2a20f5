#include "fluid/gsph_fluid_rates.h"

#include <algorithm>
#include <cmath>

#include "fluid/gsph_pair_band.h"
#include "fluid/riemann_solver.h"

namespace slamsph {

namespace {

// The scalar pair loop over particles [i_begin, i_end) of a band: each pair once (j > i); the
// task of band b writes to bands b and b + 1 only. It is the reference of the lane loops
// (gsph_pair_band.h) and runs for the cubic spline and on CPUs without AVX2.
// solve_riemann() is written out with its divisions hoisted
// (tests/unit/test_fluid_momentum.cpp checks it against the plain formulas through the
// conservation and uniform-state tests; riemann_solver.h is the reference).
// Every constant and array pointer is copied into a local: read through
// GsphBandData, the compiler has to reload them (and redo the kernel's constant
// factor) after every store to acc[j] or drho[j], which may alias them as far as it knows.
// 1/rho_j comes from a per-particle array filled with V = m/rho (the same division, once per
// particle instead of once per pair), so the sums are bit-identical to the plain form.
template <bool kViscous, KernelType kType, RatePass kPass>
void scalar_band(const GsphBandData& d, const Kernel& kernel_in, std::uint32_t i_begin,
                 std::uint32_t i_end) {
  constexpr bool kMomentum = kPass != RatePass::Continuity;
  constexpr bool kContinuity = kPass != RatePass::Momentum;
  const Kernel kernel = kernel_in;
  const double support2 = d.support2, eta2 = d.eta2;
  const double c0 = d.c0, inv_c0 = d.inv_c0, omega = d.omega, nu = d.nu;
  const Vec2 g_static = d.g_static;
  const Vec2* const x = d.x;
  const Vec2* const v = d.v;
  const double* const rho = d.rho;
  const double* const inv_rho = d.inv_rho;
  const double* const p = d.p;
  const double* const V = d.V;
  Vec2* const acc = d.acc;
  double* const drho = d.drho;
  const std::uint32_t* const start = d.start;
  const std::uint32_t* const index = d.index;
  for (std::uint32_t i = i_begin; i < i_end; ++i) {
    const Vec2 xi = x[i], vi = v[i];
    const double rhoi = rho[i], pi = p[i], inv_rhoi = inv_rho[i], Vi = V[i];
    Vec2 acc_i;
    double drho_i = 0.0;
    const std::uint32_t end_k = start[i + 1];
    for (std::uint32_t k = start[i]; k < end_k; ++k) {
      const std::uint32_t j = index[k];
      const Vec2 dx = xi - x[j];
      const double r2 = norm2(dx);
      if (r2 >= support2 || r2 == 0.0) continue;  // the lists carry a skin
      const double r = std::sqrt(r2), inv_r = 1.0 / r;
      const double dwr = kernel.dw_over_r_as<kType>(r);  // grad_i W_ij = dwr * dx
      const double rhoj = rho[j], Vj = V[j];
      // Riemann problem along e_ij = -dx / r (spec §2; riemann_solver.h). Seen from j
      // (left and right swapped, axis reversed) U* changes sign and p* is the same.
      const double uL = -dot(vi, dx) * inv_r, uR = -dot(v[j], dx) * inv_r;
      const double inv_sum = 1.0 / (rhoi + rhoj);
      const double du = uL - uR;
      const double beta = std::min(omega * std::max(du, 0.0), c0);
      const double dp_static = 0.5 * (rhoi + rhoj) * dot(g_static, dx);
      const double us = (rhoi * uL + rhoj * uR + (pi - p[j] - dp_static) * inv_c0) * inv_sum;
      const double ps = (rhoj * pi + rhoi * p[j] + beta * rhoi * rhoj * du) * inv_sum;
      // (v_i - v*) . grad_i W = (U_L - U*) e . (dwr dx) = -(U_L - U*) dwr r, and for j
      // (v_j - v*) . grad_j W = -(U* - U_R) dwr r.
      if constexpr (kContinuity) {
        const double dwr_r = dwr * r;
        drho_i -= Vj * (uL - us) * dwr_r;
        drho[j] -= Vi * (us - uR) * dwr_r;
      }
      // Pressure forces -2 V_j p* / rho_i grad_i W and its mirror on j (equal and opposite
      // momentum, m_i V_j / rho_i = V_i V_j = m_j V_i / rho_j).
      if constexpr (kMomentum) {
        const double fp = -2.0 * ps * dwr;
        acc_i += (Vj * inv_rhoi * fp) * dx;
        acc[j] -= (Vi * inv_rho[j] * fp) * dx;
      }
      if constexpr (kViscous && kMomentum) {
        // Morris et al. 1997: sum m_j (mu_i + mu_j)/(rho_i rho_j) (r.gradW)/(r^2+eta^2) v_ij
        const double coef = nu * (rhoi + rhoj) * dwr * r2 / (r2 + eta2);
        const Vec2 vij = vi - v[j];
        acc_i += (coef * Vj * inv_rhoi) * vij;
        acc[j] -= (coef * Vi * inv_rho[j]) * vij;
      }
    }
    if constexpr (kMomentum) acc[i] += acc_i;
    if constexpr (kContinuity) drho[i] += drho_i;
  }
}

template <bool kViscous, KernelType kType, RatePass kPass>
void rates_impl(FluidParticles& f, const BandedPairs& pairs, const Kernel& kernel_in,
                const GsphParams& prm, const Executor& exec, PairLoop loop,
                const AfterFluidPass* then) {
  constexpr bool kMomentum = kPass != RatePass::Continuity;
  constexpr bool kContinuity = kPass != RatePass::Momentum;
  // The pass's arrays and constants, for either loop.
  const GsphBandData d{f.x.data(),
                       f.v.data(),
                       f.rho.data(),
                       f.inv_rho.data(),
                       f.p.data(),
                       f.volume.data(),
                       f.a.data(),
                       f.drho.data(),
                       pairs.half.start.data(),
                       pairs.half.index.data(),
                       kernel_in.inv_h(),
                       kernel_in.wendland_dw_over_r_factor(),
                       kernel_in.support() * kernel_in.support(),
                       kMorrisEta2 * kernel_in.h() * kernel_in.h(),
                       prm.c0,
                       1.0 / prm.c0,
                       prm.omega,
                       prm.viscosity,
                       prm.hydrostatic_correction ? prm.gravity : Vec2{},  // riemann_solver.h
                       kViscous,
                       kPass};
  // The lane loops (gsph_pair_band.h) for the Wendland kernel where the CPU has them: the
  // same sums, bit for bit (docs/validation.md §6, Sessions 14 and 15).
  const bool wendland = kType == KernelType::WendlandC2;
  const bool eight = wendland && (loop == PairLoop::Auto || loop == PairLoop::EightLanes) &&
                     gsph_band_avx512_available();
  const bool four = wendland && !eight && (loop == PairLoop::Auto || loop == PairLoop::FourLanes) &&
                    gsph_band_avx2_available();
  const auto pair_loop = [&d, &kernel_in, eight, four](std::uint32_t i_begin, std::uint32_t i_end) {
    if (eight)
      gsph_wendland_band_avx512(d, i_begin, i_end);
    else if (four)
      gsph_wendland_band_avx2(d, i_begin, i_end);
    else
      scalar_band<kViscous, kType, kPass>(d, kernel_in, i_begin, i_end);
  };
  // Before the sums: V = m/rho, 1/rho and the zeroed sums; after them: drho's factor 2 rho_i
  // and gravity (Eqs. 1-2).
  const auto prepare = [&f](std::size_t i) {
    f.volume[i] = f.m[i] / f.rho[i];
    f.inv_rho[i] = 1.0 / f.rho[i];
    if constexpr (kMomentum) f.a[i] = Vec2{};
    if constexpr (kContinuity) f.drho[i] = 0.0;  // sum_j V_j (v_i - v*) . grad W until the end
  };
  const Vec2 g = prm.gravity;
  const auto finish = [&f, g](std::size_t i) {
    if constexpr (kContinuity) f.drho[i] *= 2.0 * f.rho[i];
    if constexpr (kMomentum) f.a[i] += g;
  };
  const std::size_t bands = pairs.bands();
  if (bands == 0 || pairs.band_start.back() != f.size()) {
    // Lists that do not cover the particles (none built yet): three sweeps.
    exec.for_each(f.size(), prepare);
    exec.for_alternating(bands, [&](std::size_t band) {
      pair_loop(pairs.band_start[band], pairs.band_start[band + 1]);
    });
    exec.for_each(f.size(), finish);
    if (then) (*then)(0, f.size(), 0);
    return;
  }
  // One sweep: the task of band b reads and writes bands b and b + 1 only, the even bands run
  // first, then the odd ones (Executor::for_alternating). So an even task prepares its two
  // bands before its sums (nothing has touched them yet), and an odd task finishes its two
  // bands after its sums (no task of either band is left to run); band 0, written by task 0
  // only, is finished by it. The per-particle work then runs on bands just loaded into the
  // cache, and the result is the three-sweep one, bit for bit.
  const auto rows = [&pairs, bands](std::size_t band, const auto& op) {
    if (band >= bands) return;
    for (std::size_t i = pairs.band_start[band]; i < pairs.band_start[band + 1]; ++i) op(i);
  };
  // A finished band is handed on (AfterFluidPass): by the same argument no task reads it again.
  const auto finish_rows = [&](std::size_t band) {
    if (band >= bands) return;
    rows(band, finish);
    if (then) (*then)(pairs.band_start[band], pairs.band_start[band + 1], band);
  };
  exec.for_alternating(bands, [&](std::size_t band) {
    const bool odd = band % 2 == 1;
    if (!odd) {
      rows(band, prepare);
      rows(band + 1, prepare);
    }
    pair_loop(pairs.band_start[band], pairs.band_start[band + 1]);
    if (odd) {
      finish_rows(band);
      finish_rows(band + 1);
    } else if (band == 0) {
      finish_rows(band);
    }
  });
}

template <bool kViscous, RatePass kPass>
void dispatch_kernel(FluidParticles& f, const BandedPairs& ff, const Kernel& kernel,
                     const GsphParams& prm, const Executor& exec, PairLoop loop,
                     const AfterFluidPass* then) {
  if (kernel.type() == KernelType::WendlandC2)
    rates_impl<kViscous, KernelType::WendlandC2, kPass>(f, ff, kernel, prm, exec, loop, then);
  else
    rates_impl<kViscous, KernelType::CubicSpline, kPass>(f, ff, kernel, prm, exec, loop, then);
}

template <RatePass kPass>
void dispatch_viscous(FluidParticles& f, const BandedPairs& ff, const Kernel& kernel,
                      const GsphParams& prm, const Executor& exec, PairLoop loop,
                      const AfterFluidPass* then) {
  if (prm.viscosity > 0.0)
    dispatch_kernel<true, kPass>(f, ff, kernel, prm, exec, loop, then);
  else
    dispatch_kernel<false, kPass>(f, ff, kernel, prm, exec, loop, then);
}

}  // namespace

void compute_gsph_fluid_rates(FluidParticles& f, const BandedPairs& ff, const Kernel& kernel,
                              const GsphParams& prm, const Executor& exec, RatePass pass,
                              PairLoop loop, const AfterFluidPass* then) {
  switch (pass) {
    case RatePass::Both:
      return dispatch_viscous<RatePass::Both>(f, ff, kernel, prm, exec, loop, then);
    case RatePass::Momentum:
      return dispatch_viscous<RatePass::Momentum>(f, ff, kernel, prm, exec, loop, then);
    case RatePass::Continuity:
      return dispatch_viscous<RatePass::Continuity>(f, ff, kernel, prm, exec, loop, then);
  }
}

}  // namespace slamsph
