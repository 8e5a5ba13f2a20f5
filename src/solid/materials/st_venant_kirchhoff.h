// St Venant–Kirchhoff hyperelasticity in plane strain (spec §3), as pure functions at one
// material point, plus the stress measures derived from any first Piola–Kirchhoff stress.
//
//   E_GL = ½(FᵀF − I),  S = λ tr(E_GL) I + 2μ E_GL,  P = F S,
//   Ψ = ½ λ (tr E_GL)² + μ E_GL : E_GL      (strain energy per reference volume)
//
// Plane strain: F_zz = 1, so E_zz = 0 and the out-of-plane stress is not zero. For SVK we
// use the consistent value S_zz = λ tr(E_GL), σ_zz = S_zz / J (J = det F), NOT the linear
// elastic ν(σxx + σyy): the two agree to first order in strain and the SVK value keeps the
// von Mises stress and pressure consistent with the energy at large strain.
//
// StVenantKirchhoff below is the law object of solid/materials/material_law.h: no history,
// its update ignores F_old and dt. The stress measures at the end of this header serve every
// law.
#pragma once
#include <array>
#include <span>

#include "core/vec.h"
#include "solid/materials/material_law.h"

namespace slamsph {

struct SvkParameters {
  double lambda = 0.0;  // first Lamé parameter [Pa]
  double mu = 0.0;      // shear modulus [Pa]
};

// Lamé parameters from Young's modulus E [Pa] and Poisson's ratio ν [-].
SvkParameters svk_from_young(double youngs_modulus, double poisson_ratio);

// Inline (here, not in the .cpp): the fused sub-step calls svk_pk1 once per particle per
// sub-step, and an out-of-line call there spills every live vector register around it (all
// are caller-saved); inlined, the same operations in the same order (same bits).
// Green–Lagrange strain ½(FᵀF − I).
inline Mat2 green_lagrange(const Mat2& F) {
  Mat2 E = transpose(F) * F;
  E -= Mat2::identity();
  E *= 0.5;
  return E;
}
// Second Piola–Kirchhoff stress from the Green–Lagrange strain.
inline Mat2 svk_pk2(const SvkParameters& p, const Mat2& E) {
  Mat2 S = 2.0 * p.mu * E;
  const double l = p.lambda * trace(E);
  S.xx += l;
  S.yy += l;
  return S;
}
// First Piola–Kirchhoff stress P = F S.
inline Mat2 svk_pk1(const SvkParameters& p, const Mat2& F) {
  return F * svk_pk2(p, green_lagrange(F));
}
// Strain energy per unit reference volume [J/m^3].
double svk_strain_energy_density(const SvkParameters& p, const Mat2& F);
// Out-of-plane Cauchy stress σ_zz = λ tr(E_GL) / det F [Pa].
double svk_cauchy_zz(const SvkParameters& p, const Mat2& F);

// The law object (interface: solid/materials/material_law.h).
class StVenantKirchhoff {
 public:
  static constexpr std::array<HistoryField, 0> kHistory{};

  explicit StVenantKirchhoff(SvkParameters p = {}) : p_(p) {}
  const SvkParameters& parameters() const { return p_; }

  // Hyperelastic: P depends on F_new only.
  Mat2 update(const Mat2& /*F_old*/, const Mat2& F_new, double /*dt*/,
              std::span<double> /*history*/) const {
    return svk_pk1(p_, F_new);
  }
  double cauchy_zz(const Mat2& F, std::span<const double> /*history*/) const {
    return svk_cauchy_zz(p_, F);
  }
  double energy_density(const Mat2& F, std::span<const double> /*history*/) const {
    return svk_strain_energy_density(p_, F);
  }

 private:
  SvkParameters p_;
};

// In-plane Cauchy stress plus the out-of-plane component.
struct CauchyStress {
  double xx = 0.0, yy = 0.0, xy = 0.0, zz = 0.0;  // [Pa]
};
// σ = P Fᵀ / det F (symmetrised: for a P from a hyperelastic law it already is).
CauchyStress cauchy_from_pk1(const Mat2& P, const Mat2& F, double sigma_zz);
// von Mises equivalent stress sqrt(3/2 s:s) including σ_zz [Pa].
double von_mises_stress(const CauchyStress& s);
// Pressure −(σxx + σyy + σzz)/3 [Pa].
double pressure(const CauchyStress& s);
// von Mises equivalent of a plane-strain strain tensor E (E_zz = 0):
// sqrt(2/3 dev(E):dev(E)) with the 3x3 deviator [-].
double equivalent_strain(const Mat2& E);

}  // namespace slamsph
