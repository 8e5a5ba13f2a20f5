// Polar lattices for curved bodies: a solid disc and an annulus (ring, e.g. a fuselage
// skin), laid out in concentric layers of particles with near-uniform arc spacing.
//
// disc: N = round(R/dx) layers of thickness t = R/N (t = dx when R is a multiple of dx);
//   layer k at radius r_k = (k+½)t with n_k = round(2π r_k/t) particles (n_0 = 3, so no
//   centre particle is needed); the outermost layer's outer edge is exactly R. Each
//   particle of layer k stands for an equal share of the annulus [k t, (k+1) t], so the
//   volumes sum to π R² exactly. Odd layers are rotated by half an arc step.
// ring: `layers` layers of thickness t = (r_out - r_in)/layers, layer k (0 = innermost) at
//   r_in + (k+½)t. For a thin ring (every layer's arc spacing within ±5% of t with one
//   common count n = round(2π r_mid/t)) all layers share n and are radially aligned, a
//   polar grid on which the FPM's 4-neighbour stencil (spec §3) is regular; otherwise
//   n_k = round(2π r_k/t) per layer. Volumes are equal shares of each layer's annulus,
//   summing to π(r_out² - r_in²) exactly.
#pragma once
#include "geometry/particle_lattice.h"

namespace slamsph {

ParticleLattice disc(Vec2 centre, double radius, double dx);
ParticleLattice ring(Vec2 centre, double r_in, double r_out, int layers);

}  // namespace slamsph
