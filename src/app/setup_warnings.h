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
std::vector<std::string> setup_warnings(const CaseConfig& cfg);

}  // namespace slamsph
