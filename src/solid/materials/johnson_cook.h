// Johnson–Cook elastic–plastic solid in plane strain (paper §4.5, Table 1; spec §3, §5;
// docs/model.md §3 "Johnson–Cook" has the equations and the choice of kinematics).
//
// Kinematics as in J2LinearHardening: F = Fe Fp, Hencky elasticity, exponential-map radial
// return, history Cp⁻¹ in the reference frame. The deviatoric Kirchhoff stress is
// s = 2μ dev ε_e; the volumetric part is the Mie–Grüneisen pressure (mie_gruneisen.h),
// τ_mean = −J p(J, c_v (T − T0)) (plastic flow is isochoric, so J_e = J). The yield function
// q − σ_y(ε̄p, ε̇p, T) with the Johnson–Cook flow stress
//
//   σ_y = (A + B ε̄p^n) (1 + C ln ε̇*) (1 − T*^m),  ε̇* = max(ε̇p/ε̇0, 1),
//   T* = (T − T_r)/(T_m − T_r) clipped to [0, 1],  ε̇p = Δε̄p/Δt,
//
// is solved for Δε̄p by a bracketed Newton iteration on the consistency condition
// q_tr − 3μ Δε̄p = σ_y(ε̄p + Δε̄p, Δε̄p/Δt, T(Δε̄p)) with the adiabatic heating of the same
// step, ρ0 c_v ΔT = χ σ_y Δε̄p (χ the heating fraction) — rate and heat are implicit, so the
// committed stress lies on the yield surface of the committed state.
//
// Damage (johnson_cook_failure.h): D += Δε̄p/ε_f(σ*, ε̇*, T*) with σ* = τ_mean/q of the
// returned stress. At D ≥ 1 the particle fails: from that update on it carries no
// deviatoric stress and no tension (τ = −J max(p, 0) 1).
//
// History (per particle): Cp⁻¹ (xx, xy, yy, zz), ε̄p, ε̇p, T, D, failed (0/1) and the stress
// triaxiality σ*; ε̇p and σ* keep their values at failure once the particle has failed.
#pragma once
#include <array>
#include <span>

#include "core/vec.h"
#include "solid/materials/material_law.h"
#include "solid/materials/mie_gruneisen.h"

namespace slamsph {

struct JohnsonCookParameters {
  double mu = 0.0;      // shear modulus [Pa]
  double rho0 = 0.0;    // reference density [kg/m^3]
  JohnsonCookModel jc;  // flow stress, heating, EOS and failure constants
};

// Kirchhoff stress in plane strain: in-plane tensor and the zz component [Pa].
struct KirchhoffStress {
  Mat2 in_plane;
  double zz = 0.0;
};

class JohnsonCook {
 public:
  enum Slot {
    kCpInvXX,
    kCpInvXY,
    kCpInvYY,
    kCpInvZZ,
    kPlasticStrain,
    kPlasticStrainRate,
    kTemperature,
    kDamage,
    kFailed,
    kTriaxiality,
    kSlots
  };
  static constexpr std::array<HistoryField, kSlots> kHistory{{
      {"plastic_metric_xx", "-", 1.0, false},  // Cp⁻¹ components
      {"plastic_metric_xy", "-", 0.0, false},
      {"plastic_metric_yy", "-", 1.0, false},
      {"plastic_metric_zz", "-", 1.0, false},
      {"equivalent_plastic_strain", "-", 0.0, true},
      {"plastic_strain_rate", "1/s", 0.0, true},
      {"temperature", "K", 293.0, true},  // replaced by initial_temperature (initial_history)
      {"damage", "-", 0.0, true},
      {"failed", "-", 0.0, true},
      {"triaxiality", "-", 0.0, true},
  }};

  explicit JohnsonCook(JohnsonCookParameters p);
  const JohnsonCookParameters& parameters() const { return p_; }

  // The interface of solid/materials/material_law.h (F_zz = 1).
  Mat2 update(const Mat2& F_old, const Mat2& F_new, double dt, std::span<double> history) const;
  double cauchy_zz(const Mat2& F, std::span<const double> history) const;
  double energy_density(const Mat2& F, std::span<const double> history) const;
  // The virgin history of a particle (temperature = initial_temperature).
  std::array<double, kSlots> initial_history() const;

  // The committing update with an out-of-plane stretch F_zz (1 in plane strain; material-
  // point tests drive uniaxial stress with it). Returns the Kirchhoff stress.
  KirchhoffStress update_kirchhoff(const Mat2& F, double Fzz, double dt,
                                   std::span<double> history) const;
  // Kirchhoff stress of the committed state at (F, F_zz), no return mapping.
  KirchhoffStress elastic_kirchhoff(const Mat2& F, double Fzz,
                                    std::span<const double> history) const;

  // Homologous temperature T* clipped to [0, 1] [-].
  double homologous_temperature(double T) const;

 private:
  JohnsonCookParameters p_;
  MieGruneisenParameters eos_;
};

}  // namespace slamsph
