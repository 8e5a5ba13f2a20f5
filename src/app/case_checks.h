// Checks that refuse a case before the run (exit 2, "<file>:<line>: <key>: ...") for what
// the parser cannot see in one key: the size of the problem (particle count and memory,
// neighbour-search cells), and, once the particles are built, bodies without particles,
// bodies overlapping each other, and materials too stiff for the fluid time step.
#pragma once
#include "app/fsi_stepper.h"
#include "io/case_config.h"

namespace slamsph {

// Default of `--max-particles`: about 10 GB of state at ~1 kB per particle.
inline constexpr double kDefaultMaxParticles = 1e7;
// Most solid sub-steps a fluid step may need (dual time stepping), or time steps a run may
// need without fluid or dual time stepping, before the case is refused as too stiff.
inline constexpr double kMaxSubsteps = 1e4;
inline constexpr double kMaxSteps = 1e9;
// Most neighbour-search cells the particles' bounding box and the domain may span.
inline constexpr double kMaxGridCells = 1e8;

// Particles the case will create, estimated from areas (fluid blocks, shapes) and spacings.
double estimate_particles(const CaseConfig& cfg);

// Before building: the estimated particle count against `max_particles`, the cells of the
// neighbour-search grid over the particles' bounding box and over the domain.
void check_case_size(const CaseConfig& cfg, double max_particles);

// After building, before the first step: every body has particles, no two bodies overlap,
// no elastic body needs more than kMaxSubsteps solid sub-steps per fluid step.
void check_built_case(const CaseConfig& cfg, const FsiSystem& sys);

}  // namespace slamsph
