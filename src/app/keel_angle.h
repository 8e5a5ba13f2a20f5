// The angle of a point about a section's centre measured from the keel, as the paper's
// skin plots use it (Fig. 25): 0 at −y (the bottom of a section entering from above),
// positive towards +x, in degrees in (−180, 180]. Used by failure.csv (app/failure_log)
// and the skin P_yy profile (app/snapshots, which shifts it to [0, 360)), and summary.json's
// per-part peaks (app/part_peaks), about the body's reference mass centre.
#pragma once
#include <cmath>
#include <numbers>

#include "core/vec.h"
#include "solid/solid_body.h"

namespace slamsph {

inline double keel_angle_deg(Vec2 d) {
  return std::atan2(d.x, -d.y) * 180.0 / std::numbers::pi;
}

// The mass centre of a body's reference configuration (a section's centre for a symmetric
// fuselage), the point keel angles are measured about.
inline Vec2 reference_mass_centre(const SolidBody& body) {
  Vec2 c{};
  double m = 0.0;
  const bool massed = body.m.size() == body.size();  // else equal weights
  for (std::size_t i = 0; i < body.size(); ++i) {
    const double mi = massed ? body.m[i] : 1.0;
    c += mi * body.X[i];
    m += mi;
  }
  return m > 0.0 ? c / m : c;
}

}  // namespace slamsph
