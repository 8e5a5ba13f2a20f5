// Outward surface normals of a solid body's particles, used by the leak counter (spec
// §4, "thin structures"). The normal is the negative gradient of the body's own colour
// function, n_s ∝ -sum_j V_j grad_s W_sj, in the reference configuration; it is zero
// inside the body where the colour gradient vanishes (|sum| h below a threshold).
#pragma once
#include <vector>

#include "core/kernel.h"
#include "core/vec.h"

namespace slamsph {

std::vector<Vec2> reference_surface_normals(const std::vector<Vec2>& X,
                                            const std::vector<double>& V0, const Kernel& kernel);

}  // namespace slamsph
