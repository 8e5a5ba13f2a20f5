#include "solid/reference_gradients.h"

#include <algorithm>

#include "core/parallel.h"
#include "solid/correction_matrix.h"
#include "solid/fpm_neighbour_selection.h"
#include "solid/fpm_weight.h"
#include "solid/symmetric_pairs.h"

namespace slamsph {
namespace {

void reverse_of_symmetric(const NeighbourList& pairs, std::vector<std::uint32_t>& reverse) {
  reverse.assign(pairs.index.size(), 0);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    for (std::uint32_t k = pairs.start[i]; k < pairs.start[i + 1]; ++k) {
      const std::uint32_t j = pairs.index[k];
      const auto b = pairs.index.begin() + pairs.start[j];
      const auto e = pairs.index.begin() + pairs.start[j + 1];
      reverse[k] = static_cast<std::uint32_t>(std::lower_bound(b, e, i) - pairs.index.begin());
    }
}

}  // namespace

void build_reference_operators(SolidBody& body, const Executor& exec) {
  const std::size_t n = body.size();
  std::vector<std::uint8_t> use;
  std::vector<Vec2> raw;
  if (body.scheme == SolidScheme::TlSfpm) {
    select_fpm_sets(body.X, body.dx, exec, body.fpm_sets);
    symmetric_union(body.fpm_sets, body.pairs, body.pair_reverse, use);
    raw.resize(body.pairs.index.size());
    exec.for_each(n, [&](std::size_t i) {
      for (std::uint32_t k = body.pairs.start[i]; k < body.pairs.start[i + 1]; ++k)
        raw[k] = fpm_reference_gradient(body.X[i], body.X[body.pairs.index[k]], body.dx);
    });
  } else {
    body.fpm_sets = NeighbourList{};
    CellGrid grid;
    grid.build(body.X, body.kernel.support());
    build_neighbour_list(body.X, body.X, grid, body.kernel.support(), true, exec, body.pairs);
    sort_each_list(body.pairs, exec);  // reverse_of_symmetric searches sorted lists
    reverse_of_symmetric(body.pairs, body.pair_reverse);
    use.assign(body.pairs.index.size(), 1);
    raw.resize(body.pairs.index.size());
    exec.for_each(n, [&](std::size_t i) {
      for (std::uint32_t k = body.pairs.start[i]; k < body.pairs.start[i + 1]; ++k) {
        const Vec2 rij = body.X[i] - body.X[body.pairs.index[k]];
        raw[k] = body.kernel.dw_over_r(norm(rij)) * rij;
      }
    });
  }
  compute_correction_matrices(body.X, body.V0, body.pairs, raw, use, exec, body.B);
  body.grad0.assign(body.pairs.index.size(), Vec2{});
  exec.for_each(n, [&](std::size_t i) {
    for (std::uint32_t k = body.pairs.start[i]; k < body.pairs.start[i + 1]; ++k)
      if (use[k]) body.grad0[k] = body.V0[body.pairs.index[k]] * (body.B[i] * raw[k]);
  });
}

}  // namespace slamsph
