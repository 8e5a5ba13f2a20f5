#include "solid/body_energy.h"

#include <type_traits>
#include <variant>

#include "solid/body_dynamics.h"
#include "solid/materials/material_law_choice.h"

namespace slamsph {

namespace {
template <class>
inline constexpr bool kAlwaysFalse = false;
}  // namespace

double plastic_work(const SolidBody& body) {
  if (!body.is_elastic()) return 0.0;
  return std::visit(
      [&](const auto& law) -> double {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (std::is_same_v<Law, StVenantKirchhoff>) {
          return 0.0;
        } else if constexpr (std::is_same_v<Law, J2LinearHardening>) {
          const J2Parameters& p = law.parameters();
          const std::vector<double>& ep = body.history.values[J2LinearHardening::kPlasticStrain];
          double w = 0.0;
          for (std::size_t i = 0; i < body.size(); ++i)
            w += body.V0[i] * (p.yield_stress + 0.5 * p.hardening_modulus * ep[i]) * ep[i];
          return w;
        } else if constexpr (std::is_same_v<Law, JohnsonCook>) {
          // The law heats adiabatically by χ of the plastic work (solid/materials/
          // johnson_cook.h): ρ0 c_v ΔT = χ q Δε̄p per update, so the plastic work per
          // reference volume is ρ0 c_v (T − T0)/χ, exactly as the return mapping did it.
          // With χ = 0 no heat records it and the work shows in the residual instead.
          const JohnsonCookParameters& p = law.parameters();
          if (!(p.jc.heating_fraction > 0.0)) return 0.0;
          const std::vector<double>& T = body.history.values[JohnsonCook::kTemperature];
          double w = 0.0;
          for (std::size_t i = 0; i < body.size(); ++i)
            w += body.V0[i] * p.rho0 * p.jc.specific_heat * (T[i] - p.jc.initial_temperature);
          return w / p.jc.heating_fraction;
        } else {
          // A new law must say how much work its plastic flow (or damage) dissipates, else
          // the energy balance would silently lose it.
          static_assert(kAlwaysFalse<Law>, "plastic_work: add this material law");
          return 0.0;
        }
      },
      body.material.law);
}

bool has_moving_clamp(const SolidBody& body) {
  for (std::size_t i = 0; i < body.clamp_velocity.size(); ++i)
    if (body.clamped[i] && (body.clamp_velocity[i].x != 0.0 || body.clamp_velocity[i].y != 0.0))
      return true;
  return false;
}

BodyEnergyTerms body_energy_terms(const SolidBody& body, Vec2 gravity) {
  BodyEnergyTerms t;
  const Vec2 g = body.feels_gravity ? gravity : Vec2{};
  t.external_work = body.external_work;
  t.clamp_work = body.clamp_work;
  if (body.is_elastic()) {
    const BodyEnergies e = body_energies(body);
    t.kinetic = e.kinetic;
    t.strain = e.strain;
    t.hourglass = e.hourglass;
    t.viscous = e.dissipated;
    t.plastic = plastic_work(body);
    for (std::size_t i = 0; i < body.size(); ++i) t.potential -= body.m[i] * dot(g, body.x[i]);
  } else {
    // Rigid bodies move as their rigid state says (solid/rigid_motion.h).
    const RigidState& r = body.rigid;
    t.kinetic = 0.5 * r.mass * norm2(r.vel) + 0.5 * r.inertia * r.omega * r.omega;
    t.potential = -r.mass * dot(g, r.com);
  }
  // The hourglass potential the Eulerian switch's rebuilds released (0 without a switch).
  t.dissipated = t.viscous + t.plastic + body.switch_released;
  return t;
}

}  // namespace slamsph
