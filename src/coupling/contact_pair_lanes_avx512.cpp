// The contact's fluid-side loop in eight AVX-512F lanes (coupling/contact_pair_lanes.h). This file
// alone is compiled with -mavx512f -ffp-contract=off (CMakeLists.txt). So that no AVX-512 code
// reaches the rest of the program through the linker's choice among copies of an inline function,
// it calls no inline function of a project or standard header — only the AVX-512 intrinsics, which
// are always inlined — and keeps everything else in an anonymous namespace (the test
// contact_avx512_object_defines_only_its_functions, tests/CMakeLists.txt, checks the object's
// symbols; tests/unit/test_coupling_contact_lanes.cpp the sums).
#include "coupling/contact_pair_lanes.h"

#if defined(__AVX512F__)
// GCC 12's AVX-512 headers start the result of a zero-masked intrinsic from an undefined
// vector (`__Y = __Y`), which -Wmaybe-uninitialized reports as a read of an uninitialised value.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>

namespace slamsph {

namespace {

struct Lanes {
  static constexpr unsigned W = 8;
  using V = __m512d;  // GCC/Clang vector type: + − × / act lane-wise as the scalar IEEE ops
  static V splat(double s) { return _mm512_set1_pd(s); }
  static V load(const double* p) { return _mm512_load_pd(p); }
  static void store(double* p, V v) { _mm512_store_pd(p, v); }
  static V sqrt(V v) { return _mm512_sqrt_pd(v); }
  // Whether any lane of a comparison's result is set.
  template <class M>
  static bool any(M m) {
    const __m512i bits = (__m512i)m;
    return _mm512_test_epi64_mask(bits, bits) != 0;
  }
  // The eight doubles a[j[l]] (plain loads: vgatherdpd is slow on Zen 4).
  static V gather(const double* a, const std::uint32_t* j) {
    return _mm512_set_pd(a[j[7]], a[j[6]], a[j[5]], a[j[4]], a[j[3]], a[j[2]], a[j[1]], a[j[0]]);
  }
  // The (x, y) of the eight Vec2 a[j[l]] (as doubles from a) -> the x lanes and the y lanes.
  static void load_pairs(const double* a, const std::uint32_t* j, V& xs, V& ys) {
    const auto two = [a, j](int l, int m) {
      return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a + 2 * j[l])),
                                  _mm_loadu_pd(a + 2 * j[m]), 1);
    };
    const V even = _mm512_insertf64x4(_mm512_castpd256_pd512(two(0, 2)), two(4, 6), 1);
    const V odd = _mm512_insertf64x4(_mm512_castpd256_pd512(two(1, 3)), two(5, 7), 1);
    xs = _mm512_unpacklo_pd(even, odd);
    ys = _mm512_unpackhi_pd(even, odd);
  }
};

}  // namespace

}  // namespace slamsph

#include "coupling/contact_pair_lanes_body.h"

namespace slamsph {

bool contact_lanes_avx512_available() {
  return __builtin_cpu_supports("avx512f");
}

std::uint32_t contact_to_fluid_avx512(const ContactLaneData& d, std::uint32_t i_begin,
                                      std::uint32_t i_end) {
  return d.viscous ? to_fluid<true>(d, i_begin, i_end) : to_fluid<false>(d, i_begin, i_end);
}

}  // namespace slamsph

#else  // not an x86-64 build with -mavx512f: the four-lane or the scalar loop runs

namespace slamsph {

bool contact_lanes_avx512_available() {
  return false;
}

std::uint32_t contact_to_fluid_avx512(const ContactLaneData&, std::uint32_t, std::uint32_t i_end) {
  return i_end;
}

}  // namespace slamsph

#endif
