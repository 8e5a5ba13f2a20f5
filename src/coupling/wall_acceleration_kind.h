// The choice of numerics.wall_acceleration (docs/case_format.md, docs/model.md §4).
#pragma once

namespace slamsph {

// Which acceleration of an elastic body the contact's static term uses,
// ρ (g − a)·r in the virtual pressure (Eq. 12) and in the pair's Riemann U* (docs/model.md §4,
// "Wall acceleration of a sub-cycled skin"):
//   BodyMean  the body's mass-weighted mean acceleration, Σ m ā / Σ m over the fluid step
//             (its rigid-body deceleration; default);
//   Local     each particle's own: with dual time stepping its average over the fluid step
//             ā = (v(t+Δt) − v(t))/Δt (issue 9's choice), else its last acceleration. The
//             fluid then answers the skin's local acceleration one fluid step late: an
//             explicit added-mass feedback that pumps skins lighter than the water they
//             carry (3-layer skin, I-stringer panels);
//   None      gravity only.
// Rigid bodies always use their own acceleration (coupling/wall_acceleration.h).
enum class WallAcceleration { BodyMean, Local, None };

}  // namespace slamsph
