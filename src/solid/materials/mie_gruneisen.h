// Mie–Grüneisen equation of state with a linear U_s–u_p Hugoniot (spec §3), the volumetric
// part of the Johnson–Cook solid (solid/materials/johnson_cook.h):
//
//   η = ρ/ρ0 − 1 = 1/J − 1
//   p = (1 − Γη/2) p_H + Γ ρ e,   p_H = ρ0 c² η (1 + η) / (1 − (s − 1) η)²   (η > 0, compression)
//   p = ρ0 c² η + Γ ρ e                                                     (η ≤ 0, tension)
//
// e is the specific internal energy above the initial state [J/kg]; the Johnson–Cook law
// passes the heat of plastic work, c_v (T − T0). The tension branch is linear as the spec
// asks; both branches have the slope ρ0 c² at η = 0, so the bulk modulus is K = ρ0 c².
#pragma once

namespace slamsph {

struct MieGruneisenParameters {
  double rho0 = 0.0;   // reference density [kg/m^3]
  double c = 0.0;      // bulk sound speed [m/s]
  double gamma = 0.0;  // Grüneisen coefficient Γ [-]
  double s = 0.0;      // Hugoniot slope [-]
};

// Pressure at the volume ratio J = det F [-] and specific internal energy e [J/kg] [Pa].
double mie_gruneisen_pressure(const MieGruneisenParameters& p, double J, double e);

// Cold-curve (e = 0) energy per reference volume, −∫_1^J p(J', 0) dJ' [J/m^3]; with
// `compression_only` the tension branch carries no pressure (a failed particle).
double mie_gruneisen_cold_energy(const MieGruneisenParameters& p, double J,
                                 bool compression_only = false);

}  // namespace slamsph
