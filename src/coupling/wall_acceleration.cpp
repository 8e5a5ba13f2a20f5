#include "coupling/wall_acceleration.h"

namespace slamsph {

void apply_wall_acceleration(ContactParticles& contact, const ContactLayout& layout, std::size_t b,
                             const SolidBody& body, WallAcceleration wall) {
  if (!body.is_elastic() || wall == WallAcceleration::Local) return;
  const std::size_t o = layout.offset[b], n = body.size();
  Vec2 a;
  if (wall == WallAcceleration::BodyMean) {
    // The body's momentum change per unit mass (clamped particles included: their share is
    // zero or prescribed).
    double mass = 0.0;
    Vec2 ma;
    for (std::size_t i = 0; i < n; ++i) mass += body.m[i], ma += body.m[i] * contact.a[o + i];
    if (mass > 0.0) a = (1.0 / mass) * ma;
  }
  for (std::size_t i = 0; i < n; ++i) contact.a[o + i] = a;
  for (std::size_t g = 0; g < layout.ghosts.size(); ++g)
    if (layout.ghosts[g].body == b) contact.a[layout.first_ghost() + g] = a;
}

}  // namespace slamsph
