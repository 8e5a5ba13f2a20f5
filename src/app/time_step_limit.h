// The choice of the fluid step Δt (spec §2, §3, §6) and which criterion set it. The
// criterion is a typed value; its text is only for messages.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/kernel.h"
#include "fluid/fluid_particles.h"
#include "solid/solid_body.h"

namespace slamsph {

class Executor;

enum class StepLimiter {
  None,               // nothing limits (not yet chosen)
  FluidAcousticCfl,   // CFL h / (c0 + max|v|) (spec §2)
  FluidAcceleration,  // acceleration_cfl sqrt(h / max|a|), 0.25 by default
  SolidCfl,           // a body's stable step, when bodies share the fluid step (spec §3, §6)
  EndTimeFraction,    // nothing moves: end time / 100
};
inline constexpr std::size_t kStepLimiterCount = 5;  // the enumerators above

struct StepLimit {
  double dt = 0.0;
  StepLimiter limiter = StepLimiter::None;
  std::size_t body = 0;  // SolidCfl: the limiting body
};

// "fluid acoustic CFL", "fluid acceleration", "solid CFL (body NAME)", "end time / 100", "none".
std::string describe(const StepLimit& lim, const std::vector<SolidBody>& bodies);
inline bool limited_by_fluid(StepLimiter l) {
  return l == StepLimiter::FluidAcousticCfl || l == StepLimiter::FluidAcceleration;
}

struct StepLimitParams {
  double cfl = 0.25;               // fluid acoustic CFL number [-]
  double acceleration_cfl = 0.25;  // factor of the bound sqrt(h / max|a|); 0 switches it off [-]
  double c0 = 0.0;                 // artificial sound speed [m/s]
  double end_time = 0.0;           // [s]
  bool bodies_share_step = false;  // false under dual time stepping (app/dual_time_stepping.h)
};

// What the fluid criteria read from the particles: max |v|² and max |a|² [m²/s², m²/s⁴].
struct FluidMaxima {
  double v2 = 0.0;
  double a2 = 0.0;
};
FluidMaxima fluid_maxima(const FluidParticles& fluid, const Executor& exec);

// The smallest of the criteria above; the first one found wins ties. `known`: the fluid's
// maxima as a sweep over the current v and a already found them (the integrator's last sweep,
// app/fsi_stepper.cpp; maxima are exact in any order, so the step is the same), else
// fluid_maxima() is called.
StepLimit choose_time_step(const FluidParticles& fluid, const std::vector<SolidBody>& bodies,
                           const Kernel& kernel_f, const StepLimitParams& prm, const Executor& exec,
                           const FluidMaxima* known = nullptr);

}  // namespace slamsph
