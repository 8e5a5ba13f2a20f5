// Initial velocity of the first bending mode of a clamped–free plate (validation README §5,
// Gray, Monaghan & Swift 2001):
//   v_y(s) = V_f c0 [M (cos ks − cosh ks) − N (sin ks − sinh ks)] / Q,  kL = 1.875,
//   M = sin kL + sinh kL,  N = cos kL + cosh kL,  Q = 2 (cos kL sinh kL − sin kL cosh kL),
// s measured from the clamp edge, L the free length, c0 = sqrt(K/ρ), K = E / (3(1 − 2ν)).
// At the free end the bracket divided by Q is 1, so the tip starts at V_f c0.
#pragma once

namespace slamsph {

// v_y at distance s from the clamp edge (0 for s <= 0).
double cantilever_mode_velocity(double s, double length, double vf, double c0);

// c0 = sqrt(K/ρ) with the 3D bulk modulus K = E / (3(1 − 2ν)).
double bulk_sound_speed(double youngs_modulus, double poisson_ratio, double density);

}  // namespace slamsph
