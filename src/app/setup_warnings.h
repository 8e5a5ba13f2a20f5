// Warnings about a valid but questionable set-up, printed by `slamsph check` and `run`
// before any computation. They never stop a run.
#pragma once
#include <string>
#include <vector>

#include "io/case_config.h"

namespace slamsph {

// A fluid block at rest on the square lattice whose zig-zag mode is unstable under its
// hydrostatic pressure (core/lattice_stability.h) for more than ~10 e-folding times of
// the run: the still water would start to move.
//
// Water at rest next to a body 3 or more times finer than the water (spacing ratio
// numerics.dx / body dx >= 3) with numerics.h_over_dx below 1.5: the fine wall's lattice
// residual pushes the marginally stable square lattice over (docs/model.md §4, "Bodies
// finer than the water": still water at h = 1.38 dx reached 18 % (r = 3) and 33 % (r = 4)
// of sqrt(gH); at h = 1.5 dx at most 2.2 % up to r = 8).
//
// A ring with explicit `layers` whose particle spacing t/layers differs from the body's dx
// (which sets its smoothing length) by more than 25 %.
std::vector<std::string> setup_warnings(const CaseConfig& cfg);

}  // namespace slamsph
