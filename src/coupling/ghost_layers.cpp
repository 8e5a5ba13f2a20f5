#include "coupling/ghost_layers.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slamsph {

GhostDepths ghost_depths(double d, double support, double ghost_spacing) {
  GhostDepths g;
  g.layers = static_cast<int>(std::ceil(support / d - 1e-9));
  g.cell = std::max(1, static_cast<int>(std::floor(ghost_spacing / d + 1e-9)));
  return g;
}

int layers_behind(const CellGrid& grid, std::span<const Vec2> pts, Vec2 x, Vec2 n, double d,
                  int K) {
  auto occupied = [&](Vec2 p) {
    bool found = false;
    grid.for_each_candidate(p, [&](std::uint32_t j) {
      if (norm2(pts[j] - p) < 0.5625 * d * d) found = true;  // within 0.75 d
    });
    return found;
  };
  int present = 0;
  while (present < K && occupied(x - (present + 1) * d * n)) ++present;
  return present;
}

std::vector<GhostSpec> plan_ghost_layers(const std::vector<Vec2>& X,
                                         const std::vector<Vec2>& normals,
                                         std::span<const double> spacing, double support,
                                         double ghost_spacing) {
  std::vector<GhostSpec> out;
  if (X.empty()) return out;
  if (spacing.size() != X.size())
    throw std::invalid_argument("plan_ghost_layers: one spacing per particle expected");
  // Cells as large as the coarsest probe radius (0.75 d_max) so the 3x3 search sees it.
  double dmax = 0.0;
  for (double d : spacing) dmax = std::max(dmax, d);
  CellGrid grid;
  grid.build(X, dmax);
  for (std::size_t i = 0; i < X.size(); ++i) {
    const Vec2 n = normals[i];
    if (norm2(n) == 0.0) continue;
    const double d = spacing[i];
    const GhostDepths g = ghost_depths(d, support, ghost_spacing);
    const int present = layers_behind(grid, X, X[i], n, d, g.layers);
    // Cells of m layers from the back face (present + 1/2) d until K d is covered; with
    // m = 1 the depths are present + 1 ... K exactly.
    for (int j = 0; j < g.cells(present); ++j)
      out.push_back({static_cast<std::uint32_t>(i), g.depth(present, j), g.weight(present, j)});
  }
  return out;
}

std::vector<GhostSpec> plan_ghost_layers(const std::vector<Vec2>& X,
                                         const std::vector<Vec2>& normals, double d, double support,
                                         double ghost_spacing) {
  const std::vector<double> spacing(X.size(), d);
  return plan_ghost_layers(X, normals, spacing, support, ghost_spacing);
}

}  // namespace slamsph
