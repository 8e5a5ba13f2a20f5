// The three sweeps of the contact's fluid-side loop in vector lanes
// (coupling/contact_pair_lanes.h), written once for any lane count. Included only by
// contact_pair_lanes_avx2.cpp and contact_pair_lanes_avx512.cpp, after their `Lanes` (the vector
// type V of W doubles, with splat, load, store, sqrt, any, gather and load_pairs), and compiled
// with their ISA flags and -ffp-contract=off. Everything here is in an anonymous namespace and
// calls no inline function of a project or standard header (the tests
// *_object_defines_only_its_functions, tests/CMakeLists.txt), so no ISA-specific copy of one
// reaches the rest of the program. The operations are those of contact_pair<kViscous>
// (coupling/contact_pair.h), solve_riemann (fluid/riemann_solver.h) and
// Kernel::dw_over_r_as<WendlandC2> (core/kernel.h) in the order they are written there; std::max(a,
// b) is (a < b ? b : a) and std::min(a, b) is (b < a ? b : a), written so below.
#pragma once
// (No include: the including file has <immintrin.h>, contact_pair_lanes.h and Lanes.)

namespace slamsph {

namespace {

constexpr unsigned kChunk = kContactLaneChunk;
constexpr unsigned kPad = 16;  // a full vector written at the last pair (16 indices)

struct Chunk {
  // Sweep 1: the pairs that act, in list order.
  alignas(64) std::uint32_t s[kChunk + kPad];  // contact particle
  alignas(64) std::uint32_t k[kChunk + kPad];  // list entry (for the kept forces)
  alignas(64) double dxx[kChunk + kPad], dxy[kChunk + kPad], r2[kChunk + kPad];
  alignas(64) double vxi[kChunk + kPad], vyi[kChunk + kPad], rhoi[kChunk + kPad];
  alignas(64) double pi[kChunk + kPad], Vi[kChunk + kPad];
  std::uint32_t first[kChunk + 1];  // pairs of the chunk's p-th fluid particle: first[p] ..
  // Sweep 2: each pair's total force (x, y), viscous force and continuity term.
  alignas(64) double tx[kChunk + kPad], ty[kChunk + kPad];
  alignas(64) double gx[kChunk + kPad], gy[kChunk + kPad], dr[kChunk + kPad];
};

// Sweep 1 for fluid particle i (volume Vi): appends its acting partners at n; returns the new
// n. Branch-free: every listed partner is written at n, which advances only if it acts.
inline unsigned pack(const ContactLaneData& d, Chunk& c, std::uint32_t i, double Vi, unsigned n) {
  const double xi = d.xf[i].x, yi = d.xf[i].y;
  const double vxi = d.vf[i].x, vyi = d.vf[i].y, rhoi = d.rhof[i], pi = d.pf[i];
  const double support2 = d.support2;
  const std::uint32_t end_k = d.start[i + 1];
  for (std::uint32_t k = d.start[i]; k < end_k; ++k) {
    const std::uint32_t s = d.index[k];
    const double dxx = xi - d.xs[s].x, dxy = yi - d.xs[s].y;
    const double r2 = dxx * dxx + dxy * dxy;
    // The scalar loop's tests: wetted, ContactParticles::faces, then r2 inside the support
    // and not zero (contact_pair). Combined without branches (a third of the listed pairs
    // are the lists' skin, so a branch per test is mispredicted often).
    unsigned acts = static_cast<unsigned>(d.wetted[s] != 0) &
                    static_cast<unsigned>(!(r2 >= support2)) & static_cast<unsigned>(r2 != 0.0);
    if (d.ghost[s])
      acts &= static_cast<unsigned>(
          (xi - d.anchor[s].x) * d.normal[s].x + (yi - d.anchor[s].y) * d.normal[s].y > 0.0);
    c.s[n] = s;
    c.k[n] = k;
    c.dxx[n] = dxx;
    c.dxy[n] = dxy;
    c.r2[n] = r2;
    c.vxi[n] = vxi;
    c.vyi[n] = vyi;
    c.rhoi[n] = rhoi;
    c.pi[n] = pi;
    c.Vi[n] = Vi;
    n += acts;
  }
  return n;
}

#if defined(__AVX512F__)
// Sweep 1 in eight lanes (as the fluid's, fluid/gsph_pair_band_avx512.cpp): eight listed
// partners at a time, r2 and the support test in lanes, the wetted and ghost flags read per lane
// into bit masks (a ghost's facing test per lane, in the scalar loop's operations), and the
// acting partners compressed into a register and stored whole (a compress to memory is slow on
// Zen 4). The same pairs in the same order as pack().
inline unsigned pack8(const ContactLaneData& d, Chunk& c, std::uint32_t i, double Vi, unsigned n) {
  const __m512d zero = _mm512_setzero_pd(), support2 = _mm512_set1_pd(d.support2);
  const double xi = d.xf[i].x, yi = d.xf[i].y;
  const __m512d vxi = _mm512_set1_pd(d.vf[i].x), vyi = _mm512_set1_pd(d.vf[i].y);
  const __m512d rhoi = _mm512_set1_pd(d.rhof[i]), pi = _mm512_set1_pd(d.pf[i]);
  const __m512d Vis = _mm512_set1_pd(Vi);
  const __m512i lane = _mm512_set_epi32(15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0);
  const std::uint32_t end_k = d.start[i + 1];
  for (std::uint32_t k = d.start[i]; k < end_k; k += 8) {
    const std::uint32_t left = end_k - k;
    const __mmask8 listed = left >= 8 ? 0xFF : static_cast<__mmask8>((1u << left) - 1u);
    const __m512i j16 = _mm512_maskz_loadu_epi32(static_cast<__mmask16>(listed), d.index + k);
    std::uint32_t j[8];
    j[0] = d.index[k];
    for (std::uint32_t l = 1; l < 8; ++l) j[l] = l < left ? d.index[k + l] : j[0];
    __m512d xs, ys;
    Lanes::load_pairs(&d.xs[0].x, j, xs, ys);
    const __m512d dxx = xi - xs, dxy = yi - ys;
    const __m512d r2 = dxx * dxx + dxy * dxy;
    // The scalar loop's tests: r2 inside the support and not zero (NaN kept), wetted, faces.
    unsigned acts = _mm512_mask_cmp_pd_mask(
        _mm512_mask_cmp_pd_mask(listed, r2, support2, _CMP_NGE_UQ), r2, zero, _CMP_NEQ_UQ);
    unsigned wet = 0, ghost = 0;
    for (unsigned l = 0; l < 8; ++l) {
      wet |= static_cast<unsigned>(d.wetted[j[l]] != 0) << l;
      ghost |= static_cast<unsigned>(d.ghost[j[l]] != 0) << l;
    }
    acts &= wet;
    for (unsigned g = acts & ghost; g != 0; g &= g - 1) {
      const unsigned l = static_cast<unsigned>(__builtin_ctz(g));
      const std::uint32_t s = j[l];
      if (!((xi - d.anchor[s].x) * d.normal[s].x + (yi - d.anchor[s].y) * d.normal[s].y > 0.0))
        acts &= ~(1u << l);
    }
    const __mmask8 m = static_cast<__mmask8>(acts);
    const __m512i ks = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(k)), lane);
    _mm512_storeu_si512(c.s + n, _mm512_maskz_compress_epi32(static_cast<__mmask16>(m), j16));
    _mm512_storeu_si512(c.k + n, _mm512_maskz_compress_epi32(static_cast<__mmask16>(m), ks));
    _mm512_storeu_pd(c.dxx + n, _mm512_maskz_compress_pd(m, dxx));
    _mm512_storeu_pd(c.dxy + n, _mm512_maskz_compress_pd(m, dxy));
    _mm512_storeu_pd(c.r2 + n, _mm512_maskz_compress_pd(m, r2));
    _mm512_storeu_pd(c.vxi + n, vxi);
    _mm512_storeu_pd(c.vyi + n, vyi);
    _mm512_storeu_pd(c.rhoi + n, rhoi);
    _mm512_storeu_pd(c.pi + n, pi);
    _mm512_storeu_pd(c.Vi + n, Vis);
    n += static_cast<unsigned>(__builtin_popcount(acts));
  }
  return n;
}
#endif

// Sweep 2: the pairs [0, n) of the chunk, W at a time (the last group's extra lanes repeat
// pair 0, computed and never summed).
template <bool kViscous>
void physics(const ContactLaneData& d, Chunk& c, unsigned n) {
  using V = Lanes::V;
  constexpr unsigned W = Lanes::W;
  for (unsigned l = n; l < n + W; ++l) {
    c.s[l] = c.s[0];
    c.dxx[l] = c.dxx[0];
    c.dxy[l] = c.dxy[0];
    c.r2[l] = c.r2[0];
    c.vxi[l] = c.vxi[0];
    c.vyi[l] = c.vyi[0];
    c.rhoi[l] = c.rhoi[0];
    c.pi[l] = c.pi[0];
    c.Vi[l] = c.Vi[0];
  }
  const V zero = Lanes::splat(0.0);
  const V inv_h = Lanes::splat(d.inv_h), w_factor = Lanes::splat(d.w_factor);
  const V c0 = Lanes::splat(d.c0), omega = Lanes::splat(d.omega);
  const V p_min = Lanes::splat(d.p_min), p_barrier = Lanes::splat(d.p_barrier);
  const V nu = Lanes::splat(d.nu), eta2 = Lanes::splat(d.eta2);
  const bool barrier = d.p_barrier > 0.0;
  for (unsigned e = 0; e < n; e += W) {
    const std::uint32_t* const s = c.s + e;
    V vxs, vys;
    Lanes::load_pairs(&d.vs[0].x, s, vxs, vys);
    const V rhos = Lanes::gather(d.rhos, s), ps = Lanes::gather(d.ps, s);
    const V Vs = Lanes::gather(d.Vs, s);
    V grx = zero, gry = zero;  // g_rel: Vec2{} without the static term
    if (d.hydrostatic) {
      V asx, asy;
      Lanes::load_pairs(&d.as[0].x, s, asx, asy);
      grx = d.gravity.x - asx;
      gry = d.gravity.y - asy;
    }
    const V dxx = Lanes::load(c.dxx + e), dxy = Lanes::load(c.dxy + e);
    const V r2 = Lanes::load(c.r2 + e);
    const V vxi = Lanes::load(c.vxi + e), vyi = Lanes::load(c.vyi + e);
    const V rhoi = Lanes::load(c.rhoi + e), pi = Lanes::load(c.pi + e);
    const V Vi = Lanes::load(c.Vi + e);
    const V r = Lanes::sqrt(r2);
    // Kernel::dw_over_r_as<WendlandC2>: t = std::max(0.0, 1 - q/2).
    const V q = r * inv_h;
    const V u = 1.0 - 0.5 * q;
    const V t = zero < u ? u : zero;
    const V dwr = w_factor * t * t * t;
    // e = dx (-1/r); L = (rho_i, v_i . e, p_i), R = (rho'_s, v_s . e, p'_s).
    const V m_inv_r = -1.0 / r;
    const V ex = m_inv_r * dxx, ey = m_inv_r * dxy;
    const V uL = vxi * ex + vyi * ey;
    const V uR = vxs * ex + vys * ey;
    const V dp_static = 0.5 * (rhoi + rhos) * (grx * dxx + gry * dxy);
    // solve_riemann.
    const V inv_sum = 1.0 / (rhoi + rhos);
    const V du = uL - uR;
    const V du_pos = du < zero ? zero : du;  // std::max(du, 0.0)
    const V om = omega * du_pos;
    const V beta = c0 < om ? c0 : om;  // std::min(om, c0)
    const V su = (rhoi * uL + rhos * uR + (pi - ps - dp_static) / c0) * inv_sum;
    const V sp = (rhos * pi + rhoi * ps) * inv_sum + beta * rhoi * rhos * du * inv_sum;
    // The cavitation limit (contact_pair.h).
    V p_star = sp, u_star = su;
    const auto cav = sp < p_min;
    if (Lanes::any(cav)) {
      const V dpl = pi - p_min;
      const V dpl_pos = dpl < zero ? zero : dpl;  // std::max(L.p - p_min, 0.0)
      const V u_cav = uL + dpl_pos / (rhoi * c0);
      const V u_lim = u_cav < su ? u_cav : su;  // std::min(s.u, u_cav)
      p_star = cav ? p_min : sp;
      u_star = cav ? u_lim : su;
    }
    const V fc = -2.0 * Vi * Vs * p_star * dwr;
    V fx = fc * dxx, fy = fc * dxy;
    // contact_barrier_force: zero (+0) unless the pair is closer than r0.
    V bx = zero, by = zero;
    if (barrier) {
      const auto maybe = ~(8.0 * (r * r) >= 1.000001 * (Vi + Vs));
      if (Lanes::any(maybe)) {
        const V r0 = 0.25 * (Lanes::sqrt(Vi) + Lanes::sqrt(Vs));
        const auto near = maybe & ~(r >= r0);
        if (Lanes::any(near)) {
          const V s2 = (r0 * r0) / (r * r);
          const V phi = s2 * s2 - s2;
          const V bc = 2.0 * Vi * Vs * p_barrier * phi / (r0 * r0 * r0 * r);
          bx = near ? bc * dxx : zero;
          by = near ? bc * dxy : zero;
        }
      }
    }
    fx = fx + bx;
    fy = fy + by;
    const V dr = Vs * (uL - u_star) * (-dwr * r);
    V gx = zero, gy = zero;  // force_viscous: Vec2{} when inviscid
    if constexpr (kViscous) {
      V nsx, nsy;
      Lanes::load_pairs(&d.vs_noslip[0].x, s, nsx, nsy);
      const V coef = Vi * Vs * nu * (rhoi + rhos) * dwr * r2 / (r2 + eta2);
      gx = coef * (vxi - nsx);
      gy = coef * (vyi - nsy);
    }
    Lanes::store(c.tx + e, fx + gx);
    Lanes::store(c.ty + e, fy + gy);
    Lanes::store(c.gx + e, gx);
    Lanes::store(c.gy + e, gy);
    Lanes::store(c.dr + e, dr);
  }
}

// Sweep 3: the chunk's fluid particles ids[0 .. count), each with a list: the scalar loop's
// additions and the kept pair forces.
inline void sums(const ContactLaneData& d, const Chunk& c, const std::uint32_t* ids,
                 unsigned count) {
  for (unsigned p = 0; p < count; ++p) {
    double fx = 0.0, fy = 0.0, drho = 0.0;  // the scalar loop's Vec2 force and drho
    for (unsigned e = c.first[p]; e < c.first[p + 1]; ++e) {
      fx += c.tx[e];
      fy += c.ty[e];
      drho += c.dr[e];
      if (d.keep_total) {
        const std::uint32_t k = c.k[e];
        d.keep_total[k].x = c.tx[e];
        d.keep_total[k].y = c.ty[e];
        d.keep_viscous[k].x = c.gx[e];
        d.keep_viscous[k].y = c.gy[e];
        d.keep_acted[k] = 1;
      }
    }
    const std::uint32_t i = ids[p];
    if (d.momentum) {
      const double m = d.mf[i];
      d.af[i].x += fx / m;
      d.af[i].y += fy / m;
    }
    if (d.continuity) d.drhof[i] += 2.0 * d.rhof[i] * drho;
  }
}

// Fluid particles [i_begin, i_end) up to the first with more than kChunk listed partners:
// chunks of at most kChunk listed (so at most kChunk packed) pairs. Returns that particle (or
// i_end): the caller runs it through the scalar loop. A particle without listed partners is
// skipped as by the scalar loop (its sums untouched, not even += 0).
template <bool kViscous>
std::uint32_t to_fluid(const ContactLaneData& d, std::uint32_t i_begin, std::uint32_t i_end) {
  Chunk c;
  std::uint32_t ids[kChunk];  // the chunk's fluid particles
  unsigned count = 0, n = 0, listed_n = 0;
  c.first[0] = 0;
  const auto run = [&]() {
    if (n > 0) physics<kViscous>(d, c, n);
    sums(d, c, ids, count);
    count = 0;
    n = 0;
    listed_n = 0;
  };
  std::uint32_t i = i_begin;
  for (; i < i_end; ++i) {
    const std::uint32_t listed = d.start[i + 1] - d.start[i];
    if (listed == 0) continue;
    if (listed > kChunk) break;
    if (listed_n + listed > kChunk || count == kChunk) run();
    const double Vi = d.mf[i] / d.rhof[i];  // m_i / rho_i, as the scalar loop
#if defined(__AVX512F__)
    n = pack8(d, c, i, Vi, n);
#else
    n = pack(d, c, i, Vi, n);
#endif
    listed_n += listed;
    ids[count] = i;
    c.first[++count] = n;
  }
  if (count > 0) run();
  return i;
}

}  // namespace

}  // namespace slamsph
