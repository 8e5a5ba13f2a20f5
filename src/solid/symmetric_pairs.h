// Symmetric pair list for the TL force sum (spec §3): the union of per-particle gradient
// sets, pairs(i) = S_i ∪ {j : i ∈ S_j}, so j ∈ pairs(i) ⇔ i ∈ pairs(j) and the pairwise
// force conserves linear momentum to round-off. Also returns, per pair k = (i, j), the
// position of (j, i) in j's list and whether j belongs to i's own set S_i.
#pragma once
#include <cstdint>
#include <vector>

#include "core/cell_grid.h"

namespace slamsph {

void symmetric_union(const NeighbourList& sets, NeighbourList& pairs,
                     std::vector<std::uint32_t>& reverse, std::vector<std::uint8_t>& in_own_set);

}  // namespace slamsph
