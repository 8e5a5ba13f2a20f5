// The SVK law of the sub-step's pass 1 in eight lanes (solid/substep_law_lanes.h). Built with
// -mavx512f -ffp-contract=off (CMakeLists.txt); it defines nothing but the function of the
// header. The per-particle rows (F, P, V0 P: Mat2 and SubstepParticleMats) are read and
// written by plain loops over the block's lanes, the arithmetic by component in lanes.
#include "solid/substep_law_lanes.h"

#if defined(__AVX512F__)
#include <immintrin.h>

namespace slamsph {

void substep_lanes_avx512_svk(const SubstepSvkLaneData& d, std::size_t base, std::size_t i0,
                              std::size_t i1, const SubstepLane1Sums& s) {
  const __m512d half = _mm512_set1_pd(0.5), one = _mm512_set1_pd(1.0), zero = _mm512_setzero_pd();
  // svk_pk2: 2.0 * p.mu * E is (2 μ) E.
  const __m512d two_mu = _mm512_set1_pd(2.0 * d.mu), lambda = _mm512_set1_pd(d.lambda);
  for (std::size_t b8 = base + ((i0 - base) & ~std::size_t{7}); b8 < i1; b8 += 8) {
    const std::size_t lo = b8 > i0 ? b8 : i0, hi = b8 + 8 < i1 ? b8 + 8 : i1;
    const std::size_t o = b8 - base;
    // P_old and the per-particle constants by component (lanes outside [lo, hi) stay 0).
    alignas(64) double po[4][8] = {}, v0[8] = {}, r0[8] = {};
    for (std::size_t i = lo; i < hi; ++i) {
      for (int c = 0; c < 4; ++c) po[c][i - b8] = d.P[4 * i + c];
      v0[i - b8] = d.V0[i];
      r0[i - b8] = d.rho0[i];
    }
    // F and Ḟ (xx, xy, yx, yy) from pass 1's lanes (its lanes of [lo, hi)).
    const __mmask8 m = static_cast<__mmask8>(((1u << (hi - b8)) - 1u) & ~((1u << (lo - b8)) - 1u));
    const __m512d Fxx = _mm512_maskz_loadu_pd(m, s.F[0] + o),
                  Fxy = _mm512_maskz_loadu_pd(m, s.F[1] + o),
                  Fyx = _mm512_maskz_loadu_pd(m, s.F[2] + o),
                  Fyy = _mm512_maskz_loadu_pd(m, s.F[3] + o);
    // green_lagrange: E = Fᵀ F (Mat2 product with transpose(F) = (xx, yx, xy, yy)), E −= I,
    // E *= ½.
    __m512d Exx = _mm512_add_pd(_mm512_mul_pd(Fxx, Fxx), _mm512_mul_pd(Fyx, Fyx));
    __m512d Exy = _mm512_add_pd(_mm512_mul_pd(Fxx, Fxy), _mm512_mul_pd(Fyx, Fyy));
    __m512d Eyx = _mm512_add_pd(_mm512_mul_pd(Fxy, Fxx), _mm512_mul_pd(Fyy, Fyx));
    __m512d Eyy = _mm512_add_pd(_mm512_mul_pd(Fxy, Fxy), _mm512_mul_pd(Fyy, Fyy));
    Exx = _mm512_mul_pd(_mm512_sub_pd(Exx, one), half);
    Exy = _mm512_mul_pd(_mm512_sub_pd(Exy, zero), half);
    Eyx = _mm512_mul_pd(_mm512_sub_pd(Eyx, zero), half);
    Eyy = _mm512_mul_pd(_mm512_sub_pd(Eyy, one), half);
    // svk_pk2: S = (2 μ) E, then λ tr E on the diagonal.
    const __m512d l = _mm512_mul_pd(lambda, _mm512_add_pd(Exx, Eyy));
    const __m512d Sxx = _mm512_add_pd(_mm512_mul_pd(Exx, two_mu), l);
    const __m512d Sxy = _mm512_mul_pd(Exy, two_mu);
    const __m512d Syx = _mm512_mul_pd(Eyx, two_mu);
    const __m512d Syy = _mm512_add_pd(_mm512_mul_pd(Eyy, two_mu), l);
    // svk_pk1: P = F S.
    const __m512d Pxx = _mm512_add_pd(_mm512_mul_pd(Fxx, Sxx), _mm512_mul_pd(Fxy, Syx));
    const __m512d Pxy = _mm512_add_pd(_mm512_mul_pd(Fxx, Sxy), _mm512_mul_pd(Fxy, Syy));
    const __m512d Pyx = _mm512_add_pd(_mm512_mul_pd(Fyx, Sxx), _mm512_mul_pd(Fyy, Syx));
    const __m512d Pyy = _mm512_add_pd(_mm512_mul_pd(Fyx, Sxy), _mm512_mul_pd(Fyy, Syy));
    // ddot(0.5 * (P_old + P), Ḟ) / ρ0: the sum, times ½, the four products added in order.
    const __m512d Mxx = _mm512_mul_pd(_mm512_add_pd(_mm512_load_pd(po[0]), Pxx), half);
    const __m512d Mxy = _mm512_mul_pd(_mm512_add_pd(_mm512_load_pd(po[1]), Pxy), half);
    const __m512d Myx = _mm512_mul_pd(_mm512_add_pd(_mm512_load_pd(po[2]), Pyx), half);
    const __m512d Myy = _mm512_mul_pd(_mm512_add_pd(_mm512_load_pd(po[3]), Pyy), half);
    __m512d sp = _mm512_mul_pd(Mxx, _mm512_maskz_loadu_pd(m, s.Fd[0] + o));
    sp = _mm512_add_pd(sp, _mm512_mul_pd(Mxy, _mm512_maskz_loadu_pd(m, s.Fd[1] + o)));
    sp = _mm512_add_pd(sp, _mm512_mul_pd(Myx, _mm512_maskz_loadu_pd(m, s.Fd[2] + o)));
    sp = _mm512_add_pd(sp, _mm512_mul_pd(Myy, _mm512_maskz_loadu_pd(m, s.Fd[3] + o)));
    // Lanes outside [lo, hi) divide 0 by 0 and are not stored.
    sp = _mm512_div_pd(sp, _mm512_load_pd(r0));
    // V0 P (Mat2 times a scalar: each component times V0).
    const __m512d V = _mm512_load_pd(v0);
    alignas(64) double f[4][8], p[4][8], vp[4][8], pw[8];
    _mm512_store_pd(f[0], Fxx);
    _mm512_store_pd(f[1], Fxy);
    _mm512_store_pd(f[2], Fyx);
    _mm512_store_pd(f[3], Fyy);
    _mm512_store_pd(p[0], Pxx);
    _mm512_store_pd(p[1], Pxy);
    _mm512_store_pd(p[2], Pyx);
    _mm512_store_pd(p[3], Pyy);
    _mm512_store_pd(vp[0], _mm512_mul_pd(Pxx, V));
    _mm512_store_pd(vp[1], _mm512_mul_pd(Pxy, V));
    _mm512_store_pd(vp[2], _mm512_mul_pd(Pyx, V));
    _mm512_store_pd(vp[3], _mm512_mul_pd(Pyy, V));
    _mm512_store_pd(pw, sp);
    for (std::size_t i = lo; i < hi; ++i) {
      const std::size_t k = i - b8;
      for (int c = 0; c < 4; ++c) {
        d.F[4 * i + c] = f[c][k];
        d.P[4 * i + c] = p[c][k];
      }
      d.stress_power[i] = pw[k];
      // SubstepParticleMats: vp_c0 = (xx, yx), vp_c1 = (xy, yy).
      double* const mi = d.mats + 8 * i;
      mi[0] = vp[0][k];
      mi[1] = vp[2][k];
      mi[2] = vp[1][k];
      mi[3] = vp[3][k];
    }
  }
}

}  // namespace slamsph

#else  // a build without AVX-512F for this file: the scalar law runs

namespace slamsph {

void substep_lanes_avx512_svk(const SubstepSvkLaneData&, std::size_t, std::size_t, std::size_t,
                              const SubstepLane1Sums&) {}

}  // namespace slamsph

#endif
