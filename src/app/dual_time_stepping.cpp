#include "app/dual_time_stepping.h"

#include "coupling/fluid_force_correction.h"
#include "solid/body_dynamics.h"

namespace slamsph {

bool DualTimeStepping::corrects_later(const SolidBody& body) const {
  return subcycled_ && body.is_elastic() && correction_ != FluidForceCorrection::Kick;
}

long DualTimeStepping::advance(std::vector<SolidBody>& bodies, double t, double dt, Vec2 gravity,
                               bool subcycled, const Executor& exec) {
  subcycled_ = subcycled;
  long substeps = 0;
  f_held_.resize(bodies.size());  // reused storage
  received_.assign(bodies.size(), Vec2{});
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    SolidBody& body = bodies[b];
    f_held_[b] = body.f_fluid;
    // NextStep: the impulse still due from the last step is held as a force over this one
    // (its work is then counted with the fluid's, force times drift, by the sub-steps).
    const bool deliver = corrects_later(body) && correction_ == FluidForceCorrection::NextStep;
    if (deliver) {
      body.impulse_due.resize(body.size());
      for (std::size_t i = 0; i < body.size(); ++i) {
        body.f_fluid[i] += (1.0 / dt) * body.impulse_due[i];
        body.impulse_due[i] = Vec2{};
      }
    }
    Vec2 held;  // the force the body is advanced with, held over the step
    for (const Vec2& f : body.f_fluid) held += f;
    received_[b] = dt * held;
    advance_body(body, t, dt, gravity, exec);
    if (deliver) body.f_fluid = f_held_[b];
    if (body.is_elastic()) substeps += body.last_substeps;
  }
  return substeps;
}

void DualTimeStepping::correct(std::vector<SolidBody>& bodies, double dt) {
  const double half = 0.5 * dt;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    SolidBody& body = bodies[b];
    // The particles no integrator moves: their support takes dt/2 (F_n+1 - F_n) as given.
    const bool supported =
        body.kind == BodyKind::RigidFixed || body.kind == BodyKind::RigidPrescribed;
    Vec2 held_by_support;
    for (std::size_t i = 0; i < body.size(); ++i)
      if (supported || (body.is_elastic() && body.clamped[i]))
        held_by_support += half * (body.f_fluid[i] - f_held_[b][i]);
    received_[b] += held_by_support;
    if (!corrects_later(body)) {
      // The kick, measured on the body as the momentum it added.
      const Vec2 vel0 = body.rigid.vel;
      if (body.is_elastic()) v_before_.assign(body.v.begin(), body.v.end());
      correct_for_new_fluid_force(body, f_held_[b], dt);
      if (body.kind == BodyKind::RigidFree)
        received_[b] += body.rigid.mass * (body.rigid.vel - vel0);
      if (body.is_elastic())
        for (std::size_t i = 0; i < body.size(); ++i)
          if (!body.clamped[i]) received_[b] += body.m[i] * (body.v[i] - v_before_[i]);
    } else if (correction_ == FluidForceCorrection::NextStep) {
      body.impulse_due.resize(body.size());
      for (std::size_t i = 0; i < body.size(); ++i)
        if (!body.clamped[i]) body.impulse_due[i] += half * (body.f_fluid[i] - f_held_[b][i]);
    }
  }
}

}  // namespace slamsph
