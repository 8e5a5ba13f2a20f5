// State of the Lagrangian → Eulerian switch of an elastic body (spec §5, paper §3;
// solid/eulerian_failed_interaction.h, docs/model.md §3 "Eulerian switch of failed
// particles"). Derived, not persistent: `switched` is a function of the law's `failed`
// history (checkpointed) and of the reference pairs, so a resumed run rebuilds it, and the
// topology with it, at its first step. Empty (and never looked at again) for a body none of
// whose particles has failed.
#pragma once
#include <cstdint>
#include <vector>

#include "core/cell_grid.h"

namespace slamsph {

struct EulerianState {
  bool active = false;                 // some particle is switched
  std::vector<std::uint8_t> switched;  // 1 = the particle interacts in the current configuration
  std::vector<std::uint32_t> members;  // the switched particles, ascending
  std::size_t failed_count = 0;        // failed particles the set was built from
  NeighbourList reference_pairs;       // the full reference pair list (before any switch)
  // Current pairs with at least one switched particle (rebuilt every sub-step from the
  // current positions): for a switched i all particles within 2h, for an intact i the
  // switched ones. Symmetric: j in pairs(i) <=> i in pairs(j).
  NeighbourList pairs;
  // A_i = V0_i τ_i K_i of every particle (0 for intact ones) at the current sub-step: the map
  // of i's Kirchhoff stress onto its pair forces (eulerian_failed_interaction.h). Scratch.
  std::vector<Mat2> stress_map;
  // Scratch of the pair search (not state).
  CellGrid grid;
  std::vector<Vec2> member_x;
  NeighbourList to_members;
};

}  // namespace slamsph
