#include "solid/materials/johnson_cook_failure.h"

#include <algorithm>
#include <cmath>

namespace slamsph {

double johnson_cook_failure_strain(const FailureModel& m, double triaxiality, double rate_ratio,
                                   double homologous_temperature) {
  const double ef = (m.d1 + m.d2 * std::exp(m.d3 * triaxiality)) *
                    (1.0 + m.d4 * std::log(std::max(rate_ratio, 1.0))) *
                    (1.0 + m.d5 * homologous_temperature);
  return std::max(ef, 1e-12);
}

double damage_increment(const FailureModel& m, double plastic_increment, double triaxiality,
                        double rate_ratio, double homologous_temperature) {
  switch (m.kind) {
    case FailureKind::JohnsonCook:
      return plastic_increment /
             johnson_cook_failure_strain(m, triaxiality, rate_ratio, homologous_temperature);
    case FailureKind::CriticalPlasticStrain:
      return plastic_increment / m.critical_plastic_strain;
    case FailureKind::None:
      break;
  }
  return 0.0;
}

}  // namespace slamsph
