// Fluid–fluid GSPH rates, spec §2 / paper Eqs. 1–3, computed in one fused pass:
//   drho_i/dt = 2 rho_i sum_j (m_j/rho_j) (v_i - v*) . grad_i W_ij
//   dv_i/dt   = -2 sum_j m_j p*/(rho_i rho_j) grad_i W_ij + g  (+ Morris viscosity)
// Only v* . e_ij = U* enters the continuity term, because (v_i - v*) is contracted with
// grad_i W_ij, which is parallel to e_ij. The pass overwrites `a` and `drho`; contact
// terms (coupling/) are added afterwards. `pass` selects the sums (fluid_integrator_kind.h): the
// symplectic step computes the momentum and the continuity sums at different states; each
// of those passes writes only its own array (and zeroes it first). Each pair is evaluated once
// (core/cell_grid.h, BandedPairs) and applied to both particles; the bands make that race-free and
// keep the summation order, hence the results, independent of the thread count.
#pragma once
#include <cstddef>
#include <functional>

#include "core/cell_grid.h"
#include "core/kernel.h"
#include "core/parallel.h"
#include "fluid/fluid_integrator_kind.h"
#include "fluid/fluid_particles.h"

namespace slamsph {

struct GsphParams {
  double c0 = 0.0;                     // sound speed [m/s]
  double omega = 3.0;                  // low-dissipation limiter [-]
  double viscosity = 0.0;              // kinematic viscosity [m^2/s]; 0 = inviscid
  Vec2 gravity;                        // [m/s^2]
  bool hydrostatic_correction = true;  // static state rho g . r in U* (riemann_solver.h)
};

// Which pair loop: Auto takes, for the Wendland kernel, the eight-lane one
// (fluid/gsph_pair_band.h) on CPUs with AVX-512F, else the four-lane one on CPUs with AVX2,
// else the scalar one; Scalar always the scalar one (the reference the lanes are tested
// against, bit for bit); FourLanes / EightLanes that one where the CPU has it, else the
// scalar one. All give the same sums.
enum class PairLoop { Auto, Scalar, FourLanes, EightLanes };

// Work on particles the pass has finished: then(begin, end, slot) is called once for each
// band's particles [begin, end), slot = the band's index (0, once for every particle, when
// the lists do not cover the particles), right after their a and drho are final and when no
// task of the pass will read or write them again, so that it may write their v, rho and p
// (not x) and read their a and drho on bands still in the cache (app/fsi_stepper.cpp: the
// integrator's last sweep). It must touch only particles [begin, end); calls run in parallel.
using AfterFluidPass = std::function<void(std::size_t begin, std::size_t end, std::size_t slot)>;

void compute_gsph_fluid_rates(FluidParticles& f, const BandedPairs& pairs, const Kernel& kernel,
                              const GsphParams& prm, const Executor& exec,
                              RatePass pass = RatePass::Both, PairLoop loop = PairLoop::Auto,
                              const AfterFluidPass* then = nullptr);

}  // namespace slamsph
