// Pass 2's pair sums in eight lanes (solid/substep_pair_lanes.h): a lane per particle, the
// block's slots in order, each slot's own records loaded as runs of eight, j's V0 P and G
// and the reverse pair's κ ε gathered (masked: a slot past a lane's pairs loads nothing and
// adds nothing). Built with -mavx512f -ffp-contract=off (CMakeLists.txt), the only file of
// the solid domain built so; it defines nothing but the two functions of the header.
#include "solid/substep_pair_lanes.h"

#if defined(__AVX512F__)
// GCC 12's _mm512_sqrt_pd passes an undefined vector as the (unused) source of its mask.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>

namespace slamsph {

namespace {

// The lanes of [i0, i1) in the block of particles [b8, b8 + 8).
inline __mmask8 range_mask(std::size_t b8, std::size_t i0, std::size_t i1) {
  const unsigned lo = i0 > b8 ? static_cast<unsigned>(i0 - b8) : 0u;
  const unsigned hi = i1 - b8 < 8 ? static_cast<unsigned>(i1 - b8) : 8u;
  return static_cast<__mmask8>(((1u << hi) - 1u) & ~((1u << lo) - 1u));
}

// The block of particles [b8, b8 + 8) in the ELL layout, both passes: the lanes of [i0, i1)
// in it, the position of its slot 0, its slot count and its slots' lane masks.
struct EllBlock {
  __mmask8 range;
  std::uint32_t p0, slots;
  const std::uint8_t* mask;
};
inline EllBlock ell_block(const std::uint32_t* off, const std::uint8_t* mask, std::size_t b8,
                          std::size_t i0, std::size_t i1) {
  const std::size_t blk = b8 / 8;
  const std::uint32_t p0 = off[blk];
  return {range_mask(b8, i0, i1), p0, (off[blk + 1] - p0) / 8, mask + p0 / 8};
}

// c0 gx + c1 gy: two products, then their sum (the scalar loop's rounding).
inline __m512d dot_slot(__m512d c0, __m512d c1, __m512d gx, __m512d gy) {
  return _mm512_add_pd(_mm512_mul_pd(c0, gx), _mm512_mul_pd(c1, gy));
}

template <bool kHourglass>
void pair_sums(const SubstepLaneData& d, std::size_t base, std::size_t i0, std::size_t i1,
               SubstepLaneSums& out) {
  const __m512d zero = _mm512_setzero_pd();
  for (std::size_t b8 = i0 & ~std::size_t{7}; b8 < i1; b8 += 8) {
    const auto [range, p0, slots, mk] = ell_block(d.off, d.mask, b8, i0, i1);
    __m512d fs_x = zero, fs_y = zero, grad_x = zero, grad_y = zero;
    for (std::uint32_t s = 0; s < slots; ++s) {
      // Lanes whose particle has an s-th pair (fewer with every slot: none left, none later).
      const __mmask8 m = static_cast<__mmask8>(mk[s] & range);
      if (m == 0) break;
      const std::uint32_t p = p0 + 8 * s;
      const __m512d gx = _mm512_loadu_pd(d.g_rev_x + p), gy = _mm512_loadu_pd(d.g_rev_y + p);
      // j's 8 doubles (V0 P and G by columns), one row per lane, transposed: col[c] holds
      // component c of the eight partners (a masked slot's j is its own particle).
      __m512d col[8];
      {
        const std::int32_t* const jj = d.j + p;
        __m512d r[8];
        for (int l = 0; l < 8; ++l)
          r[l] = _mm512_loadu_pd(d.mats + 8 * static_cast<std::size_t>(jj[l]));
        __m512d t[8], u[8];
        for (int l = 0; l < 8; l += 2) {
          t[l] = _mm512_unpacklo_pd(r[l], r[l + 1]);
          t[l + 1] = _mm512_unpackhi_pd(r[l], r[l + 1]);
        }
        // t[0]: (r0[0] r1[0]) (r0[2] r1[2]) (r0[4] r1[4]) (r0[6] r1[6]); t[1] likewise odd.
        u[0] = _mm512_shuffle_f64x2(t[0], t[2], 0x88);  // cols 0, 4 of rows 0-3
        u[1] = _mm512_shuffle_f64x2(t[0], t[2], 0xDD);  // cols 2, 6
        u[2] = _mm512_shuffle_f64x2(t[1], t[3], 0x88);  // cols 1, 5
        u[3] = _mm512_shuffle_f64x2(t[1], t[3], 0xDD);  // cols 3, 7
        u[4] = _mm512_shuffle_f64x2(t[4], t[6], 0x88);  // the same of rows 4-7
        u[5] = _mm512_shuffle_f64x2(t[4], t[6], 0xDD);
        u[6] = _mm512_shuffle_f64x2(t[5], t[7], 0x88);
        u[7] = _mm512_shuffle_f64x2(t[5], t[7], 0xDD);
        col[0] = _mm512_shuffle_f64x2(u[0], u[4], 0x88);
        col[4] = _mm512_shuffle_f64x2(u[0], u[4], 0xDD);
        col[2] = _mm512_shuffle_f64x2(u[1], u[5], 0x88);
        col[6] = _mm512_shuffle_f64x2(u[1], u[5], 0xDD);
        col[1] = _mm512_shuffle_f64x2(u[2], u[6], 0x88);
        col[5] = _mm512_shuffle_f64x2(u[2], u[6], 0xDD);
        col[3] = _mm512_shuffle_f64x2(u[3], u[7], 0x88);
        col[7] = _mm512_shuffle_f64x2(u[3], u[7], 0xDD);
      }
      // fs += V0_j P_j g_ji, by components (vp_c0 = (xx, yx), vp_c1 = (xy, yy)).
      const __m512d c0x = col[0], c0y = col[1], c1x = col[2], c1y = col[3];
      fs_x = _mm512_mask_add_pd(fs_x, m, fs_x, dot_slot(c0x, c1x, gx, gy));
      fs_y = _mm512_mask_add_pd(fs_y, m, fs_y, dot_slot(c0y, c1y, gx, gy));
      if constexpr (kHourglass) {
        // grad += G_j g_ji, then grad += κ ε_ij − κ ε_ji (two adds, as the scalar loop).
        const __m512d g0x = col[4], g0y = col[5], g1x = col[6], g1y = col[7];
        grad_x = _mm512_mask_add_pd(grad_x, m, grad_x, dot_slot(g0x, g1x, gx, gy));
        grad_y = _mm512_mask_add_pd(grad_y, m, grad_y, dot_slot(g0y, g1y, gx, gy));
        const __m256i rp = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(d.rev_pos + p));
        const __m512d kr_x = _mm512_mask_i32gather_pd(zero, m, rp, d.keps_x, 8);
        const __m512d kr_y = _mm512_mask_i32gather_pd(zero, m, rp, d.keps_y, 8);
        grad_x = _mm512_mask_add_pd(grad_x, m, grad_x,
                                    _mm512_sub_pd(_mm512_loadu_pd(d.keps_x + p), kr_x));
        grad_y = _mm512_mask_add_pd(grad_y, m, grad_y,
                                    _mm512_sub_pd(_mm512_loadu_pd(d.keps_y + p), kr_y));
      }
    }
    const std::size_t o = b8 - base;
    _mm512_mask_storeu_pd(out.fs_x + o, range, fs_x);
    _mm512_mask_storeu_pd(out.fs_y + o, range, fs_y);
    _mm512_mask_storeu_pd(out.grad_x + o, range, grad_x);
    _mm512_mask_storeu_pd(out.grad_y + o, range, grad_y);
  }
}

// The (x, y) pairs at 2 j[l] of `a` for the eight lanes, as x and y vectors (loads of the
// rows and two permutations instead of two gathers; every j is a valid particle).
inline void pairs_by_component(const double* a, const std::int32_t* j, __m512d& x, __m512d& y) {
  auto row = [&](int l) { return _mm_loadu_pd(a + 2 * static_cast<std::size_t>(j[l])); };
  auto four = [&](int l) {
    __m512 v = _mm512_castpd_ps(_mm512_castpd128_pd512(row(l)));
    v = _mm512_insertf32x4(v, _mm_castpd_ps(row(l + 1)), 1);
    v = _mm512_insertf32x4(v, _mm_castpd_ps(row(l + 2)), 2);
    v = _mm512_insertf32x4(v, _mm_castpd_ps(row(l + 3)), 3);
    return _mm512_castps_pd(v);
  };
  const __m512d lo = four(0), hi = four(4);  // (x0 y0 x1 y1 x2 y2 x3 y3), lanes 4-7
  x = _mm512_permutex2var_pd(lo, _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), hi);
  y = _mm512_permutex2var_pd(lo, _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15), hi);
}

// Up to this many slots per block keep x_j − x_i for the hourglass loop; a block with more
// gathers x_j again.
constexpr std::uint32_t kMaxKeptSlots = 32;

template <bool kHourglass, bool kViscous>
void pass1_pairs(const SubstepLane1Data& d, std::size_t base, std::size_t i0, std::size_t i1,
                 SubstepLane1Sums& out) {
  const __m512d zero = _mm512_setzero_pd();
  // Lane l's particle: its (x, y) at 2 (b8 + l) of x and vh.
  const __m256i lane2 = _mm256_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14);
  const __m512d nac = _mm512_set1_pd(-d.av_alpha * d.c), beta = _mm512_set1_pd(d.av_beta);
  const __m512d hundredth = _mm512_set1_pd(0.01);
  const __m512d mhalf = _mm512_set1_pd(-0.5);
  __m512d dxs[kMaxKeptSlots], dys[kMaxKeptSlots];
  for (std::size_t b8 = i0 & ~std::size_t{7}; b8 < i1; b8 += 8) {
    const auto [range, p0, slots, mk] = ell_block(d.off, d.mask, b8, i0, i1);
    const __m256i i2 = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(2 * b8)), lane2);
    const __m512d xi_x = _mm512_mask_i32gather_pd(zero, range, i2, d.x, 8);
    const __m512d xi_y = _mm512_mask_i32gather_pd(zero, range, i2, d.x + 1, 8);
    const __m512d vi_x = _mm512_mask_i32gather_pd(zero, range, i2, d.vh, 8);
    const __m512d vi_y = _mm512_mask_i32gather_pd(zero, range, i2, d.vh + 1, 8);
    __m512d fav_x = zero, fav_y = zero, heat = zero;
    // F and Ḟ by components: F_ab += (x_j − x_i)_a g_b (add_outer's rounding).
    __m512d Fxx = zero, Fxy = zero, Fyx = zero, Fyy = zero;
    __m512d Dxx = zero, Dxy = zero, Dyx = zero, Dyy = zero;
    std::uint32_t used = 0;  // slots with a lane
    for (std::uint32_t s = 0; s < slots; ++s) {
      const __mmask8 m = static_cast<__mmask8>(mk[s] & range);
      if (m == 0) break;
      used = s + 1;
      const std::uint32_t p = p0 + 8 * s;
      __m512d xj_x, xj_y, vj_x, vj_y;
      pairs_by_component(d.x, d.j + p, xj_x, xj_y);
      pairs_by_component(d.vh, d.j + p, vj_x, vj_y);
      const __m512d gx = _mm512_loadu_pd(d.g_x + p), gy = _mm512_loadu_pd(d.g_y + p);
      const __m512d dx = _mm512_sub_pd(xj_x, xi_x), dy = _mm512_sub_pd(xj_y, xi_y);
      const __m512d dvx = _mm512_sub_pd(vj_x, vi_x), dvy = _mm512_sub_pd(vj_y, vi_y);
      Fxx = _mm512_mask_add_pd(Fxx, m, Fxx, _mm512_mul_pd(dx, gx));
      Fyx = _mm512_mask_add_pd(Fyx, m, Fyx, _mm512_mul_pd(dy, gx));
      Fxy = _mm512_mask_add_pd(Fxy, m, Fxy, _mm512_mul_pd(dx, gy));
      Fyy = _mm512_mask_add_pd(Fyy, m, Fyy, _mm512_mul_pd(dy, gy));
      Dxx = _mm512_mask_add_pd(Dxx, m, Dxx, _mm512_mul_pd(dvx, gx));
      Dyx = _mm512_mask_add_pd(Dyx, m, Dyx, _mm512_mul_pd(dvy, gx));
      Dxy = _mm512_mask_add_pd(Dxy, m, Dxy, _mm512_mul_pd(dvx, gy));
      Dyy = _mm512_mask_add_pd(Dyy, m, Dyy, _mm512_mul_pd(dvy, gy));
      if (s < kMaxKeptSlots) {
        dxs[s] = dx;
        dys[s] = dy;
      }
      if constexpr (kViscous) {
        // viscous_force_on's pair term (monaghan_pi, artificial_viscosity.h) in its order of
        // operations, for every pair from i's side (the scalar loop computes a pair once, at
        // its lower particle, and gives j −f: x_ji = −x_ij and v_ji = −v_ij exactly, so the
        // same Π and s, and s x_ji = −(s x_ij) exactly; where Π = 0 it stores +0 for i and −0
        // for j, which add alike to a sum that starts at +0, never −0), summed in i's pair
        // order as pass 2 sums the stored terms.
        const __m512d xij_x = _mm512_sub_pd(xi_x, xj_x), xij_y = _mm512_sub_pd(xi_y, xj_y);
        const __m512d vij_x = _mm512_sub_pd(vi_x, vj_x), vij_y = _mm512_sub_pd(vi_y, vj_y);
        const __m512d vx = _mm512_add_pd(_mm512_mul_pd(vij_x, xij_x), _mm512_mul_pd(vij_y, xij_y));
        const __m512d hm = _mm512_loadu_pd(d.h_pair + p), rm = _mm512_loadu_pd(d.rho_pair + p);
        const __m512d r2 = _mm512_add_pd(_mm512_mul_pd(xij_x, xij_x), _mm512_mul_pd(xij_y, xij_y));
        const __m512d mu =
            _mm512_div_pd(_mm512_mul_pd(hm, vx),
                          _mm512_add_pd(r2, _mm512_mul_pd(_mm512_mul_pd(hundredth, hm), hm)));
        const __m512d pi = _mm512_mul_pd(
            rm, _mm512_add_pd(_mm512_mul_pd(nac, mu), _mm512_mul_pd(_mm512_mul_pd(beta, mu), mu)));
        // Π is returned where vx ≥ 0 is false (NaN included), then used where Π ≠ 0.
        const __mmask8 act = _mm512_mask_cmp_pd_mask(m, vx, zero, _CMP_NGE_UQ) &
                             _mm512_cmp_pd_mask(pi, zero, _CMP_NEQ_UQ);
        if (act != 0) {
          const __m512d sc =
              _mm512_div_pd(_mm512_mul_pd(pi, _mm512_loadu_pd(d.vw + p)), _mm512_sqrt_pd(r2));
          const __m512d dxv =
              _mm512_add_pd(_mm512_mul_pd(xij_x, vij_x), _mm512_mul_pd(xij_y, vij_y));
          fav_x = _mm512_mask_add_pd(fav_x, act, fav_x, _mm512_mul_pd(sc, xij_x));
          fav_y = _mm512_mask_add_pd(fav_y, act, fav_y, _mm512_mul_pd(sc, xij_y));
          heat = _mm512_mask_add_pd(heat, act, heat, _mm512_mul_pd(_mm512_mul_pd(mhalf, sc), dxv));
        }
      }
    }
    const std::size_t o = b8 - base;
    _mm512_mask_storeu_pd(out.F[0] + o, range, Fxx);
    _mm512_mask_storeu_pd(out.F[1] + o, range, Fxy);
    _mm512_mask_storeu_pd(out.F[2] + o, range, Fyx);
    _mm512_mask_storeu_pd(out.F[3] + o, range, Fyy);
    _mm512_mask_storeu_pd(out.Fd[0] + o, range, Dxx);
    _mm512_mask_storeu_pd(out.Fd[1] + o, range, Dxy);
    _mm512_mask_storeu_pd(out.Fd[2] + o, range, Dyx);
    _mm512_mask_storeu_pd(out.Fd[3] + o, range, Dyy);
    _mm512_mask_storeu_pd(out.fav_x + o, range, fav_x);
    _mm512_mask_storeu_pd(out.fav_y + o, range, fav_y);
    _mm512_mask_storeu_pd(out.heat + o, range, heat);
    if constexpr (kHourglass) {
      // hourglass_moment: κ ε = κ (F X_ij − (x_j − x_i)) (simd::mul's rounding), G += κ ε ⊗ X.
      __m512d Gxx = zero, Gxy = zero, Gyx = zero, Gyy = zero;
      for (std::uint32_t s = 0; s < used; ++s) {
        const __mmask8 m = static_cast<__mmask8>(mk[s] & range);
        const std::uint32_t p = p0 + 8 * s;
        __m512d dx, dy;
        if (s < kMaxKeptSlots) {
          dx = dxs[s];
          dy = dys[s];
        } else {
          const __m256i j2 =
              _mm256_slli_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(d.j + p)), 1);
          dx = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, m, j2, d.x, 8), xi_x);
          dy = _mm512_sub_pd(_mm512_mask_i32gather_pd(zero, m, j2, d.x + 1, 8), xi_y);
        }
        const __m512d Xx = _mm512_loadu_pd(d.X_x + p), Xy = _mm512_loadu_pd(d.X_y + p);
        const __m512d kap = _mm512_loadu_pd(d.kappa + p);
        const __m512d kx = _mm512_mul_pd(
            kap, _mm512_sub_pd(_mm512_add_pd(_mm512_mul_pd(Fxx, Xx), _mm512_mul_pd(Fxy, Xy)), dx));
        const __m512d ky = _mm512_mul_pd(
            kap, _mm512_sub_pd(_mm512_add_pd(_mm512_mul_pd(Fyx, Xx), _mm512_mul_pd(Fyy, Xy)), dy));
        _mm512_mask_storeu_pd(d.keps_x + p, m, kx);
        _mm512_mask_storeu_pd(d.keps_y + p, m, ky);
        Gxx = _mm512_mask_add_pd(Gxx, m, Gxx, _mm512_mul_pd(kx, Xx));
        Gyx = _mm512_mask_add_pd(Gyx, m, Gyx, _mm512_mul_pd(ky, Xx));
        Gxy = _mm512_mask_add_pd(Gxy, m, Gxy, _mm512_mul_pd(kx, Xy));
        Gyy = _mm512_mask_add_pd(Gyy, m, Gyy, _mm512_mul_pd(ky, Xy));
      }
      _mm512_mask_storeu_pd(out.G[0] + o, range, Gxx);
      _mm512_mask_storeu_pd(out.G[1] + o, range, Gxy);
      _mm512_mask_storeu_pd(out.G[2] + o, range, Gyx);
      _mm512_mask_storeu_pd(out.G[3] + o, range, Gyy);
    }
  }
}

}  // namespace

bool substep_lanes_avx512_available() {
  return __builtin_cpu_supports("avx512f");
}

void substep_lanes_avx512_pass1(const SubstepLane1Data& d, std::size_t base, std::size_t i0,
                                std::size_t i1, SubstepLane1Sums& out) {
  if (d.hourglass)
    d.viscous ? pass1_pairs<true, true>(d, base, i0, i1, out)
              : pass1_pairs<true, false>(d, base, i0, i1, out);
  else
    d.viscous ? pass1_pairs<false, true>(d, base, i0, i1, out)
              : pass1_pairs<false, false>(d, base, i0, i1, out);
}

void substep_lanes_avx512_pass2(const SubstepLaneData& d, std::size_t base, std::size_t i0,
                                std::size_t i1, SubstepLaneSums& out) {
  d.hourglass ? pair_sums<true>(d, base, i0, i1, out) : pair_sums<false>(d, base, i0, i1, out);
}

}  // namespace slamsph

#else  // a build without AVX-512F for this file: the scalar loop runs

namespace slamsph {

bool substep_lanes_avx512_available() {
  return false;
}

void substep_lanes_avx512_pass1(const SubstepLane1Data&, std::size_t, std::size_t, std::size_t,
                                SubstepLane1Sums&) {}

void substep_lanes_avx512_pass2(const SubstepLaneData&, std::size_t, std::size_t, std::size_t,
                                SubstepLaneSums&) {}

}  // namespace slamsph

#endif
