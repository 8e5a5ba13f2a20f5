#include "solid/rigid_motion.h"

#include <algorithm>
#include <cmath>

namespace slamsph {

Vec2 prescribed_velocity(std::span<const PrescribedVelocity> table, double t) {
  if (table.empty()) return {};
  if (t <= table.front().t) return table.front().v;
  if (t >= table.back().t) return table.back().v;
  std::size_t k = 1;
  while (table[k].t < t) ++k;
  const PrescribedVelocity& a = table[k - 1];
  const PrescribedVelocity& b = table[k];
  const double s = b.t > a.t ? (t - a.t) / (b.t - a.t) : 1.0;
  return a.v + s * (b.v - a.v);
}

Vec2 prescribed_displacement(std::span<const PrescribedVelocity> table, double t0, double t1) {
  // Trapezoid rule between consecutive breakpoints inside [t0, t1]: exact for linear pieces.
  Vec2 d;
  double ta = t0;
  Vec2 va = prescribed_velocity(table, t0);
  for (const PrescribedVelocity& p : table) {
    if (p.t <= t0 || p.t >= t1) continue;
    d += (0.5 * (p.t - ta)) * (va + p.v);
    ta = p.t;
    va = p.v;
  }
  d += (0.5 * (t1 - ta)) * (va + prescribed_velocity(table, t1));
  return d;
}

void init_rigid_state(SolidBody& body, double mass_override, double inertia_override) {
  RigidState& r = body.rigid;
  double m = 0.0;
  Vec2 mx;
  for (std::size_t i = 0; i < body.size(); ++i) {
    m += body.m[i];
    mx += body.m[i] * body.X[i];
  }
  r.com0 = m > 0.0 ? mx / m : Vec2{};
  r.com = r.com0;
  double inertia = 0.0;
  for (std::size_t i = 0; i < body.size(); ++i) inertia += body.m[i] * norm2(body.X[i] - r.com0);
  r.mass = m;
  if (mass_override > 0.0) {
    if (m > 0.0) inertia *= mass_override / m;
    r.mass = mass_override;
  }
  r.inertia = inertia_override > 0.0 ? inertia_override : inertia;
  r.angle = 0.0;
}

void place_rigid_particles(SolidBody& body) {
  const RigidState& r = body.rigid;
  const double c = std::cos(r.angle), s = std::sin(r.angle);
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vec2 d = body.X[i] - r.com0;
    const Vec2 arm{c * d.x - s * d.y, s * d.x + c * d.y};
    const Vec2 perp{-arm.y, arm.x};
    body.x[i] = r.com + arm;
    body.v[i] = r.vel + r.omega * perp;
    body.a[i] = r.acc + r.alpha * perp - (r.omega * r.omega) * arm;
  }
}

void advance_rigid(SolidBody& body, double t, double dt, Vec2 gravity) {
  RigidState& r = body.rigid;
  switch (body.kind) {
    case BodyKind::Elastic:
      return;
    case BodyKind::RigidFixed:
      for (std::size_t i = 0; i < body.size(); ++i) {
        body.v[i] = Vec2{};
        body.a[i] = Vec2{};
      }
      r.vel = r.acc = Vec2{};
      r.omega = r.alpha = 0.0;
      return;
    case BodyKind::RigidPrescribed: {
      const Vec2 v0 = prescribed_velocity(body.motion, t);
      const Vec2 v1 = prescribed_velocity(body.motion, t + dt);
      const Vec2 step = prescribed_displacement(body.motion, t, t + dt);
      // Work of the fluid on the driven body (energy balance): the force held over the
      // step times the displacement the body makes; gravity's is the driver's business.
      Vec2 force;
      for (std::size_t i = 0; i < body.size(); ++i) force += body.f_fluid[i];
      body.external_work += dot(force, step);
      r.com += step;
      r.vel = v1;
      r.acc = dt > 0.0 ? (v1 - v0) / dt : Vec2{};
      r.omega = r.alpha = 0.0;
      place_rigid_particles(body);
      return;
    }
    case BodyKind::RigidFree: {
      Vec2 force;
      double torque = 0.0;
      for (std::size_t i = 0; i < body.size(); ++i) {
        force += body.f_fluid[i];
        torque += cross(body.x[i] - r.com, body.f_fluid[i]);
      }
      const Vec2 g = body.feels_gravity ? gravity : Vec2{};
      r.acc = force / r.mass + g;
      r.alpha = r.allow_rotation && r.inertia > 0.0 ? torque / r.inertia : 0.0;
      // Constant acceleration over the step: exact update.
      const Vec2 v0 = r.vel;
      r.vel += dt * r.acc;
      r.com += (0.5 * dt) * (v0 + r.vel);
      const double w0 = r.omega;
      r.omega += dt * r.alpha;
      r.angle += 0.5 * dt * (w0 + r.omega);
      body.external_work +=
          dot(force + r.mass * g, (0.5 * dt) * (v0 + r.vel)) + torque * 0.5 * dt * (w0 + r.omega);
      place_rigid_particles(body);
      return;
    }
  }
}

}  // namespace slamsph
