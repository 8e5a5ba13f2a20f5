// Makes the fluid–solid momentum exchange exact under dual time stepping (spec §6).
// A body is advanced over [t_n, t_n+dt] holding the fluid force F_n of the last
// evaluation (its sub-steps may be many). The fluid, integrated kick–drift–kick, receives
// -dt/2 (F_n + F_n+1) over the same step. After F_n+1 is known, this correction kicks the
// body by dt/2 (F_n+1 - F_n), so it receives exactly dt/2 (F_n + F_n+1): for a body
// without sub-cycling this is identical to kick–drift–kick, and total linear momentum of
// fluid plus free bodies is conserved to round-off.
#pragma once
#include <vector>

#include "core/vec.h"
#include "coupling/force_correction_kind.h"
#include "solid/solid_body.h"

namespace slamsph {

// f_old: the per-particle fluid force the body was advanced with; body.f_fluid holds the new.
void correct_for_new_fluid_force(SolidBody& body, const std::vector<Vec2>& f_old, double dt);

}  // namespace slamsph
