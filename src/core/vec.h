// Small fixed-size 2D vector and 2x2 matrix types used everywhere (plane strain, 2D flow).
#pragma once
#include <cmath>

namespace slamsph {

struct Vec2 {
  double x = 0.0, y = 0.0;
  constexpr Vec2() = default;
  constexpr Vec2(double x_, double y_) : x(x_), y(y_) {}
  constexpr Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }
  constexpr Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }
  constexpr Vec2& operator*=(double s) {
    x *= s;
    y *= s;
    return *this;
  }
};
constexpr Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.y + b.y};
}
constexpr Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
constexpr Vec2 operator-(Vec2 a) {
  return {-a.x, -a.y};
}
constexpr Vec2 operator*(double s, Vec2 a) {
  return {s * a.x, s * a.y};
}
constexpr Vec2 operator*(Vec2 a, double s) {
  return {s * a.x, s * a.y};
}
constexpr Vec2 operator/(Vec2 a, double s) {
  return {a.x / s, a.y / s};
}
constexpr double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.y * b.y;
}
constexpr double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}
constexpr double norm2(Vec2 a) {
  return dot(a, a);
}
inline double norm(Vec2 a) {
  return std::sqrt(norm2(a));
}

// Row-major 2x2 matrix [[xx, xy], [yx, yy]].
struct Mat2 {
  double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;
  static constexpr Mat2 identity() { return {1.0, 0.0, 0.0, 1.0}; }
  constexpr Mat2& operator+=(const Mat2& o) {
    xx += o.xx;
    xy += o.xy;
    yx += o.yx;
    yy += o.yy;
    return *this;
  }
  constexpr Mat2& operator-=(const Mat2& o) {
    xx -= o.xx;
    xy -= o.xy;
    yx -= o.yx;
    yy -= o.yy;
    return *this;
  }
  constexpr Mat2& operator*=(double s) {
    xx *= s;
    xy *= s;
    yx *= s;
    yy *= s;
    return *this;
  }
};
constexpr Mat2 operator+(Mat2 a, const Mat2& b) {
  return a += b;
}
constexpr Mat2 operator-(Mat2 a, const Mat2& b) {
  return a -= b;
}
constexpr Mat2 operator*(double s, Mat2 a) {
  return a *= s;
}
constexpr Mat2 operator*(const Mat2& a, const Mat2& b) {
  return {a.xx * b.xx + a.xy * b.yx, a.xx * b.xy + a.xy * b.yy, a.yx * b.xx + a.yy * b.yx,
          a.yx * b.xy + a.yy * b.yy};
}
constexpr Vec2 operator*(const Mat2& a, Vec2 v) {
  return {a.xx * v.x + a.xy * v.y, a.yx * v.x + a.yy * v.y};
}
// Outer product a ⊗ b: (a ⊗ b)_kl = a_k b_l.
constexpr Mat2 outer(Vec2 a, Vec2 b) {
  return {a.x * b.x, a.x * b.y, a.y * b.x, a.y * b.y};
}
constexpr Mat2 transpose(const Mat2& a) {
  return {a.xx, a.yx, a.xy, a.yy};
}
constexpr double trace(const Mat2& a) {
  return a.xx + a.yy;
}
constexpr double det(const Mat2& a) {
  return a.xx * a.yy - a.xy * a.yx;
}
constexpr double ddot(const Mat2& a, const Mat2& b) {
  return a.xx * b.xx + a.xy * b.xy + a.yx * b.yx + a.yy * b.yy;
}
// Inverse; the caller guarantees det != 0 (checked where matrices are built).
constexpr Mat2 inverse(const Mat2& a) {
  const double d = det(a);
  return {a.yy / d, -a.xy / d, -a.yx / d, a.xx / d};
}

}  // namespace slamsph
