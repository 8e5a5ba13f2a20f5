// Outward surface normals of a solid body's particles, used by the leak counter (spec
// §4, "thin structures"). The normal is the negative gradient of the body's own colour
// function, n_s ∝ -sum_j V_j grad_s W_sj, in the reference configuration; it is zero
// inside the body where the colour gradient vanishes (|sum| h below a threshold).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/cell_grid.h"
#include "core/kernel.h"
#include "core/vec.h"

namespace slamsph {

std::vector<Vec2> reference_surface_normals(const std::vector<Vec2>& X,
                                            const std::vector<double>& V0, const Kernel& kernel);

struct SolidBody;

// New surfaces of a cracked elastic body (spec §5; docs/model.md §4 "Leak counter"): every
// particle of the failure zone (zone[i] = 1: its reference position lies within two kernel
// supports of a failed particle's, coupling/failure_zone_ghosts.h) gets the colour-gradient
// normal of the current configuration, n ∝ −Σ_j V_j ∇W_ij over the body's particles at their
// current positions x with their current volumes V0 det F, written into normals[i] (zero
// inside, the same threshold as the reference normals). Others are left as they are. No-op
// for an empty zone (no particle of the body has failed). `grid` bins body.x with cells of
// at least the body kernel's support.
void update_normals_near_failure(const SolidBody& body, const CellGrid& grid,
                                 std::span<const std::uint8_t> zone, std::span<Vec2> normals);

}  // namespace slamsph
