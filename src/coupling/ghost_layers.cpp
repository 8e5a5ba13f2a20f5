#include "coupling/ghost_layers.h"

#include <cmath>

#include "core/cell_grid.h"

namespace slamsph {

std::vector<GhostSpec> plan_ghost_layers(const std::vector<Vec2>& X,
                                         const std::vector<Vec2>& normals, double d,
                                         double support) {
  std::vector<GhostSpec> out;
  if (X.empty()) return out;
  const int K = static_cast<int>(std::ceil(support / d - 1e-9));
  CellGrid grid;
  grid.build(X, d);
  auto occupied = [&](Vec2 p) {
    bool found = false;
    grid.for_each_candidate(p, [&](std::uint32_t j) {
      if (norm2(X[j] - p) < 0.5625 * d * d)
        found = true;  // within 0.75 d: tolerant of offset ring layers
    });
    return found;
  };
  for (std::size_t i = 0; i < X.size(); ++i) {
    const Vec2 n = normals[i];
    if (norm2(n) == 0.0) continue;
    int present = 0;
    while (present < K && occupied(X[i] - (present + 1) * d * n)) ++present;
    for (int k = present + 1; k <= K; ++k) out.push_back({static_cast<std::uint32_t>(i), k});
  }
  return out;
}

}  // namespace slamsph
