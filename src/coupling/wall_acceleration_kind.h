// The choice of numerics.wall_acceleration (docs/case_format.md, docs/model.md §4).
#pragma once

namespace slamsph {

// Which acceleration of a sub-cycled elastic body the contact's static term uses,
// ρ (g − a)·r in the virtual pressure (Eq. 12) and in the pair's Riemann U* (docs/model.md §4,
// "Wall acceleration of a sub-cycled skin"):
//   BodyMean  the body's mass-weighted mean acceleration over the fluid step, Σ m ā / Σ m
//             (its rigid-body deceleration; default);
//   Local     each particle's own average ā = (v(t+Δt) − v(t))/Δt (issue 9's choice). The
//             fluid then answers the skin's local acceleration one fluid step late: an
//             explicit added-mass feedback that pumps skins lighter than the water they
//             carry (3-layer skin, I-stringer panels);
//   None      gravity only.
// Rigid bodies and bodies that are not sub-cycled always use their own acceleration.
enum class WallAcceleration { BodyMean, Local, None };

}  // namespace slamsph
