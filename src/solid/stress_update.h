// First Piola–Kirchhoff stress of every particle from its deformation gradient, through the
// body's material law (spec §3). Only St Venant–Kirchhoff ("svk") exists so far; a
// Johnson–Cook law would add its own state and a branch here.
#pragma once

#include "solid/solid_body.h"

namespace slamsph {

class Executor;

void update_stress(SolidBody& body, const Executor& exec);

// Strain energy per unit reference volume of particle i [J/m^3].
double strain_energy_density(const SolidBody& body, std::size_t i);

}  // namespace slamsph
