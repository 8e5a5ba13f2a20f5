#include "app/time_step_limit.h"

#include <cmath>
#include <limits>

#include "core/parallel.h"
#include "solid/body_dynamics.h"

namespace slamsph {

std::string describe(const StepLimit& lim, const std::vector<SolidBody>& bodies) {
  switch (lim.limiter) {
    case StepLimiter::None:
      return "none";
    case StepLimiter::FluidAcousticCfl:
      return "fluid acoustic CFL";
    case StepLimiter::FluidAcceleration:
      return "fluid acceleration";
    case StepLimiter::SolidCfl:
      return "solid CFL (body " + (lim.body < bodies.size() ? bodies[lim.body].name : "?") + ")";
    case StepLimiter::EndTimeFraction:
      return "end time / 100";
  }
  return "none";
}

FluidMaxima fluid_maxima(const FluidParticles& fluid, const Executor& exec) {
  return {exec.max_of(
              fluid.size(), [&](std::size_t i) { return norm2(fluid.v[i]); }, 0.0,
              Executor::kMinParallelCheap),
          exec.max_of(
              fluid.size(), [&](std::size_t i) { return norm2(fluid.a[i]); }, 0.0,
              Executor::kMinParallelCheap)};
}

StepLimit choose_time_step(const FluidParticles& fluid, const std::vector<SolidBody>& bodies,
                           const Kernel& kernel_f, const StepLimitParams& prm, const Executor& exec,
                           const FluidMaxima* known) {
  StepLimit lim{std::numeric_limits<double>::infinity(), StepLimiter::None, 0};
  if (fluid.size() > 0) {
    const FluidMaxima m = known ? *known : fluid_maxima(fluid, exec);
    const double vmax = std::sqrt(m.v2);
    const double amax = std::sqrt(m.a2);
    const double h = kernel_f.h();
    lim = {prm.cfl * h / (prm.c0 + vmax), StepLimiter::FluidAcousticCfl, 0};
    if (amax > 0.0 && prm.acceleration_cfl > 0.0) {
      const double dta = prm.acceleration_cfl * std::sqrt(h / amax);
      if (dta < lim.dt) lim = {dta, StepLimiter::FluidAcceleration, 0};
    }
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const double dts = stable_time_step(bodies[b]);
    if (prm.bodies_share_step && dts < lim.dt) lim = {dts, StepLimiter::SolidCfl, b};
  }
  if (!std::isfinite(lim.dt)) lim = {prm.end_time / 100.0, StepLimiter::EndTimeFraction, 0};
  return lim;
}

}  // namespace slamsph
