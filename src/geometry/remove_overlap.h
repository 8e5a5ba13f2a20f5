// Initial-condition clean-up where a body is immersed in (or touches) a fluid block:
// drop the fluid particles closer than `gap` to any body particle, typically
// gap = ½(dx_fluid + dx_solid) so the fluid starts one half-spacing off the body surface.
#pragma once
#include <cstddef>
#include <vector>

#include "core/vec.h"

namespace slamsph {

// Indices (ascending) of the fluid particles whose distance to every solid particle is
// >= gap. Uses a cell list, O(N_fluid + N_solid).
std::vector<std::size_t> remove_overlap(const std::vector<Vec2>& fluid,
                                        const std::vector<Vec2>& solid, double gap);

}  // namespace slamsph
