#include "io/case_resolution.h"

namespace slamsph {

void rescale_resolution(CaseConfig& cfg, double dx) {
  const double ratio = dx / cfg.numerics.dx;
  cfg.numerics.dx = dx;
  for (BodyConfig& b : cfg.bodies) b.dx *= ratio;
}

}  // namespace slamsph
