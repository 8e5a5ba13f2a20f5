// The fluid pair loop of one band (fluid/gsph_fluid_rates.cpp) in vector lanes, for the
// Wendland C2 kernel on x86-64 CPUs: eight lanes with AVX-512F (fluid/gsph_pair_band_avx512.cpp,
// the only file built with -mavx512f; its own header comment says how it packs the pairs),
// else four lanes with AVX2 (fluid/gsph_pair_band_avx2.cpp, the only file built with -mavx2);
// chosen at run time, so the binary still runs on any x86-64.
//
// Four lanes: four listed partners j of particle i go through the distance, the square root, the
// divisions, the kernel and the Riemann solution at once; then each lane's contributions are
// added to i and to its j one lane after the other, in list order. Every lane operation is the
// scalar loop's operation in the same order (no reassociation; no fused multiply-add, which
// -mavx2 does not enable), so the sums are bit-identical to the scalar loop's
// (GsphPairBand.FourLanesAreBitIdenticalToTheScalarLoop) and results do not depend on the
// CPU. Partners beyond the support or on top of i are computed and masked to +0 in every
// contribution, which is subtracted (x − (+0) = x for every x, −0 included, where x + (+0)
// would turn −0 into +0), as the scalar loop skips them.
#pragma once
#include <cstdint>

#include "core/vec.h"
#include "fluid/fluid_integrator_kind.h"

namespace slamsph {

// The arrays and constants of one fluid pass (gsph_fluid_rates.cpp builds it once; the
// scalar loop reads it too).
struct GsphBandData {
  const Vec2* x;
  const Vec2* v;
  const double* rho;
  const double* inv_rho;
  const double* p;
  const double* V;  // m/rho
  Vec2* acc;
  double* drho;
  const std::uint32_t* start;  // pairs of i: index[start[i] .. start[i + 1])
  const std::uint32_t* index;
  double inv_h, w_factor;  // Kernel::inv_h(), Kernel::wendland_dw_over_r_factor()
  double support2, eta2, c0, inv_c0, omega, nu;
  Vec2 g_static;
  bool viscous;
  RatePass pass;
};

// True when this build has the four-lane loop and the CPU runs AVX2.
bool gsph_band_avx2_available();

// Particles [i_begin, i_end) of a band: the scalar loop of gsph_fluid_rates.cpp for the
// Wendland kernel. Only call it when gsph_band_avx2_available().
void gsph_wendland_band_avx2(const GsphBandData& d, std::uint32_t i_begin, std::uint32_t i_end);

// The same in eight lanes (fluid/gsph_pair_band_avx512.cpp, built with -mavx512f), computing
// only the partners inside the support, packed in list order: the same sums, bit for bit
// (GsphPairBand.EightLanesAreBitIdenticalToTheScalarLoop). Only call it when
// gsph_band_avx512_available() (a list longer than its chunk goes to the four-lane loop).
bool gsph_band_avx512_available();
void gsph_wendland_band_avx512(const GsphBandData& d, std::uint32_t i_begin, std::uint32_t i_end);

}  // namespace slamsph
