// The angle of a point about a section's centre measured from the keel, as the paper's
// skin plots use it (Fig. 25): 0 at −y (the bottom of a section entering from above),
// positive towards +x, in degrees in (−180, 180]. Used by failure.csv (app/failure_log)
// and the skin P_yy profile (app/snapshots, which shifts it to [0, 360)).
#pragma once
#include <cmath>
#include <numbers>

#include "core/vec.h"

namespace slamsph {

inline double keel_angle_deg(Vec2 d) {
  return std::atan2(d.x, -d.y) * 180.0 / std::numbers::pi;
}

}  // namespace slamsph
