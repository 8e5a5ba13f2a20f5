// Where and when particles fail (issue 11; spec §5): after every step the run scans the
// `failed` history field of each body whose material law can fail (Johnson–Cook with a
// failure criterion, solid/materials/johnson_cook.h) and reports the particles that failed
// during the step, once each. The recorder writes them to failure.csv and the first one to
// summary.json.
//
// Angle: of the particle's reference position about the body's reference centre of mass,
// in degrees, 0 at the bottom (−y, the keel of a section entering water from above),
// positive towards +x (counter-clockwise), in (−180, 180].
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "solid/solid_body.h"

namespace slamsph {

class JsonObject;

class FailureLog {
 public:
  // Watches the bodies whose law has a `failed` history field; particles that have
  // failed already (a resumed run) are not reported again.
  void reset(const std::vector<SolidBody>& bodies);
  // Some body's law has a failure criterion (then failure.csv is written).
  bool active() const { return active_; }

  // Rows of failure.csv for the particles that failed since the last scan, in body then
  // particle order; the first row ever is kept as the first failure.
  std::vector<std::vector<double>> scan(const std::vector<SolidBody>& bodies, double time);
  static std::vector<std::string> headers();

  // {"failed_particles": {body: n, ...}, "first": {time_s, body, particle, position_m,
  // part, angle_deg, triaxiality, plastic_strain_rate_per_s} or null}.
  JsonObject summary(const std::vector<SolidBody>& bodies) const;

  // The first failure's row (empty if none yet); checkpointed by the recorder.
  std::vector<double> first;

 private:
  bool active_ = false;
  std::vector<int> failed_slot_;                  // per body: index of `failed`, or -1
  std::vector<Vec2> centre_;                      // per body: reference centre of mass
  std::vector<std::vector<unsigned char>> seen_;  // per body and particle
};

}  // namespace slamsph
