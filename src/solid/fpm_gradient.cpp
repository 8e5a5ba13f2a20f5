#include "solid/fpm_gradient.h"

#include <cmath>
#include <stdexcept>

namespace slamsph {

Mat2 fpm_moment_matrix(Vec2 Xi, std::span<const Vec2> Xj, std::span<const double> w) {
  Mat2 M;
  for (std::size_t k = 0; k < Xj.size(); ++k) {
    const Vec2 d = Xj[k] - Xi;
    M += w[k] * outer(d, d);
  }
  return M;
}

Vec2 fpm_gradient(Vec2 Xi, double fi, std::span<const Vec2> Xj, std::span<const double> fj,
                  std::span<const double> w) {
  const Mat2 M = fpm_moment_matrix(Xi, Xj, w);
  const double scale = trace(M);
  if (!(scale > 0.0) || std::abs(det(M)) <= 1e-12 * scale * scale)
    throw std::invalid_argument("fpm_gradient: degenerate (collinear) neighbour set");
  Vec2 b;
  for (std::size_t k = 0; k < Xj.size(); ++k) b += (w[k] * (fj[k] - fi)) * (Xj[k] - Xi);
  return inverse(M) * b;
}

}  // namespace slamsph
