#include "coupling/fluid_force_correction.h"

namespace slamsph {

void correct_for_new_fluid_force(SolidBody& body, const std::vector<Vec2>& f_old, double dt) {
  const double half = 0.5 * dt;
  switch (body.kind) {
    case BodyKind::RigidFixed:
    case BodyKind::RigidPrescribed:
      return;
    case BodyKind::Elastic:
      for (std::size_t i = 0; i < body.size(); ++i) {
        if (body.clamped[i]) continue;
        body.v[i] += (half / body.m[i]) * (body.f_fluid[i] - f_old[i]);
      }
      return;
    case BodyKind::RigidFree: {
      RigidState& r = body.rigid;
      Vec2 df;
      double dtorque = 0.0;
      for (std::size_t i = 0; i < body.size(); ++i) {
        const Vec2 d = body.f_fluid[i] - f_old[i];
        df += d;
        dtorque += cross(body.x[i] - r.com, d);
      }
      r.vel += (half / r.mass) * df;
      if (r.allow_rotation && r.inertia > 0.0) r.omega += half * dtorque / r.inertia;
      for (std::size_t i = 0; i < body.size(); ++i) {
        const Vec2 arm = body.x[i] - r.com;
        body.v[i] = r.vel + r.omega * Vec2{-arm.y, arm.x};
      }
      return;
    }
  }
}

}  // namespace slamsph
