// Two-lane double vectors (GCC/Clang vector extensions; SSE2 on x86-64, NEON on AArch64) for
// the hot pair loops of the elastic sub-step (solid/elastic_substep.cpp): a Vec2 is one
// register, a Mat2 two column registers. Lane-wise + − × are the scalar IEEE operations in
// the same order, so a loop written with these types rounds exactly as its scalar Vec2 / Mat2
// form (the targets have no fused multiply-add unless the build enables one).
#pragma once
#include <cstring>

#include "core/vec.h"

namespace slamsph::simd {

using v2d = double __attribute__((vector_size(16)));

inline v2d load(const Vec2& a) {
  v2d r;
  std::memcpy(&r, &a, sizeof r);
  return r;
}
inline void store(Vec2& a, v2d v) {
  a = Vec2{v[0], v[1]};
}
inline v2d splat(double s) {
  return v2d{s, s};
}
inline v2d lo(v2d a) {
  return v2d{a[0], a[0]};
}
inline v2d hi(v2d a) {
  return v2d{a[1], a[1]};
}

// A 2x2 matrix by columns: c0 = (xx, yx), c1 = (xy, yy).
struct Cols {
  v2d c0{0.0, 0.0}, c1{0.0, 0.0};
};
inline Cols cols(const Mat2& m) {
  return {v2d{m.xx, m.yx}, v2d{m.xy, m.yy}};
}
inline Mat2 mat(const Cols& m) {
  return {m.c0[0], m.c1[0], m.c0[1], m.c1[1]};
}
// M v with v given as its broadcast components (vx, vx) and (vy, vy): the rounding of
// operator*(Mat2, Vec2).
inline v2d mul(const Cols& m, v2d vx, v2d vy) {
  return m.c0 * vx + m.c1 * vy;
}
// m += a ⊗ b with b given as broadcast components: the rounding of m += outer(a, b).
inline void add_outer(Cols& m, v2d a, v2d bx, v2d by) {
  m.c0 += a * bx;
  m.c1 += a * by;
}

}  // namespace slamsph::simd
