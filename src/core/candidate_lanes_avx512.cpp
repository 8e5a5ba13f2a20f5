// The lists' distance test in eight lanes (core/candidate_lanes.h). This file alone is compiled
// with -mavx512f -ffp-contract=off (CMakeLists.txt), under the rule of
// fluid/gsph_pair_band_avx512.cpp: it calls no inline function of a project or standard header,
// only the AVX-512 intrinsics and GCC builtins (the test
// candidate_avx512_object_defines_only_its_functions checks its symbols).
#include "core/candidate_lanes.h"

#if defined(__AVX512F__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"  // as in gsph_pair_band_avx512.cpp
#include <immintrin.h>

namespace slamsph {

bool candidate_lanes_avx512_available() {
  return __builtin_cpu_supports("avx512f");
}

std::uint32_t* candidates_within_avx512(const Vec2* pts, std::uint32_t b, std::uint32_t e, Vec2 q,
                                        double r2, std::uint32_t* dst) {
  const __m512d qx = _mm512_set1_pd(q.x), qy = _mm512_set1_pd(q.y), lim = _mm512_set1_pd(r2);
  const __m512i even = _mm512_set_epi64(14, 12, 10, 8, 6, 4, 2, 0);
  const __m512i odd = _mm512_set_epi64(15, 13, 11, 9, 7, 5, 3, 1);
  const __m512i step = _mm512_set1_epi32(8);
  __m512i j = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(b)),
                               _mm512_set_epi32(0, 0, 0, 0, 0, 0, 0, 0, 7, 6, 5, 4, 3, 2, 1, 0));
  std::uint32_t k = b;
  for (; k + 8 <= e; k += 8) {
    const double* const p = &pts[k].x;
    const __m512d lo = _mm512_loadu_pd(p), hi = _mm512_loadu_pd(p + 8);
    const __m512d dx = _mm512_sub_pd(qx, _mm512_permutex2var_pd(lo, even, hi));
    const __m512d dy = _mm512_sub_pd(qy, _mm512_permutex2var_pd(lo, odd, hi));
    const __m512d d2 = _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
    const __mmask8 in = _mm512_cmp_pd_mask(d2, lim, _CMP_LT_OQ);
    // Compressed in a register and stored whole (a compressing store to memory is slow on
    // this AMD CPU, fluid/gsph_pair_band_avx512.cpp): the eight slots lie within the eight
    // candidates just tested, so never past what dst may hold.
    const __m512i packed = _mm512_maskz_compress_epi32(static_cast<__mmask16>(in), j);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst), _mm512_castsi512_si256(packed));
    dst += __builtin_popcount(static_cast<unsigned>(in));
    j = _mm512_add_epi32(j, step);
  }
  for (; k < e; ++k) {  // the tail as the scalar test
    const double dx = q.x - pts[k].x, dy = q.y - pts[k].y;
    if (dx * dx + dy * dy < r2) *dst++ = k;
  }
  return dst;
}

}  // namespace slamsph

#else  // not an x86-64 build with -mavx512f: the scalar test runs

namespace slamsph {

bool candidate_lanes_avx512_available() {
  return false;
}

std::uint32_t* candidates_within_avx512(const Vec2*, std::uint32_t, std::uint32_t, Vec2, double,
                                        std::uint32_t* dst) {
  return dst;
}

}  // namespace slamsph

#endif
