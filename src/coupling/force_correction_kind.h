// The choice of numerics.fluid_force_correction (docs/case_format.md, docs/model.md §5).
#pragma once

namespace slamsph {

// How a body sub-cycled under the held force F_n receives the rest of the fluid's impulse
// dt/2 (F_n+1 - F_n) (numerics.fluid_force_correction, docs/model.md §5; issue 10):
//   Kick      at once, as a velocity kick at the end of the step (fluid_force_correction.h);
//   None      never (the body receives dt F_n per step: momentum is exchanged exactly only up
//             to dt/2 (F_N - F_0) and the step-size changes; for measurements);
//   NextStep  as a force held over the next fluid step (app/dual_time_stepping.h,
//             SolidBody::impulse_due): exact once the due impulse is counted.
// Rigid bodies and bodies not sub-cycled (global step) always get the kick.
enum class FluidForceCorrection { Kick, None, NextStep };

}  // namespace slamsph
