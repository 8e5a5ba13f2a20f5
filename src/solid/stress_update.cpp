#include "solid/stress_update.h"

#include "core/parallel.h"

namespace slamsph {

void update_stress(SolidBody& body, const Executor& exec) {
  body.P.resize(body.size());
  const SvkParameters p = body.material.svk;
  exec.for_each(body.size(), [&](std::size_t i) { body.P[i] = svk_pk1(p, body.F[i]); });
}

double strain_energy_density(const SolidBody& body, std::size_t i) {
  return svk_strain_energy_density(body.material.svk, body.F[i]);
}

}  // namespace slamsph
