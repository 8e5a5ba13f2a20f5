// The closed set of material laws a body can use (solid/materials/material_law.h), as a
// variant so the per-particle loops dispatch once per pass, not per particle.
#pragma once
#include <span>
#include <variant>

#include <vector>

#include "solid/materials/j2_linear_hardening.h"
#include "solid/materials/johnson_cook.h"
#include "solid/materials/material_law.h"
#include "solid/materials/st_venant_kirchhoff.h"

namespace slamsph {

using MaterialLaw = std::variant<StVenantKirchhoff, J2LinearHardening, JohnsonCook>;

// The law of `model` with Young's modulus E [Pa] and Poisson's ratio ν [-] (Lamé
// parameters λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)), plane strain) and density ρ0 [kg/m^3]
// (used by the Johnson–Cook law's equation of state and heating; throws
// std::invalid_argument if a Johnson–Cook law gets ρ0 <= 0).
MaterialLaw make_material_law(const MaterialModel& model, double youngs_modulus,
                              double poisson_ratio, double density = 0.0);

// The history fields the law declares.
std::span<const HistoryField> history_fields(const MaterialLaw& law);

// The virgin history of one particle, one value per field (the declared initial values
// unless the law's parameters set them).
std::vector<double> initial_history(const MaterialLaw& law);

}  // namespace slamsph
