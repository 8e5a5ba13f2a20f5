#include "geometry/remove_overlap.h"

#include <stdexcept>

#include "core/cell_grid.h"

namespace slamsph {

std::vector<std::size_t> remove_overlap(const std::vector<Vec2>& fluid,
                                        const std::vector<Vec2>& solid, double gap) {
  std::vector<std::size_t> kept;
  kept.reserve(fluid.size());
  if (solid.empty() || !(gap > 0.0)) {
    for (std::size_t i = 0; i < fluid.size(); ++i) kept.push_back(i);
    return kept;
  }
  CellGrid grid;
  grid.build(solid, gap);
  const double gap2 = gap * gap;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    bool overlap = false;
    grid.for_each_candidate(fluid[i], [&](std::uint32_t j) {
      if (norm2(fluid[i] - solid[j]) < gap2) overlap = true;
    });
    if (!overlap) kept.push_back(i);
  }
  return kept;
}

}  // namespace slamsph
