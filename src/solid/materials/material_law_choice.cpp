#include "solid/materials/material_law_choice.h"

namespace slamsph {

MaterialLaw make_material_law(const MaterialModel& model, double youngs_modulus,
                              double poisson_ratio) {
  const SvkParameters lame = svk_from_young(youngs_modulus, poisson_ratio);
  if (const auto* j2 = std::get_if<J2LinearHardeningModel>(&model))
    return J2LinearHardening(
        J2Parameters{lame.lambda, lame.mu, j2->yield_stress, j2->hardening_modulus});
  return StVenantKirchhoff(lame);
}

std::span<const HistoryField> history_fields(const MaterialLaw& law) {
  return std::visit([](const auto& l) { return std::span<const HistoryField>(l.kHistory); }, law);
}

}  // namespace slamsph
