#include "coupling/substep_average.h"

namespace slamsph {

void SubstepAverage::begin(const SolidBody& body) {
  x0 = body.x;
  v0 = body.v;
  valid = false;
}

void SubstepAverage::end(const SolidBody& body, double dt) {
  const std::size_t n = body.size();
  v_mean.resize(n);
  a_mean.resize(n);
  const double inv_dt = 1.0 / dt;
  for (std::size_t i = 0; i < n; ++i) {
    v_mean[i] = (body.x[i] - x0[i]) * inv_dt;
    a_mean[i] = (body.v[i] - v0[i]) * inv_dt;
  }
  // The body's momentum change over the step per unit mass (clamped particles included:
  // their share is zero or prescribed).
  double mass = 0.0;
  Vec2 ma;
  for (std::size_t i = 0; i < n; ++i) mass += body.m[i], ma += body.m[i] * a_mean[i];
  a_body = mass > 0.0 ? (1.0 / mass) * ma : Vec2{};
  valid = dt > 0.0;
}

void apply_substep_average(ContactParticles& contact, const ContactLayout& layout, std::size_t b,
                           const SubstepAverage& avg, WallAcceleration wall) {
  if (!avg.valid) return;
  const std::size_t o = layout.offset[b];
  for (std::size_t i = 0; i < avg.v_mean.size(); ++i) {
    contact.v[o + i] = avg.v_mean[i];
    contact.a[o + i] = wall == WallAcceleration::Local      ? avg.a_mean[i]
                       : wall == WallAcceleration::BodyMean ? avg.a_body
                                                            : Vec2{};
  }
  for (std::size_t g = 0; g < layout.ghosts.size(); ++g) {
    const ContactGhost& gh = layout.ghosts[g];
    if (gh.body != b) continue;
    const std::size_t c = layout.first_ghost() + g, parent = o + gh.spec.parent;
    contact.v[c] = contact.v[parent];
    contact.a[c] = contact.a[parent];
  }
}

}  // namespace slamsph
