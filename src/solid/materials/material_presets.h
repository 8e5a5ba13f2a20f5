// Shipped materials: complete parameter sets a case file can name with `preset` (the
// paper's Table 1). Plain physics values; the parser fills a material from them and lets
// the case file override any key.
#pragma once
#include <string_view>

#include "solid/materials/material_law.h"

namespace slamsph {

struct JohnsonCookPreset {
  std::string_view name;
  double density = 0.0;         // [kg/m^3]
  double youngs_modulus = 0.0;  // [Pa]
  double poisson_ratio = 0.0;   // [-]
  JohnsonCookModel model;
};

// Al 2024-T3 (paper Table 1 = Johnson & Cook 1983, 1985; spec §3, docs/references.md §8):
// ρ 2700, E 67.5 GPa, ν 0.34, A 265 MPa, B 426 MPa, n 0.34, C 0.015, m 1, c_v 875 J/kgK,
// c 5000 m/s. Not in the paper (spec §3): ε̇0 1/s, T_r 293 K, T_m 775 K, heating fraction
// 0.9; Mie–Grüneisen Γ 2.0, s 1.34 (spec §3 for aluminium); failure D1..D5 = 0.13, 0.13,
// −1.5, 0.011, 0 (Johnson & Cook 1985).
inline constexpr JohnsonCookPreset kAl2024T3{
    "al2024_t3", 2700.0, 67.5e9, 0.34,
    JohnsonCookModel{265e6, 426e6, 0.34, 0.015, 1.0, 1.0, 293.0, 775.0, 293.0, 875.0, 0.9, 5000.0,
                     2.0, 1.34,
                     FailureModel{FailureKind::JohnsonCook, 0.13, 0.13, -1.5, 0.011, 0.0, 0.0}}};

inline constexpr JohnsonCookPreset kJohnsonCookPresets[] = {kAl2024T3};

}  // namespace slamsph
