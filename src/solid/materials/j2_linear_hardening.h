// J2 (von Mises) plasticity with linear isotropic hardening in plane strain (spec §3 names a
// plastic law as the next material; docs/model.md §3 "J2 plasticity" has the derivation).
//
// Kinematics: multiplicative, F = Fe Fp, with a Hencky (logarithmic) elastic energy and the
// exponential-map radial return of Simo (1992, CMAME 99:61; Simo & Hughes 1998, Box 9.1).
// Per update, with Cp⁻¹ = (Fpᵀ Fp)⁻¹ and ε̄p the committed history:
//   b_e,tr = F Cp⁻¹ Fᵀ                            (trial elastic left Cauchy–Green; the zz
//                                                  entry is Cp⁻¹_zz since F_zz = 1)
//   ε_tr   = ½ ln b_e,tr = Σ_a ε_a n_a ⊗ n_a       (principal logarithmic strains, a = 1..3)
//   τ_tr   = λ tr(ε_tr) 1 + 2μ ε_tr,  s_tr = dev τ_tr,  q_tr = sqrt(3/2 s_tr : s_tr)
//   f      = q_tr − (σ_y + H ε̄p)
//   if f > 0:  Δε̄ = f / (3μ + H),  s = (1 − 3μ Δε̄ / q_tr) s_tr,
//              ε_e = ε_tr − Δε̄ (3/2) s_tr / q_tr,  ε̄p += Δε̄
//   τ = tr-part + s (Kirchhoff stress),  P = τ F⁻ᵀ,  Cp⁻¹ ← F⁻¹ exp(2 ε_e) F⁻ᵀ.
// The return is exact for linear hardening whenever the principal axes of the trial strain
// do not rotate (uniaxial strain, any step size); plastic flow is isochoric (det Fp = 1).
// The update uses neither F_old nor dt (the model is rate independent and Cp⁻¹ carries the
// history in the reference frame); the interface passes them for laws that need them.
//
// History (per particle): Cp⁻¹ as xx, xy, yy, zz (symmetric, plane strain: no xz, yz) and
// the equivalent plastic strain ε̄p.
#pragma once
#include <array>
#include <span>

#include "core/vec.h"
#include "solid/materials/material_law.h"

namespace slamsph {

struct J2Parameters {
  double lambda = 0.0;             // first Lamé parameter [Pa]
  double mu = 0.0;                 // shear modulus [Pa]
  double yield_stress = 0.0;       // σ_y [Pa]
  double hardening_modulus = 0.0;  // H [Pa]
};

// Kirchhoff stress in plane strain: in-plane tensor and the zz component [Pa].
struct PlaneKirchhoff {
  Mat2 in_plane;
  double zz = 0.0;
};

class J2LinearHardening {
 public:
  enum Slot { kCpInvXX, kCpInvXY, kCpInvYY, kCpInvZZ, kPlasticStrain, kSlots };
  static constexpr std::array<HistoryField, kSlots> kHistory{{
      {"plastic_metric_xx", "-", 1.0, false},  // Cp⁻¹ components
      {"plastic_metric_xy", "-", 0.0, false},
      {"plastic_metric_yy", "-", 1.0, false},
      {"plastic_metric_zz", "-", 1.0, false},
      {"equivalent_plastic_strain", "-", 0.0, true},
  }};

  explicit J2LinearHardening(J2Parameters p) : p_(p) {}
  const J2Parameters& parameters() const { return p_; }

  Mat2 update(const Mat2& F_old, const Mat2& F_new, double dt, std::span<double> history) const;
  double cauchy_zz(const Mat2& F, std::span<const double> history) const;
  double energy_density(const Mat2& F, std::span<const double> history) const;

  // Kirchhoff stress of the committed state at F (no return mapping), for tests and output.
  PlaneKirchhoff elastic_kirchhoff(const Mat2& F, std::span<const double> history) const;

 private:
  J2Parameters p_;
};

}  // namespace slamsph
