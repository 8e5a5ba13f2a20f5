// The eight-lane Wendland pair loop (fluid/gsph_pair_band.h). This file alone is compiled with
// -mavx512f (CMakeLists.txt), under the same rule as gsph_pair_band_avx2.cpp: it calls no
// inline function of a project or standard header — only the AVX-512 intrinsics and GCC
// builtins, which are always inlined — and keeps everything else in an anonymous namespace
// (the test avx512_object_defines_only_its_functions, tests/CMakeLists.txt, checks the
// object's symbols; tests/unit/test_fluid_pair_band.cpp the sums).
//
// The four-lane loop computes every listed partner of one particle, masks those beyond the
// support (a third of the list: the lists carry a skin) and pads the last group of each list;
// each particle's work is one long chain (list → positions → physics → sums). This one runs a
// chunk of particles in three sweeps over a buffer on the stack:
//   1 pack: eight listed partners at a time, r² from the positions, and the partners inside
//     the support appended, in list order, with dx and the particle's own values (vcompress);
//   2 physics: eight packed pairs at a time, whatever particle they belong to (no padding but
//     at the chunk's end), each pair's contributions stored;
//   3 sums: the scalar loop's additions, pair by pair in list order, particle by particle.
// Sweeps 1 and 2 read only positions, velocities and densities, sweep 3 alone writes the sums,
// so every sum receives the scalar loop's operands in the scalar loop's order: the same bits.
#include "fluid/gsph_pair_band.h"

#if defined(__AVX512F__)
// GCC 12's AVX-512 headers start the result of a zero-masked intrinsic from an undefined
// vector (`__Y = __Y`), which -Wmaybe-uninitialized reports as a read of an uninitialised value.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>

namespace slamsph {

namespace {

using v8 = __m512d;  // GCC/Clang vector type: + − × / act lane-wise as the scalar IEEE ops
using v2 = __m128d;

inline v8 splat(double s) {
  return _mm512_set1_pd(s);
}

// Packed pairs per chunk: its buffers (21 KB) stay in the L1 cache (128 ran the 320 000-particle
// pass 5-10 % faster than 512 or 1024 in bench_kernels). A particle with a longer list (none in
// practice: ~22 listed partners per particle) goes through the four-lane loop alone.
constexpr unsigned kChunk = 128;
constexpr unsigned kPad = 16;  // a full vector stored at the last entry

struct Chunk {
  // Sweep 1: the pairs inside the support, in list order.
  alignas(64) std::uint32_t j[kChunk + kPad];
  alignas(64) double dxx[kChunk + kPad], dxy[kChunk + kPad], r2[kChunk + kPad];
  alignas(64) double vxi[kChunk + kPad], vyi[kChunk + kPad], rhoi[kChunk + kPad];
  alignas(64) double pi[kChunk + kPad], Vi[kChunk + kPad], inv_rhoi[kChunk + kPad];
  std::uint32_t first[kChunk + 1];  // pairs of the chunk's p-th particle: first[p] ..
  // Sweep 2: each pair's contributions; (x, y) of pair e at 2e.
  alignas(64) double ci[kChunk + kPad], cj[kChunk + kPad];
  alignas(64) double fi[2 * (kChunk + kPad)], fj[2 * (kChunk + kPad)];
  alignas(64) double gi[2 * (kChunk + kPad)], gj[2 * (kChunk + kPad)];
};

// (x0..x7), (y0..y7) -> out = x0 y0 x1 y1 ... x7 y7.
inline void store_pairs(double* out, v8 x, v8 y) {
  _mm512_storeu_pd(out, _mm512_permutex2var_pd(x, _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0), y));
  _mm512_storeu_pd(out + 8,
                   _mm512_permutex2var_pd(x, _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4), y));
}

// The (x, y) of the eight Vec2 a[j[l]] (as doubles from a) -> the x lanes and the y lanes.
template <class Index>
inline void load_pairs(const double* a, const Index* j, v8& xs, v8& ys) {
  const auto two = [a, j](int l, int m) {
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a + 2 * std::uint64_t{j[l]})),
                                _mm_loadu_pd(a + 2 * std::uint64_t{j[m]}), 1);
  };
  const v8 even = _mm512_insertf64x4(_mm512_castpd256_pd512(two(0, 2)), two(4, 6), 1);
  const v8 odd = _mm512_insertf64x4(_mm512_castpd256_pd512(two(1, 3)), two(5, 7), 1);
  xs = _mm512_unpacklo_pd(even, odd);
  ys = _mm512_unpackhi_pd(even, odd);
}

// The eight doubles a[j[l]].
inline v8 load8(const double* a, const std::uint32_t* j) {
  return _mm512_set_pd(a[j[7]], a[j[6]], a[j[5]], a[j[4]], a[j[3]], a[j[2]], a[j[1]], a[j[0]]);
}

// Sweep 1 for particle i: appends its partners inside the support at c.j + n; returns the new n.
inline unsigned pack(const GsphBandData& d, Chunk& c, std::uint32_t i, unsigned n) {
  const v8 zero = _mm512_setzero_pd();
  const v8 support2 = splat(d.support2);
  const double xi = d.x[i].x, yi = d.x[i].y;
  const v8 vxi = splat(d.v[i].x), vyi = splat(d.v[i].y), rhoi = splat(d.rho[i]);
  const v8 pi = splat(d.p[i]), Vi = splat(d.V[i]), inv_rhoi = splat(d.inv_rho[i]);
  const std::uint32_t end_k = d.start[i + 1];
  for (std::uint32_t k = d.start[i]; k < end_k; k += 8) {
    const std::uint32_t left = end_k - k;
    const __mmask8 listed = left >= 8 ? 0xFF : static_cast<__mmask8>((1u << left) - 1u);
    const __m512i j16 = _mm512_maskz_loadu_epi32(static_cast<__mmask16>(listed), d.index + k);
    std::uint32_t j[8];
    j[0] = d.index[k];
    for (std::uint32_t l = 1; l < 8; ++l) j[l] = l < left ? d.index[k + l] : j[0];
    v8 xj, yj;
    load_pairs(&d.x[0].x, j, xj, yj);
    const v8 dxx = xi - xj, dxy = yi - yj;
    const v8 r2 = dxx * dxx + dxy * dxy;
    // The scalar loop's test: skipped when r2 >= support2 or r2 == 0 (NaN is kept).
    const __mmask8 use = _mm512_mask_cmp_pd_mask(
        _mm512_mask_cmp_pd_mask(listed, r2, support2, _CMP_NGE_UQ), r2, zero, _CMP_NEQ_UQ);
    _mm512_storeu_si512(c.j + n, _mm512_maskz_compress_epi32(static_cast<__mmask16>(use), j16));
    _mm512_storeu_pd(c.dxx + n, _mm512_maskz_compress_pd(use, dxx));
    _mm512_storeu_pd(c.dxy + n, _mm512_maskz_compress_pd(use, dxy));
    _mm512_storeu_pd(c.r2 + n, _mm512_maskz_compress_pd(use, r2));
    _mm512_storeu_pd(c.vxi + n, vxi);
    _mm512_storeu_pd(c.vyi + n, vyi);
    _mm512_storeu_pd(c.rhoi + n, rhoi);
    _mm512_storeu_pd(c.pi + n, pi);
    _mm512_storeu_pd(c.Vi + n, Vi);
    _mm512_storeu_pd(c.inv_rhoi + n, inv_rhoi);
    n += static_cast<unsigned>(__builtin_popcount(use));
  }
  return n;
}

// Sweep 2: the pairs [0, n) of the chunk, eight at a time (the last group's extra lanes hold
// an index that can be read and values never summed).
template <bool kViscous, bool kMomentum, bool kContinuity>
void physics(const GsphBandData& d, Chunk& c, unsigned n) {
  const v8 zero = _mm512_setzero_pd();
  for (unsigned e = 0; e < n; e += 8) {
    const std::uint32_t* const jj = c.j + e;
    v8 vxj, vyj;
    load_pairs(&d.v[0].x, jj, vxj, vyj);
    const v8 rhoj = load8(d.rho, jj), Vj = load8(d.V, jj), pj = load8(d.p, jj);
    const v8 dxx = _mm512_load_pd(c.dxx + e), dxy = _mm512_load_pd(c.dxy + e);
    const v8 r2 = _mm512_load_pd(c.r2 + e);
    const v8 vxi = _mm512_load_pd(c.vxi + e), vyi = _mm512_load_pd(c.vyi + e);
    const v8 rhoi = _mm512_load_pd(c.rhoi + e), pi = _mm512_load_pd(c.pi + e);
    const v8 Vi = _mm512_load_pd(c.Vi + e), inv_rhoi = _mm512_load_pd(c.inv_rhoi + e);
    const v8 r = _mm512_sqrt_pd(r2), inv_r = 1.0 / r;
    // Kernel::dw_over_r_as<WendlandC2>: t = max(0, 1 − q/2); MAXPD(a, b) = a > b ? a : b,
    // as std::max(0.0, u) = 0 < u ? u : 0 for NaN and ±0 too.
    const v8 q = r * d.inv_h;
    const v8 t = _mm512_max_pd(1.0 - 0.5 * q, zero);
    const v8 dwr = d.w_factor * t * t * t;
    const v8 uL = -(vxi * dxx + vyi * dxy) * inv_r;
    const v8 uR = -(vxj * dxx + vyj * dxy) * inv_r;
    const v8 inv_sum = 1.0 / (rhoi + rhoj);
    const v8 du = uL - uR;
    // std::min(omega std::max(du, 0), c0): max(du, 0) = du < 0 ? 0 : du = MAXPD(0, du);
    // min(m, c0) = c0 < m ? c0 : m = MINPD(c0, m).
    const v8 beta = _mm512_min_pd(splat(d.c0), d.omega * _mm512_max_pd(zero, du));
    const v8 dp_static = 0.5 * (rhoi + rhoj) * (d.g_static.x * dxx + d.g_static.y * dxy);
    const v8 us = (rhoi * uL + rhoj * uR + (pi - pj - dp_static) * d.inv_c0) * inv_sum;
    const v8 ps = (rhoj * pi + rhoi * pj + beta * rhoi * rhoj * du) * inv_sum;
    // The scalar loop's contributions: (v_i − v*).∇W terms, pressure and viscous forces.
    if constexpr (kContinuity) {
      const v8 dwr_r = dwr * r;
      _mm512_store_pd(c.ci + e, Vj * (uL - us) * dwr_r);
      _mm512_store_pd(c.cj + e, Vi * (us - uR) * dwr_r);
    }
    if constexpr (kMomentum) {
      const v8 fp = -2.0 * ps * dwr;
      const v8 a = Vj * inv_rhoi * fp;
      const v8 inv_rhoj = load8(d.inv_rho, jj);
      const v8 b = Vi * inv_rhoj * fp;
      store_pairs(c.fi + 2 * e, a * dxx, a * dxy);
      store_pairs(c.fj + 2 * e, b * dxx, b * dxy);
      if constexpr (kViscous) {
        const v8 coef = d.nu * (rhoi + rhoj) * dwr * r2 / (r2 + d.eta2);
        const v8 vijx = vxi - vxj, vijy = vyi - vyj;
        const v8 vci = coef * Vj * inv_rhoi;
        const v8 vcj = coef * Vi * inv_rhoj;
        store_pairs(c.gi + 2 * e, vci * vijx, vci * vijy);
        store_pairs(c.gj + 2 * e, vcj * vijx, vcj * vijy);
      }
    }
  }
}

// Sweep 3: particles [i_first, i_first + count) of the chunk, the scalar loop's additions.
template <bool kViscous, bool kMomentum, bool kContinuity>
void sums(const GsphBandData& d, const Chunk& c, std::uint32_t i_first, unsigned count) {
  for (unsigned p = 0; p < count; ++p) {
    v2 acc_i = _mm_setzero_pd();  // (x, y), the scalar loop's Vec2 acc_i
    double drho_i = 0.0;
    for (unsigned e = c.first[p]; e < c.first[p + 1]; ++e) {
      const std::uint32_t j = c.j[e];
      if constexpr (kContinuity) {
        drho_i -= c.ci[e];
        d.drho[j] -= c.cj[e];
      }
      if constexpr (kMomentum) {
        double* const aj = &d.acc[j].x;
        acc_i = _mm_add_pd(acc_i, _mm_load_pd(c.fi + 2 * e));
        v2 a = _mm_sub_pd(_mm_loadu_pd(aj), _mm_load_pd(c.fj + 2 * e));
        if constexpr (kViscous) {
          acc_i = _mm_add_pd(acc_i, _mm_load_pd(c.gi + 2 * e));
          a = _mm_sub_pd(a, _mm_load_pd(c.gj + 2 * e));
        }
        _mm_storeu_pd(aj, a);
      }
    }
    const std::uint32_t i = i_first + p;
    if constexpr (kMomentum) {
      double* const ai = &d.acc[i].x;
      _mm_storeu_pd(ai, _mm_add_pd(_mm_loadu_pd(ai), acc_i));
    }
    if constexpr (kContinuity) d.drho[i] += drho_i;
  }
}

template <bool kViscous, bool kMomentum, bool kContinuity>
void band(const GsphBandData& d, std::uint32_t i_begin, std::uint32_t i_end) {
  Chunk c;
  std::uint32_t i_first = i_begin;  // the chunk's first particle
  unsigned count = 0, n = 0;        // its particles and pairs so far
  c.first[0] = 0;
  const auto run = [&]() {
    // Readable indices in the last group's extra lanes.
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(c.j + n),
                        _mm256_set1_epi32(static_cast<int>(i_first)));
    physics<kViscous, kMomentum, kContinuity>(d, c, n);
    sums<kViscous, kMomentum, kContinuity>(d, c, i_first, count);
    i_first += count;
    count = 0;
    n = 0;
  };
  for (std::uint32_t i = i_begin; i < i_end; ++i) {
    const std::uint32_t listed = d.start[i + 1] - d.start[i];
    if (n + listed > kChunk || count == kChunk) run();
    if (listed > kChunk) {
      gsph_wendland_band_avx2(d, i, i + 1);
      i_first = i + 1;
      continue;
    }
    n = pack(d, c, i, n);
    c.first[++count] = n;
  }
  run();
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

bool gsph_band_avx512_available() {
  return __builtin_cpu_supports("avx512f");
}

void gsph_wendland_band_avx512(const GsphBandData& d, std::uint32_t i_begin, std::uint32_t i_end) {
  if (d.viscous)
    dispatch_pass<true>(d, i_begin, i_end);
  else
    dispatch_pass<false>(d, i_begin, i_end);
}

}  // namespace slamsph

#else  // not an x86-64 build with -mavx512f: the four-lane or the scalar loop runs

namespace slamsph {

bool gsph_band_avx512_available() {
  return false;
}

void gsph_wendland_band_avx512(const GsphBandData&, std::uint32_t, std::uint32_t) {}

}  // namespace slamsph

#endif
