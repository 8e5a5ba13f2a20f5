// The contact's fluid-side loop in four AVX2 lanes (coupling/contact_pair_lanes.h). This file
// alone is compiled with -mavx2 -ffp-contract=off (CMakeLists.txt). So that no AVX2 code reaches
// the rest of the program through the linker's choice among copies of an inline function, it
// calls no inline function of a project or standard header — only the AVX intrinsics, which are
// always inlined — and keeps everything else in an anonymous namespace (the test
// contact_avx2_object_defines_only_its_functions, tests/CMakeLists.txt, checks the object's
// symbols; tests/unit/test_coupling_contact_lanes.cpp the sums).
#include "coupling/contact_pair_lanes.h"

#if defined(__AVX2__)
#include <immintrin.h>

namespace slamsph {

namespace {

struct Lanes {
  static constexpr unsigned W = 4;
  using V = __m256d;  // GCC/Clang vector type: + − × / act lane-wise as the scalar IEEE ops
  static V splat(double s) { return _mm256_set1_pd(s); }
  static V load(const double* p) { return _mm256_load_pd(p); }
  static void store(double* p, V v) { _mm256_store_pd(p, v); }
  static V sqrt(V v) { return _mm256_sqrt_pd(v); }
  // Whether any lane of a comparison's result is set.
  template <class M>
  static bool any(M m) {
    return _mm256_movemask_pd(_mm256_castsi256_pd((__m256i)m)) != 0;
  }
  // The four doubles a[j[l]].
  static V gather(const double* a, const std::uint32_t* j) {
    return _mm256_set_pd(a[j[3]], a[j[2]], a[j[1]], a[j[0]]);
  }
  // The (x, y) of the four Vec2 a[j[l]] (as doubles from a) -> the x lanes and the y lanes.
  static void load_pairs(const double* a, const std::uint32_t* j, V& xs, V& ys) {
    const V a02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a + 2 * j[0])),
                                       _mm_loadu_pd(a + 2 * j[2]), 1);
    const V a13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a + 2 * j[1])),
                                       _mm_loadu_pd(a + 2 * j[3]), 1);
    xs = _mm256_unpacklo_pd(a02, a13);
    ys = _mm256_unpackhi_pd(a02, a13);
  }
};

}  // namespace

}  // namespace slamsph

#include "coupling/contact_pair_lanes_body.h"

namespace slamsph {

bool contact_lanes_avx2_available() {
  return __builtin_cpu_supports("avx2");
}

std::uint32_t contact_to_fluid_avx2(const ContactLaneData& d, std::uint32_t i_begin,
                                    std::uint32_t i_end) {
  return d.viscous ? to_fluid<true>(d, i_begin, i_end) : to_fluid<false>(d, i_begin, i_end);
}

}  // namespace slamsph

#else  // not an x86-64 build with -mavx2: the scalar loop runs

namespace slamsph {

bool contact_lanes_avx2_available() {
  return false;
}

std::uint32_t contact_to_fluid_avx2(const ContactLaneData&, std::uint32_t, std::uint32_t i_end) {
  return i_end;
}

}  // namespace slamsph

#endif
