#include "geometry/polar_lattice.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace slamsph {

namespace {

constexpr double kPi = std::numbers::pi;

// One layer of n particles at radius r covering the annulus [r_lo, r_hi].
void add_layer(ParticleLattice& out, Vec2 c, double r, double r_lo, double r_hi, long n,
               double phase, int layer) {
  const double v = kPi * (r_hi * r_hi - r_lo * r_lo) / static_cast<double>(n);
  const double step = 2.0 * kPi / static_cast<double>(n);
  for (long i = 0; i < n; ++i) {
    const double a = (static_cast<double>(i) + phase) * step;
    out.add({c.x + r * std::cos(a), c.y + r * std::sin(a)}, v, layer);
  }
}

long arc_count(double r, double t) {
  return std::max(3L, std::lround(2.0 * kPi * r / t));
}

}  // namespace

ParticleLattice disc(Vec2 centre, double radius, double dx) {
  if (!(radius > 0.0) || !(dx > 0.0)) throw std::invalid_argument("disc: radius, dx must be > 0");
  const long nl = std::max(1L, std::lround(radius / dx));
  const double t = radius / static_cast<double>(nl);
  ParticleLattice out;
  for (long k = 0; k < nl; ++k) {
    const double r = (static_cast<double>(k) + 0.5) * t;
    const double r_hi = (k + 1 == nl) ? radius : static_cast<double>(k + 1) * t;
    add_layer(out, centre, r, static_cast<double>(k) * t, r_hi, arc_count(r, t),
              (k % 2) ? 0.5 : 0.0, static_cast<int>(k));
  }
  return out;
}

ParticleLattice ring(Vec2 centre, double r_in, double r_out, int layers) {
  if (!(r_in >= 0.0) || !(r_out > r_in) || layers < 1)
    throw std::invalid_argument("ring: need 0 <= r_in < r_out and layers >= 1");
  const double t = (r_out - r_in) / layers;
  auto radius = [&](int k) { return r_in + (k + 0.5) * t; };
  // Common count for thin rings (radially aligned polar grid).
  const long n_common = arc_count(0.5 * (r_in + r_out), t);
  bool aligned = true;
  for (int k = 0; k < layers; ++k) {
    const double s = 2.0 * kPi * radius(k) / static_cast<double>(n_common);
    if (std::abs(s - t) > 0.05 * t) aligned = false;
  }
  ParticleLattice out;
  for (int k = 0; k < layers; ++k) {
    const double r_lo = (k == 0) ? r_in : r_in + k * t;
    const double r_hi = (k + 1 == layers) ? r_out : r_in + (k + 1) * t;
    const long n = aligned ? n_common : arc_count(radius(k), t);
    add_layer(out, centre, radius(k), r_lo, r_hi, n, (!aligned && k % 2) ? 0.5 : 0.0, k);
  }
  return out;
}

}  // namespace slamsph
