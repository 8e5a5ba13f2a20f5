#include "solid/materials/material_law_choice.h"

#include <stdexcept>

namespace slamsph {

MaterialLaw make_material_law(const MaterialModel& model, double youngs_modulus,
                              double poisson_ratio, double density) {
  const SvkParameters lame = svk_from_young(youngs_modulus, poisson_ratio);
  if (const auto* j2 = std::get_if<J2LinearHardeningModel>(&model))
    return J2LinearHardening(
        J2Parameters{lame.lambda, lame.mu, j2->yield_stress, j2->hardening_modulus});
  if (const auto* jc = std::get_if<JohnsonCookModel>(&model)) {
    if (!(density > 0.0))
      throw std::invalid_argument("the johnson_cook law needs a positive density");
    return JohnsonCook(JohnsonCookParameters{lame.mu, density, *jc});
  }
  return StVenantKirchhoff(lame);
}

std::span<const HistoryField> history_fields(const MaterialLaw& law) {
  return std::visit([](const auto& l) { return std::span<const HistoryField>(l.kHistory); }, law);
}

std::vector<double> initial_history(const MaterialLaw& law) {
  return std::visit(
      [](const auto& l) {
        std::vector<double> h;
        if constexpr (requires { l.initial_history(); }) {
          const auto a = l.initial_history();
          h.assign(a.begin(), a.end());
        } else {
          for (const HistoryField& f : l.kHistory) h.push_back(f.initial);
        }
        return h;
      },
      law);
}

}  // namespace slamsph
