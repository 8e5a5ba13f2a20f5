// The second half kick in eight lanes (fluid/kick_lanes.h). This file alone is compiled with
// -mavx512f -ffp-contract=off (CMakeLists.txt), under the rule of fluid/gsph_pair_band_avx512.cpp:
// it calls no inline function of a project or standard header, only the AVX-512 intrinsics
// and GCC builtins (the test kick_avx512_object_defines_only_its_functions checks its symbols).
#include "fluid/kick_lanes.h"

#if defined(__AVX512F__)
// GCC 12's AVX-512 headers start the result of an unmasked max from an undefined vector
// (`__Y = __Y`), which -Wmaybe-uninitialized reports (as in gsph_pair_band_avx512.cpp).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>

namespace slamsph {

namespace {

using v8 = __m512d;

inline v8 splat(double s) {
  return _mm512_set1_pd(s);
}

// Eight Vec2 from a -> the x lanes and the y lanes.
inline void load_xy(const Vec2* a, v8& xs, v8& ys) {
  const double* const q = &a[0].x;
  const v8 lo = _mm512_loadu_pd(q), hi = _mm512_loadu_pd(q + 8);
  xs = _mm512_permutex2var_pd(lo, _mm512_set_epi64(14, 12, 10, 8, 6, 4, 2, 0), hi);
  ys = _mm512_permutex2var_pd(lo, _mm512_set_epi64(15, 13, 11, 9, 7, 5, 3, 1), hi);
}

// The x lanes and the y lanes -> eight Vec2 at a.
inline void store_xy(Vec2* a, v8 xs, v8 ys) {
  double* const q = &a[0].x;
  _mm512_storeu_pd(q, _mm512_permutex2var_pd(xs, _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0), ys));
  _mm512_storeu_pd(q + 8,
                   _mm512_permutex2var_pd(xs, _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4), ys));
}

}  // namespace

bool kick_lanes_avx512_available() {
  return __builtin_cpu_supports("avx512f");
}

namespace {

// The drift (KickLaneData::dt): the scalar sweep's six assignments in order, and max |x - x0|².
std::uint32_t drift(const KickLaneData& d, std::uint32_t begin, std::uint32_t end, double* maxima) {
  const v8 hdt = splat(d.hdt), dt = splat(d.dt), rho0 = splat(d.rho0);
  const v8 stiffness = splat(d.stiffness), one = splat(1.0);
  v8 md = _mm512_setzero_pd();
  std::uint32_t i = begin;
  for (; i + 8 <= end; i += 8) {
    v8 vx, vy, ax, ay, xx, xy, x0x, x0y;
    load_xy(d.v + i, vx, vy);
    load_xy(d.a + i, ax, ay);
    load_xy(d.x + i, xx, xy);
    load_xy(d.x0 + i, x0x, x0y);
    const v8 drho = _mm512_loadu_pd(d.drho + i);
    const v8 vhx = vx + hdt * ax, vhy = vy + hdt * ay;
    const v8 rho_half = _mm512_loadu_pd(d.rho + i) + hdt * drho;
    xx = xx + dt * vhx;
    xy = xy + dt * vhy;
    const v8 nvx = vhx + hdt * ax, nvy = vhy + hdt * ay;
    const v8 rho = rho_half + hdt * drho;
    const v8 r = rho / rho0;
    const v8 r2 = r * r, r4 = r2 * r2;
    const v8 p = stiffness * (r4 * r2 * r - one);
    store_xy(d.v_half + i, vhx, vhy);
    _mm512_storeu_pd(d.rho_half + i, rho_half);
    store_xy(d.x + i, xx, xy);
    store_xy(d.v + i, nvx, nvy);
    _mm512_storeu_pd(d.rho + i, rho);
    _mm512_storeu_pd(d.p + i, p);
    const v8 dx = xx - x0x, dy = xy - x0y;
    md = _mm512_max_pd(dx * dx + dy * dy, md);
  }
  alignas(64) double lanes[8];
  _mm512_store_pd(lanes, md);
  for (int l = 0; l < 8; ++l)
    if (lanes[l] > maxima[0]) maxima[0] = lanes[l];
  return i;
}

}  // namespace

std::uint32_t kick_lanes_avx512(const KickLaneData& d, bool drift_too, std::uint32_t begin,
                                std::uint32_t end, double* maxima) {
  if (drift_too) return drift(d, begin, end, maxima);
  const v8 hdt = splat(d.hdt), rho0 = splat(d.rho0), stiffness = splat(d.stiffness);
  const v8 one = splat(1.0), big = splat(__DBL_MAX__);
  const v8 xmin = splat(d.domain.min.x), xmax = splat(d.domain.max.x);
  const v8 ymin = splat(d.domain.min.y), ymax = splat(d.domain.max.y);
  v8 mv = _mm512_setzero_pd(), ma = _mm512_setzero_pd();
  __mmask8 bad = 0;
  std::uint32_t i = begin;
  for (; i + 8 <= end; i += 8) {
    v8 vhx, vhy, ax, ay, xx, xy;
    load_xy(d.v_half + i, vhx, vhy);
    load_xy(d.a + i, ax, ay);
    load_xy(d.x + i, xx, xy);
    // v = v_half + dt/2 a; rho = rho_half + dt/2 drho (Vec2's operators: component-wise).
    const v8 vx = vhx + hdt * ax, vy = vhy + hdt * ay;
    const v8 rho = _mm512_loadu_pd(d.rho_half + i) + hdt * _mm512_loadu_pd(d.drho + i);
    // TaitEos::pressure for gamma = 7: r = rho / rho0, stiffness (r^4 r^2 r - 1).
    const v8 r = rho / rho0;
    const v8 r2 = r * r, r4 = r2 * r2;
    const v8 p = stiffness * (r4 * r2 * r - one);
    store_xy(d.v + i, vx, vy);
    _mm512_storeu_pd(d.rho + i, rho);
    _mm512_storeu_pd(d.p + i, p);
    // norm2 = x x + y y; the maxima as `if (q > m) m = q` (MAXPD(q, m) = q > m ? q : m).
    mv = _mm512_max_pd(vx * vx + vy * vy, mv);
    ma = _mm512_max_pd(ax * ax + ay * ay, ma);
    // FsiStepper's bad_fluid: |q| <= DBL_MAX false for NaN and ±inf; outside the domain.
    const __mmask8 finite = _mm512_cmp_pd_mask(_mm512_abs_pd(xx), big, _CMP_LE_OQ) &
                            _mm512_cmp_pd_mask(_mm512_abs_pd(xy), big, _CMP_LE_OQ) &
                            _mm512_cmp_pd_mask(_mm512_abs_pd(vx), big, _CMP_LE_OQ) &
                            _mm512_cmp_pd_mask(_mm512_abs_pd(vy), big, _CMP_LE_OQ) &
                            _mm512_cmp_pd_mask(_mm512_abs_pd(rho), big, _CMP_LE_OQ);
    const __mmask8 outside =
        _mm512_cmp_pd_mask(xx, xmin, _CMP_LT_OQ) | _mm512_cmp_pd_mask(xx, xmax, _CMP_GT_OQ) |
        _mm512_cmp_pd_mask(xy, ymin, _CMP_LT_OQ) | _mm512_cmp_pd_mask(xy, ymax, _CMP_GT_OQ);
    bad |= static_cast<__mmask8>(~finite | outside);
  }
  alignas(64) double lanes[2][8];
  _mm512_store_pd(lanes[0], mv);
  _mm512_store_pd(lanes[1], ma);
  for (int k = 0; k < 2; ++k)
    for (int l = 0; l < 8; ++l)
      if (lanes[k][l] > maxima[k]) maxima[k] = lanes[k][l];
  if (bad != 0 && 1.0 > maxima[2]) maxima[2] = 1.0;
  return i;
}

}  // namespace slamsph

#else  // not an x86-64 build with -mavx512f: the scalar sweep runs

namespace slamsph {

bool kick_lanes_avx512_available() {
  return false;
}

std::uint32_t kick_lanes_avx512(const KickLaneData&, bool, std::uint32_t begin, std::uint32_t,
                                double*) {
  return begin;
}

}  // namespace slamsph

#endif
