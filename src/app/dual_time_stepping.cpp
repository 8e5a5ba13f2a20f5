#include "app/dual_time_stepping.h"

#include "coupling/fluid_force_correction.h"
#include "solid/body_dynamics.h"

namespace slamsph {

long DualTimeStepping::advance(std::vector<SolidBody>& bodies, double t, double dt, Vec2 gravity,
                               const Executor& exec) {
  long substeps = 0;
  f_held_.resize(bodies.size());  // reused storage
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    f_held_[b] = bodies[b].f_fluid;
    advance_body(bodies[b], t, dt, gravity, exec);
    if (bodies[b].is_elastic()) substeps += bodies[b].last_substeps;
  }
  return substeps;
}

void DualTimeStepping::correct(std::vector<SolidBody>& bodies, double dt) const {
  for (std::size_t b = 0; b < bodies.size(); ++b)
    correct_for_new_fluid_force(bodies[b], f_held_[b], dt);
}

}  // namespace slamsph
