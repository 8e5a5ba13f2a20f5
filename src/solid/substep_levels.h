// Level structure of a body's pair graph for the wavefront schedule of the elastic sub-step
// (solid/elastic_substep.cpp, docs/validation.md "Solid sub-step"): the particles grouped by
// their breadth-first distance, in pairs, from a pseudo-peripheral particle of each connected
// part (George & Liu's heuristic: the last particle reached from the part's first one), so
// that every pair joins particles of the same or of adjacent levels. Sub-step s + 1 of a level
// then depends on sub-step s of that level and its two neighbours only, whatever the band of
// the stored order (a ring stored along a Hilbert curve pairs particles up to 70 % of the
// body apart in memory, but its levels are the ring's cross-sections, ~2 × the layers).
// Scratch of the sub-step: derived from the pair list, kept across calls while it is
// unchanged, never state.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/cell_grid.h"

namespace slamsph {

struct SubstepLevels {
  std::vector<std::uint32_t> order;  // the particles level by level, each level by index
  std::vector<std::uint32_t> start;  // level l is order[start[l], start[l + 1])
  std::vector<std::uint32_t> slot;   // particle i is order[slot[i]]
  std::vector<double> work;          // Σ (1 + pairs) over levels [0, l), levels + 1 entries
  std::size_t widest = 0;            // particles of the largest level
  bool ok = false;                   // every pair joins the same or adjacent levels
  // The pair list the levels were built from.
  std::vector<std::uint32_t> key_start, key_index;

  std::size_t levels() const { return start.empty() ? 0 : start.size() - 1; }
};

// Builds `lv` from `pairs` (a symmetric CSR pair list), unless it was built from the same
// list; consecutive levels are merged while the merged level has fewer than `min_level`
// particles (the merged levels keep the adjacency property: a pair joins particles at most
// one level apart before, so at most one merged level apart after).
void update_substep_levels(const NeighbourList& pairs, std::size_t min_level, SubstepLevels& lv);

}  // namespace slamsph
