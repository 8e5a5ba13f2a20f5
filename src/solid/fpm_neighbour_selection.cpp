#include "solid/fpm_neighbour_selection.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/parallel.h"
#include "solid/fpm_weight.h"

namespace slamsph {
namespace {

constexpr double kCandidateRadius = 2.5;  // [dx]
constexpr double kCentroidRadius = 1.5;   // [dx]
constexpr double kBoundaryShift = 0.25;   // [dx]
constexpr double kMinEigenRatio = 0.05;

double eigen_ratio(const Mat2& M) {
  const double tr = trace(M), d = det(M);
  const double disc = std::sqrt(std::max(0.0, 0.25 * tr * tr - d));
  const double lmax = 0.5 * tr + disc, lmin = 0.5 * tr - disc;
  return lmax > 0.0 ? lmin / lmax : 0.0;
}

// Chosen set of particle i (indices), built from its distance-sorted candidates.
std::vector<std::uint32_t> choose(Vec2 Xi, std::span<const Vec2> X, double dx,
                                  const std::vector<std::pair<double, std::uint32_t>>& cand) {
  Vec2 centroid;
  int n_close = 0;
  for (const auto& [r, j] : cand) {
    if (r >= kCentroidRadius * dx) break;
    centroid += X[j] - Xi;
    ++n_close;
  }
  if (n_close > 0) centroid = centroid / static_cast<double>(n_close);
  const bool boundary = n_close == 0 || norm(centroid) > kBoundaryShift * dx;
  std::size_t k = boundary ? 3 : 4;
  std::vector<std::uint32_t> set;
  Mat2 M;
  for (std::size_t c = 0; c < cand.size(); ++c) {
    const std::uint32_t j = cand[c].second;
    const Vec2 d = X[j] - Xi;
    set.push_back(j);
    M += fpm_weight(cand[c].first, dx) * outer(d, d);
    if (set.size() >= k && eigen_ratio(M) >= kMinEigenRatio) return set;
  }
  return {};
}

}  // namespace

void select_fpm_sets(std::span<const Vec2> X, double dx, const Executor& exec,
                     NeighbourList& sets) {
  const std::vector<double> spacing(X.size(), dx);
  select_fpm_sets(X, spacing, exec, sets);
}

void select_fpm_sets(std::span<const Vec2> X, std::span<const double> spacing, const Executor& exec,
                     NeighbourList& sets) {
  const std::size_t n = X.size();
  if (spacing.size() != n)
    throw std::invalid_argument("select_fpm_sets: one spacing per particle expected");
  double dmax = 0.0;
  for (double d : spacing) dmax = std::max(dmax, d);
  CellGrid grid;
  grid.build(X, kCandidateRadius * dmax);
  std::vector<std::vector<std::uint32_t>> chosen(n);
  exec.for_each(n, [&](std::size_t i) {
    const double dx = spacing[i];
    const double radius = kCandidateRadius * dx;
    std::vector<std::pair<double, std::uint32_t>> cand;
    grid.for_each_candidate(X[i], [&](std::uint32_t j) {
      if (j == i) return;
      const double r = norm(X[j] - X[i]);
      if (r < radius) cand.emplace_back(r, j);
    });
    std::sort(cand.begin(), cand.end());
    chosen[i] = choose(X[i], X, dx, cand);  // empty on failure (no throw inside the loop)
    std::sort(chosen[i].begin(), chosen[i].end());
  });
  for (std::size_t i = 0; i < n; ++i)
    if (chosen[i].empty())
      throw std::invalid_argument("select_fpm_sets: particle " + std::to_string(i) + " at (" +
                                  std::to_string(X[i].x) + ", " + std::to_string(X[i].y) +
                                  ") has no non-collinear neighbour set");
  sets.start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) sets.start[i + 1] = sets.start[i] + chosen[i].size();
  sets.index.clear();
  sets.index.reserve(sets.start[n]);
  for (std::size_t i = 0; i < n; ++i)
    sets.index.insert(sets.index.end(), chosen[i].begin(), chosen[i].end());
}

}  // namespace slamsph
