// Failure strain of the Johnson–Cook (1985, Eng. Fract. Mech. 21:31) damage model (spec §5):
//
//   ε_f = [D1 + D2 exp(D3 σ*)] [1 + D4 ln ε̇*] [1 + D5 T*]
//
// σ* = mean stress / von Mises stress (the stress triaxiality), ε̇* = ε̇p/ε̇0 taken ≥ 1 (as in
// the flow stress: no rate term below the reference rate), T* the homologous temperature.
// Damage D = Σ Δε̄p / ε_f; the particle fails at D = 1. For Al 2024-T3 (D1..D5 = 0.13, 0.13,
// −1.5, 0.011, 0): ε_f = 0.26 at σ* = 0 and 0.209 in uniaxial tension (σ* = 1/3).
#pragma once
#include "solid/materials/material_law.h"

namespace slamsph {

// ε_f of the Johnson–Cook model (m.kind must be FailureKind::JohnsonCook) [-]; never below
// a tiny positive floor, so a large triaxiality with D1 < 0 fails at once instead of dividing
// by a negative strain.
double johnson_cook_failure_strain(const FailureModel& m, double triaxiality, double rate_ratio,
                                   double homologous_temperature);

// Damage increment of a plastic increment Δε̄p under the current state [-]: Δε̄p/ε_f for the
// Johnson–Cook model, Δε̄p/ε_c for a critical plastic strain, 0 without failure.
double damage_increment(const FailureModel& m, double plastic_increment, double triaxiality,
                        double rate_ratio, double homologous_temperature);

}  // namespace slamsph
