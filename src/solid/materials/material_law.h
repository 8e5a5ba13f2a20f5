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
//    plasticity with linear isotropic hardening, history Cp⁻¹ and ε̄p.
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

  // Declares `f` and sets every particle (n) to the fields' initial values.
  void reset(std::span<const HistoryField> f, std::size_t n) {
    fields.assign(f.begin(), f.end());
    values.assign(fields.size(), {});
    for (std::size_t k = 0; k < fields.size(); ++k) values[k].assign(n, fields[k].initial);
    updates = 0;
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
using MaterialModel = std::variant<SvkModel, J2LinearHardeningModel>;

}  // namespace slamsph
