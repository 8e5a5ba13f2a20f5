// Structure-of-arrays storage of the water particles (style.md §4). Every field is
// declared once, in visit_fields (core/field_registry.h): resize, reordering, VTK output
// and checkpoints loop over that list.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/field_registry.h"
#include "core/vec.h"

namespace slamsph {

struct FluidParticles {
  std::vector<Vec2> x;           // position [m]
  std::vector<Vec2> v;           // velocity [m/s]
  std::vector<Vec2> a;           // acceleration [m/s^2]
  std::vector<double> rho;       // density [kg/m^3]
  std::vector<double> drho;      // density rate [kg/m^3/s]
  std::vector<double> p;         // pressure [Pa]
  std::vector<double> m;         // mass per unit length [kg/m]
  std::vector<std::int64_t> id;  // stable particle id (survives reordering)
  // Kick–drift–kick integrator state: velocity and density after the first half kick.
  std::vector<Vec2> v_half;
  std::vector<double> rho_half;
  std::vector<std::uint8_t> crossed;  // 1 once the particle was found inside a solid
  std::vector<double> volume;         // m/rho, refreshed by each rate pass (scratch)
  std::vector<double> inv_rho;        // 1/rho, refreshed by each rate pass (scratch)

  // The field list. v_half and rho_half live only inside a step and volume and inv_rho only
  // inside a rate pass, so a checkpoint between steps does not need them.
  template <class Self, class F>
  static void visit_fields(Self& s, F&& f) {
    f(FieldSpec{"position", "m", true, false}, s.x);  // the VTK points
    f(FieldSpec{"velocity", "m/s", true, true}, s.v);
    f(FieldSpec{"pressure", "Pa", true, true}, s.p);
    f(FieldSpec{"density", "kg/m^3", true, true}, s.rho);
    f(FieldSpec{"id", "-", true, true}, s.id);
    f(FieldSpec{"crossed_solid", "-", true, true}, s.crossed);  // leak counter flag
    f(FieldSpec{"acceleration", "m/s^2", true, false}, s.a);
    f(FieldSpec{"density_rate", "kg/m^3/s", true, false}, s.drho);
    f(FieldSpec{"mass", "kg/m", true, false}, s.m);
    f(FieldSpec{"velocity_half_step", "m/s", false, false}, s.v_half);
    f(FieldSpec{"density_half_step", "kg/m^3", false, false}, s.rho_half);
    f(FieldSpec{"volume", "m^2", false, false}, s.volume);
    f(FieldSpec{"inverse_density", "m^3/kg", false, false}, s.inv_rho);
  }

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) { resize_fields(*this, n); }
  // Reorders every field: new[k] = old[perm[k]] (used to keep memory in cell order), through
  // `scratch`, kept by the caller between reorders, on exec's threads (core/field_registry.h).
  template <class Index>
  void permute(const std::vector<Index>& perm, std::vector<std::byte>& scratch,
               const Executor& exec) {
    permute_fields(*this, perm, scratch, exec);
  }
  template <class Index>
  void permute(const std::vector<Index>& perm) {
    permute_fields(*this, perm);
  }
};

}  // namespace slamsph
