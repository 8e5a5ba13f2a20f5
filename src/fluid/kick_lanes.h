// The kick-drift-kick step's second half kick (app/fsi_stepper.cpp, the last sweep), and its
// first half kick with the drift (KickLaneData::dt), in eight AVX-512F lanes, for the Tait
// exponent 7: per particle
//   v = v_half + dt/2 a,  rho = rho_half + dt/2 drho,  p = Tait(rho)  (fluid/tait_eos.h),
// and what the sweep finds on its way: max |v|², max |a|² and whether a particle is not finite
// or outside the domain (FsiStepper::check_state). The scalar sweep divides rho / rho0 one
// particle at a time (perf, 320 000 particles: the sweep was compute-bound, as long as the
// pass's band tasks took to run it as the separate sweep did; docs/validation.md §6
// "Throughput", session 18); the lanes divide eight at a time. Every lane operation is the
// scalar code's in its order, no fused multiply-add (-ffp-contract=off): the same bits
// (FusedSweeps.KickInThePassIsTheSeparateSweep, tests/unit/test_app_fused_sweeps.cpp).
// fluid/kick_lanes_avx512.cpp is the only file built with -mavx512f for it; chosen at run time.
#pragma once
#include <cstdint>

#include "core/box.h"
#include "core/vec.h"

namespace slamsph {

struct KickLaneData {
  Vec2* v_half;
  double* rho_half;
  const Vec2* a;
  const double* drho;
  Vec2* x;
  Vec2* v;
  double* rho;
  double* p;
  double hdt;        // dt/2
  double rho0;       // TaitEos::rho0
  double stiffness;  // TaitEos::stiffness(), as the scalar code computes it
  Box domain;
  // The step's drift (FsiStepper::step, before the rates; kick_lanes_avx512 with drift):
  //   v_half = v + dt/2 a,  rho_half = rho + dt/2 drho,  x += dt v_half,
  //   v = v_half + dt/2 a,  rho = rho_half + dt/2 drho,  p = Tait(rho),
  // finding max |x - x0|² (the lists' displacement since their build) instead.
  double dt = 0.0;
  const Vec2* x0 = nullptr;
};

// True when this build has the lanes and the CPU runs AVX-512F.
bool kick_lanes_avx512_available();

// Particles [begin, begin + 8 k) for the largest k that fits in [begin, end); returns the
// first particle not done (the caller does the rest). The kick raises maxima[0..2] (max |v|²,
// max |a|², bad as 0/1), the drift maxima[0] (max |x - x0|²) by the particles done, with the
// scalar sweeps' comparison (q > m: NaN is never taken). Only call it when
// kick_lanes_avx512_available().
std::uint32_t kick_lanes_avx512(const KickLaneData& d, bool drift, std::uint32_t begin,
                                std::uint32_t end, double* maxima);

}  // namespace slamsph
