// Material-law interface of the total-Lagrangian solid (spec §3). A law is a small value
// with its parameters, pure functions at one material point, and a declared list of
// per-particle history fields:
//
//   Law::kHistory                          the history fields (name, unit, initial value)
//   P = law.update(F_old, F_new, dt, h)    first Piola–Kirchhoff stress at F_new; commits
//                                          the particle's history h (span of kHistory.size())
//   law.cauchy_zz(F, h)                    out-of-plane Cauchy stress (plane strain) [Pa]
//   law.energy_density(F, h)               stored (elastic) energy per reference volume [J/m^3]
//
// `update` is called exactly once per particle per solid sub-step (solid/stress_update.h,
// which counts the passes in MaterialHistory::updates); the force operators only read the
// stresses it produced, so evaluating forces never advances history. `cauchy_zz` and
// `energy_density` read committed history and change nothing.
//
// The case file names the law; the parser turns the name into a MaterialModel (a typed
// value with the law's own parameters), so physics never sees a string. The laws:
//  - StVenantKirchhoff  (solid/materials/st_venant_kirchhoff.h), no history;
//  - J2LinearHardening  (solid/materials/j2_linear_hardening.h), multiplicative J2
//    plasticity with linear isotropic hardening, history Cp⁻¹ and ε̄p;
//  - JohnsonCook        (solid/materials/johnson_cook.h), the same kinematics with the
//    Johnson–Cook flow stress (rate, temperature), a Mie–Grüneisen pressure and
//    Johnson–Cook or critical-strain failure (spec §3, §5).
#pragma once
#include <cstdint>
#include <span>
#include <string_view>
#include <variant>
#include <vector>

#include "core/vec.h"

namespace slamsph {

// One per-particle history field of a law.
struct HistoryField {
  std::string_view name;  // e.g. "equivalent_plastic_strain"
  std::string_view unit;  // e.g. "-"
  double initial = 0.0;   // value in the reference (virgin) state
  bool output = true;     // written to the VTK output (every field is persistent state)
};

// Per-particle history of one body, one named vector per field its law declares.
struct MaterialHistory {
  std::vector<HistoryField> fields;
  std::vector<std::vector<double>> values;  // values[field][particle]
  std::uint64_t updates = 0;                // committed stress-update passes (see above)

  // Declares `f` and sets every particle (n) to the fields' initial values, or to
  // `initial` (one value per field) when given: a law whose virgin state depends on its
  // parameters (the Johnson–Cook initial temperature).
  void reset(std::span<const HistoryField> f, std::size_t n, std::span<const double> initial = {}) {
    fields.assign(f.begin(), f.end());
    values.assign(fields.size(), {});
    for (std::size_t k = 0; k < fields.size(); ++k)
      values[k].assign(n, initial.empty() ? fields[k].initial : initial[k]);
    updates = 0;
  }

  // The values of the field called `name`, or nullptr when the law declares none.
  const std::vector<double>* find(std::string_view name) const {
    for (std::size_t k = 0; k < fields.size(); ++k)
      if (fields[k].name == name) return &values[k];
    return nullptr;
  }
};

// Typed model choice from the case file ([materials.<name>] model = "..."); the elastic
// constants (Young's modulus, Poisson's ratio) are common to all laws and kept beside it.
struct SvkModel {
  bool operator==(const SvkModel&) const = default;
};
struct J2LinearHardeningModel {
  double yield_stress = 0.0;       // initial yield stress σ_y (von Mises) [Pa]
  double hardening_modulus = 0.0;  // H in σ_flow = σ_y + H ε̄p [Pa]
  bool operator==(const J2LinearHardeningModel&) const = default;
};

// Failure criterion of a Johnson–Cook material (spec §5): none, the Johnson–Cook (1985)
// cumulative damage D = Σ Δε̄p / ε_f(σ*, ε̇*, T*), or a plain critical plastic strain.
enum class FailureKind { None, JohnsonCook, CriticalPlasticStrain };
struct FailureModel {
  FailureKind kind = FailureKind::None;
  double d1 = 0.0, d2 = 0.0, d3 = 0.0, d4 = 0.0, d5 = 0.0;  // ε_f constants [-]
  double critical_plastic_strain = 0.0;                     // [-]
  bool operator==(const FailureModel&) const = default;
};

// Johnson–Cook flow stress σ_y = (A + B ε̄p^n)(1 + C ln ε̇*)(1 − T*^m) with a Mie–Grüneisen
// volumetric pressure and adiabatic heating (spec §3; docs/model.md §3 "Johnson–Cook").
struct JohnsonCookModel {
  double a = 0.0;                        // A, initial yield stress [Pa]
  double b = 0.0;                        // B, hardening coefficient [Pa]
  double n = 1.0;                        // n, hardening exponent [-]
  double c = 0.0;                        // C, strain-rate coefficient [-]
  double m = 1.0;                        // m, thermal-softening exponent [-]
  double reference_strain_rate = 1.0;    // ε̇0 [1/s]
  double reference_temperature = 293.0;  // T_r [K]
  double melting_temperature = 775.0;    // T_m [K]
  double initial_temperature = 293.0;    // T at t = 0 [K]
  double specific_heat = 875.0;          // c_v [J/(kg K)]
  double heating_fraction = 0.9;         // share of the plastic work turned into heat [-]
  double eos_sound_speed = 0.0;          // Mie–Grüneisen bulk sound speed c [m/s]
  double gruneisen_gamma = 0.0;          // Γ [-]
  double hugoniot_slope = 0.0;           // s in U_s = c + s u_p [-]
  FailureModel failure;
  bool operator==(const JohnsonCookModel&) const = default;
};

using MaterialModel = std::variant<SvkModel, J2LinearHardeningModel, JohnsonCookModel>;

}  // namespace slamsph
