// Comparison of a finished run with the reference numbers of ../shared/validation
// (README §1 cylinder entry), for the case kinds that have one (output.plot).
#pragma once
#include <vector>

#include "core/vec.h"
#include "io/case_config.h"
#include "io/json_writer.h"
#include "solid/solid_body.h"

namespace slamsph {

struct ForceHistory {
  std::vector<double> time;               // [s]
  std::vector<std::vector<Vec2>> force;   // per time, per body [N/m]
};

// Fills `out` and returns true if the case has a validation target.
bool validation_report(const CaseConfig& cfg, const std::vector<SolidBody>& bodies,
                       const ForceHistory& history, JsonObject& out);

// Index of the body the cylinder-entry validation looks at: the first body that is not
// rigid_fixed (the tank); -1 if none.
int entry_body_index(const CaseConfig& cfg);

}  // namespace slamsph
