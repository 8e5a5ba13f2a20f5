// The four-lane Wendland pair loop (fluid/gsph_pair_band.h). This file alone is compiled with
// -mavx2 (CMakeLists.txt). So that no AVX2 code reaches the rest of the program through the
// linker's choice among copies of an inline function, it calls no inline function of a
// project or standard header — only the AVX intrinsics, which are always inlined — and keeps
// everything else in an anonymous namespace (the test avx2_object_defines_only_its_functions,
// tests/CMakeLists.txt, checks the object's symbols; tests/unit/test_fluid_pair_band.cpp the
// sums).
#include "fluid/gsph_pair_band.h"

#if defined(__AVX2__)
#include <immintrin.h>

namespace slamsph {

namespace {

using v4 = __m256d;  // GCC/Clang vector type: + − × / act lane-wise as the scalar IEEE ops
using v2 = __m128d;

inline v4 splat(double s) {
  return _mm256_set1_pd(s);
}

// (a0, a1, a2, a3) and (b0, b1, b2, b3) -> the pairs (a_l, b_l) of lane l.
struct Pairs {
  v2 l[4];
};
inline Pairs interleave(v4 a, v4 b) {
  const v4 lo = _mm256_unpacklo_pd(a, b);  // (a0, b0, a2, b2)
  const v4 hi = _mm256_unpackhi_pd(a, b);  // (a1, b1, a3, b3)
  return {{_mm256_castpd256_pd128(lo), _mm256_castpd256_pd128(hi), _mm256_extractf128_pd(lo, 1),
           _mm256_extractf128_pd(hi, 1)}};
}

// The (x, y) of four Vec2 -> the x lanes and the y lanes.
inline void gather(const Vec2* a, const std::uint32_t* j, v4& xs, v4& ys) {
  const v4 a02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&a[j[0]].x)),
                                      _mm_loadu_pd(&a[j[2]].x), 1);
  const v4 a13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&a[j[1]].x)),
                                      _mm_loadu_pd(&a[j[3]].x), 1);
  xs = _mm256_unpacklo_pd(a02, a13);
  ys = _mm256_unpackhi_pd(a02, a13);
}
inline v4 gather(const double* a, const std::uint32_t* j) {
  return _mm256_set_pd(a[j[3]], a[j[2]], a[j[1]], a[j[0]]);
}
inline double lane(v4 a, int l) {
  return a[l];
}

template <bool kViscous, bool kMomentum, bool kContinuity>
void band(const GsphBandData& d, std::uint32_t i_begin, std::uint32_t i_end) {
  const v4 zero = _mm256_setzero_pd();
  const v4 sign = splat(-0.0);
  const v4 lane_index = _mm256_set_pd(3.0, 2.0, 1.0, 0.0);
  const v4 support2 = splat(d.support2), c0 = splat(d.c0);
  for (std::uint32_t i = i_begin; i < i_end; ++i) {
    const double xi = d.x[i].x, yi = d.x[i].y, vxi = d.v[i].x, vyi = d.v[i].y;
    const double rhoi = d.rho[i], pi = d.p[i], inv_rhoi = d.inv_rho[i], Vi = d.V[i];
    v2 acc_i = _mm_setzero_pd();  // (x, y), the scalar loop's Vec2 acc_i
    double drho_i = 0.0;
    const std::uint32_t end_k = d.start[i + 1];
    for (std::uint32_t k = d.start[i]; k < end_k; k += 4) {
      const std::uint32_t left = end_k - k;
      std::uint32_t j[4];
      j[0] = d.index[k];
      for (std::uint32_t l = 1; l < 4; ++l) j[l] = l < left ? d.index[k + l] : j[0];
      v4 xj, yj;
      gather(d.x, j, xj, yj);
      const v4 dxx = xi - xj, dxy = yi - yj;
      const v4 r2 = dxx * dxx + dxy * dxy;
      // The scalar loop's test, skipped when r2 >= support2 or r2 == 0 (NaN is kept), and the
      // lanes past the end of the list.
      const v4 use =
          _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(r2, support2, _CMP_NGE_UQ),
                                      _mm256_cmp_pd(r2, zero, _CMP_NEQ_UQ)),
                        _mm256_cmp_pd(lane_index, splat(static_cast<double>(left)), _CMP_LT_OQ));
      if (_mm256_movemask_pd(use) == 0) continue;
      v4 vxj, vyj;
      gather(d.v, j, vxj, vyj);
      const v4 rhoj = gather(d.rho, j), Vj = gather(d.V, j), pj = gather(d.p, j);
      const v4 r = _mm256_sqrt_pd(r2), inv_r = 1.0 / r;
      // Kernel::dw_over_r_as<WendlandC2>: t = max(0, 1 − q/2); MAXPD(a, b) = a > b ? a : b,
      // as std::max(0.0, u) = 0 < u ? u : 0 for NaN and ±0 too.
      const v4 q = r * d.inv_h;
      const v4 t = _mm256_max_pd(1.0 - 0.5 * q, zero);
      const v4 dwr = d.w_factor * t * t * t;
      const v4 uL = -(vxi * dxx + vyi * dxy) * inv_r;
      const v4 uR = -(vxj * dxx + vyj * dxy) * inv_r;
      const v4 inv_sum = 1.0 / (rhoi + rhoj);
      const v4 du = uL - uR;
      // std::min(omega std::max(du, 0), c0): max(du, 0) = du < 0 ? 0 : du = MAXPD(0, du);
      // min(m, c0) = c0 < m ? c0 : m = MINPD(c0, m).
      const v4 beta = _mm256_min_pd(c0, d.omega * _mm256_max_pd(zero, du));
      const v4 dp_static = 0.5 * (rhoi + rhoj) * (d.g_static.x * dxx + d.g_static.y * dxy);
      const v4 us = (rhoi * uL + rhoj * uR + (pi - pj - dp_static) * d.inv_c0) * inv_sum;
      const v4 ps = (rhoj * pi + rhoi * pj + beta * rhoi * rhoj * du) * inv_sum;
      // Contributions, masked: subtracted from i as their negatives (exact) and from j.
      Pairs ni{}, nj{}, nvi{}, nvj{};
      v4 ci = zero, cj = zero;
      if constexpr (kContinuity) {
        const v4 dwr_r = dwr * r;
        ci = _mm256_and_pd(use, Vj * (uL - us) * dwr_r);
        cj = _mm256_and_pd(use, Vi * (us - uR) * dwr_r);
      }
      if constexpr (kMomentum) {
        const v4 fp = -2.0 * ps * dwr;
        const v4 fi = Vj * inv_rhoi * fp;
        const v4 inv_rhoj = gather(d.inv_rho, j);
        const v4 fj = Vi * inv_rhoj * fp;
        ni = interleave(_mm256_and_pd(use, _mm256_xor_pd(sign, fi * dxx)),
                        _mm256_and_pd(use, _mm256_xor_pd(sign, fi * dxy)));
        nj = interleave(_mm256_and_pd(use, fj * dxx), _mm256_and_pd(use, fj * dxy));
        if constexpr (kViscous) {
          const v4 coef = d.nu * (rhoi + rhoj) * dwr * r2 / (r2 + d.eta2);
          const v4 vijx = vxi - vxj, vijy = vyi - vyj;
          const v4 vci = coef * Vj * inv_rhoi;
          const v4 vcj = coef * Vi * inv_rhoj;
          nvi = interleave(_mm256_and_pd(use, _mm256_xor_pd(sign, vci * vijx)),
                           _mm256_and_pd(use, _mm256_xor_pd(sign, vci * vijy)));
          nvj = interleave(_mm256_and_pd(use, vcj * vijx), _mm256_and_pd(use, vcj * vijy));
        }
      }
      // Lane by lane, in list order: the scalar loop's sequence of additions.
      for (int l = 0; l < 4; ++l) {
        if constexpr (kContinuity) {
          drho_i -= lane(ci, l);
          d.drho[j[l]] -= lane(cj, l);
        }
        if constexpr (kMomentum) {
          double* const aj = &d.acc[j[l]].x;
          acc_i = _mm_sub_pd(acc_i, ni.l[l]);
          v2 a = _mm_sub_pd(_mm_loadu_pd(aj), nj.l[l]);
          if constexpr (kViscous) {
            acc_i = _mm_sub_pd(acc_i, nvi.l[l]);
            a = _mm_sub_pd(a, nvj.l[l]);
          }
          _mm_storeu_pd(aj, a);
        }
      }
    }
    if constexpr (kMomentum) {
      double* const ai = &d.acc[i].x;
      _mm_storeu_pd(ai, _mm_add_pd(_mm_loadu_pd(ai), acc_i));
    }
    if constexpr (kContinuity) d.drho[i] += drho_i;
  }
}

template <bool kViscous>
void dispatch_pass(const GsphBandData& d, std::uint32_t i_begin, std::uint32_t i_end) {
  switch (d.pass) {
    case RatePass::Both:
      return band<kViscous, true, true>(d, i_begin, i_end);
    case RatePass::Momentum:
      return band<kViscous, true, false>(d, i_begin, i_end);
    case RatePass::Continuity:
      return band<kViscous, false, true>(d, i_begin, i_end);
  }
}

}  // namespace

bool gsph_band_avx2_available() {
  return __builtin_cpu_supports("avx2");
}

void gsph_wendland_band_avx2(const GsphBandData& d, std::uint32_t i_begin, std::uint32_t i_end) {
  if (d.viscous)
    dispatch_pass<true>(d, i_begin, i_end);
  else
    dispatch_pass<false>(d, i_begin, i_end);
}

}  // namespace slamsph

#else  // not an x86-64 build with -mavx2: the scalar loop runs

namespace slamsph {

bool gsph_band_avx2_available() {
  return false;
}

void gsph_wendland_band_avx2(const GsphBandData&, std::uint32_t, std::uint32_t) {}

}  // namespace slamsph

#endif
