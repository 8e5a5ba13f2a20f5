// Linear stability of a fluid at rest on a square particle lattice (docs/model.md §2,
// "Lattice stability").
//
// Under a uniform pressure p every GSPH pair pushes its particles apart with
// f(r) = -2 p V^2 W'(r) (p* = p at rest, spec §2). Displacing the particles by
// u e^{i k.x} changes the force on a particle by m u'' = 2 p V^2 D(k) u with
//   D(k) = sum_R (1 - cos k.R) [ -W''(r) e e^T - W'(r)/r (I - e e^T) ],  r = |R|, e = R/r,
// summed over the lattice vectors R inside the support. The second term is destabilising
// (a repulsion turned sideways pushes further sideways). Compressive modes are held by the
// equation of state, transverse ones (u perpendicular to k) only by D: if t^T D t > 0 for
// some k the lattice is unstable and the mode grows at sigma = sqrt(2 p V lambda / rho).
// For Wendland C2 the square lattice is unstable at h/dx = 1.3 (lambda peaks at the
// zig-zag mode k = (0, pi/dx), columns sliding past each other) and stable near 1.38.
#pragma once
#include "core/kernel.h"
#include "core/vec.h"

namespace slamsph {

struct LatticeStability {
  double lambda = 0.0;  // largest transverse eigenvalue of D [1/m^4] (> 0: unstable)
  Vec2 wavevector;      // where it occurs [1/m], in [0, pi/dx]^2
};

// Scans k over [0, pi/dx]^2 with `samples` points per axis.
LatticeStability square_lattice_stability(const Kernel& kernel, double dx, int samples = 48);

// True if no transverse mode gains energy: lambda dx^4 <= 1e-5 (the long waves are neutral,
// lambda -> 0, so an exact zero is out of reach of the k scan).
bool is_stable(const LatticeStability& s, double dx);

// The stable h/dx closest to `h_over_dx` on a 0.01 grid in [1.2, 2] (fewer neighbours cost
// accuracy) for this kernel type; 0 if there is none.
double nearest_stable_h_over_dx(KernelType type, double h_over_dx);

// e-folding rate of the most unstable mode under pressure p [1/s]; 0 if stable.
double lattice_growth_rate(const LatticeStability& s, double pressure, double dx, double rho);

}  // namespace slamsph
