// Dual time stepping (spec §6): the bodies advance over the fluid step [t_n, t_n + Δt]
// holding the fluid force F_n of the last evaluation, each elastic body sub-cycled by its
// own stable step (solid/body_dynamics.h: n = ceil(Δt / Δt_s) equal sub-steps); after the
// fluid pass gives F_n+1, each body is kicked by Δt/2 (F_n+1 - F_n)
// (coupling/fluid_force_correction.h), so it receives exactly the impulse the fluid gave
// up. numerics.fluid_force_correction can instead give a sub-cycled elastic body that impulse
// as a force held over the next fluid step ("next_step", through SolidBody::impulse_due) or
// not at all ("none"); coupling/force_correction_kind.h, docs/model.md §5. With the switch off (or
// no fluid to sub-cycle within) the bodies' stable steps join the fluid step's limit
// (app/time_step_limit.h) and every body takes one step per fluid step: the global-step scheme.
//
// Each step it also tells the fluid's impulse each body received (the momentum balance,
// README "Momentum balance"): dt times the force the body was advanced with (Σ f_fluid, with
// the due impulse NextStep delivers), plus the kick as measured on the body, Σ m Δv over the
// particles it moves (a rigid_free body: M Δv of its centre). What no integrator moves — a
// fixed or prescribed body, a clamped particle — is held by its support, which takes the
// water's force as the water gave it: dt/2 (F_n+1 − F_n) of those particles is added as it is.
#pragma once
#include <vector>

#include "core/vec.h"
#include "coupling/force_correction_kind.h"
#include "solid/solid_body.h"

namespace slamsph {

class Executor;

class DualTimeStepping {
 public:
  DualTimeStepping(bool enabled, FluidForceCorrection correction)
      : enabled_(enabled), correction_(correction) {}

  // Whether the bodies' stable steps limit the fluid step (no sub-cycling).
  bool bodies_share_step(std::size_t fluid_particles) const {
    return !enabled_ || fluid_particles == 0;
  }
  // Advances every body over [t, t + dt] with its current f_fluid held (remembered for
  // correct()), plus the impulse still due to it (NextStep); `subcycled` is
  // !bodies_share_step(). Returns the number of elastic sub-steps taken.
  long advance(std::vector<SolidBody>& bodies, double t, double dt, Vec2 gravity, bool subcycled,
               const Executor& exec);
  // After the bodies' f_fluid was replaced by the new evaluation.
  void correct(std::vector<SolidBody>& bodies, double dt);
  // The fluid impulse body b received over the last advance() and correct() [N s/m].
  Vec2 received(std::size_t b) const { return received_[b]; }

 private:
  bool enabled_;
  std::vector<std::vector<Vec2>> f_held_;  // the fluid force each body was advanced with
  FluidForceCorrection correction_;
  bool subcycled_ = false;      // of the last advance()
  std::vector<Vec2> received_;  // per body, see received()
  std::vector<Vec2> v_before_;  // scratch: velocities before the kick
  // Whether `body` gets its correction later or never rather than as the kick.
  bool corrects_later(const SolidBody& body) const;
};

}  // namespace slamsph
