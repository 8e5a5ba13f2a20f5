// Per-part results of a run (issue 10 item 1): for every part of every elastic body
// (a fuselage's skin, stringers, floor, columns; a one-part body has the part "body"), the
// largest equivalent strain reached during the run, when and where. Equivalent strain is
// the von Mises equivalent of the plane-strain Green–Lagrange strain,
// sqrt(2/3 dev(E):dev(E)) (solid/materials/st_venant_kirchhoff.h), the quantity the
// paper's strain snapshots show. Sampled after every fluid step, like the force peak.
// summary.json lists, per body, the part table (id, name, particle count) with these peaks.
#pragma once
#include <cstddef>
#include <vector>

#include "solid/solid_body.h"

namespace slamsph {

class JsonObject;

class PartPeaks {
 public:
  // Sizes the table for the bodies' parts; all peaks zero. A resumed run restores `state`.
  void reset(const std::vector<SolidBody>& bodies);
  // Scans every elastic body's particles at time t and keeps each part's maximum.
  void update(const std::vector<SolidBody>& bodies, double time);
  // Per body: {"body", "parts": [{"id", "name", "particles", "peak_equivalent_strain",
  // "peak_time_s", "peak_particle", "peak_position_m"}]}; bodies without F (rigid) list
  // their parts without peaks.
  std::vector<JsonObject> summary(const std::vector<SolidBody>& bodies) const;

  // Flattened per body, per part: strain, time, particle, x, y (checkpointed).
  std::vector<double> state;

 private:
  static constexpr std::size_t kFields = 5;
  std::vector<std::size_t> offset_;  // per body: first part's slot in `state`
};

}  // namespace slamsph
