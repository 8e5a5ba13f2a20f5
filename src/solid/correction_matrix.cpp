#include "solid/correction_matrix.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/parallel.h"

namespace slamsph {

void compute_correction_matrices(std::span<const Vec2> X, std::span<const double> V0,
                                 const NeighbourList& pairs, std::span<const Vec2> raw_grad,
                                 std::span<const std::uint8_t> use, const Executor& exec,
                                 std::vector<Mat2>& B) {
  const std::size_t n = pairs.size();
  B.assign(n, Mat2{});
  std::vector<std::uint8_t> bad(n, 0);
  exec.for_each(n, [&](std::size_t i) {
    Mat2 A;
    for (std::uint32_t k = pairs.start[i]; k < pairs.start[i + 1]; ++k) {
      if (!use[k]) continue;
      const std::uint32_t j = pairs.index[k];
      A += V0[j] * outer(X[j] - X[i], raw_grad[k]);
    }
    const double s = std::abs(A.xx) + std::abs(A.yy) + std::abs(A.xy) + std::abs(A.yx);
    if (!(s > 0.0) || std::abs(det(A)) <= 1e-10 * s * s) {
      bad[i] = 1;
      return;
    }
    B[i] = inverse(A);
  });
  for (std::size_t i = 0; i < n; ++i)
    if (bad[i])
      throw std::invalid_argument("correction matrix (Eq. 11) singular at particle " +
                                  std::to_string(i));
}

}  // namespace slamsph
