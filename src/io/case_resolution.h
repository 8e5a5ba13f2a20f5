// Changing the resolution of a resolved case: the fluid spacing becomes `dx` and every
// body's spacing scales by the same ratio (bodies keep their spacing relative to the
// water). Used by `slamsph run --dx`, convergence studies and reduced-size tests.
#pragma once
#include "io/case_config.h"

namespace slamsph {

void rescale_resolution(CaseConfig& cfg, double dx);

}  // namespace slamsph
