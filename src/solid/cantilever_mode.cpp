#include "solid/cantilever_mode.h"

#include <cmath>

namespace slamsph {

double cantilever_mode_velocity(double s, double length, double vf, double c0) {
  if (s <= 0.0) return 0.0;
  const double kl = 1.875;
  const double k = kl / length;
  const double M = std::sin(kl) + std::sinh(kl);
  const double N = std::cos(kl) + std::cosh(kl);
  const double Q = 2.0 * (std::cos(kl) * std::sinh(kl) - std::sin(kl) * std::cosh(kl));
  const double ks = k * s;
  return vf * c0 * (M * (std::cos(ks) - std::cosh(ks)) - N * (std::sin(ks) - std::sinh(ks))) / Q;
}

double bulk_sound_speed(double youngs_modulus, double poisson_ratio, double density) {
  return std::sqrt(youngs_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)) / density);
}

}  // namespace slamsph
