#include "core/lattice_stability.h"

#include <cmath>
#include <numbers>

namespace slamsph {

LatticeStability square_lattice_stability(const Kernel& kernel, double dx, int samples) {
  const double support = kernel.support();
  const int n = static_cast<int>(std::ceil(support / dx));
  const double eps = 1e-6 * kernel.h();  // W'' by central differences of W'
  LatticeStability best{-1.0e300, Vec2{}};
  for (int a = 0; a <= samples; ++a) {
    for (int b = 0; b <= samples; ++b) {
      if (a == 0 && b == 0) continue;
      const Vec2 k{std::numbers::pi / dx * a / samples, std::numbers::pi / dx * b / samples};
      const double kn = norm(k);
      const Vec2 t{-k.y / kn, k.x / kn};  // transverse direction
      double lambda = 0.0;
      for (int i = -n; i <= n; ++i) {
        for (int j = -n; j <= n; ++j) {
          const Vec2 R{i * dx, j * dx};
          const double r = norm(R);
          if (r == 0.0 || r >= support) continue;
          const double et = dot(R, t) / r;
          const double w1 = kernel.dw(r);
          const double w2 = (kernel.dw(r + eps) - kernel.dw(r - eps)) / (2.0 * eps);
          lambda += (1.0 - std::cos(dot(k, R))) * (-w2 * et * et - w1 / r * (1.0 - et * et));
        }
      }
      if (lambda > best.lambda) best = {lambda, k};
    }
  }
  return best;
}

bool is_stable(const LatticeStability& s, double dx) {
  return s.lambda * dx * dx * dx * dx <= 1e-5;
}

double nearest_stable_h_over_dx(KernelType type, double h_over_dx) {
  // lambda dx^4 depends on h/dx only; evaluate at dx = 1.
  double best = 0.0;
  for (int k = 120; k <= 200; ++k) {
    const double r = 0.01 * k;
    if (best > 0.0 && std::abs(r - h_over_dx) >= std::abs(best - h_over_dx)) continue;
    if (is_stable(square_lattice_stability(Kernel(type, r), 1.0, 24), 1.0)) best = r;
  }
  return best;
}

double lattice_growth_rate(const LatticeStability& s, double pressure, double dx, double rho) {
  if (s.lambda <= 0.0 || pressure <= 0.0) return 0.0;
  return std::sqrt(2.0 * pressure * dx * dx * s.lambda / rho);
}

}  // namespace slamsph
