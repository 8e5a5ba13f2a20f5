#include "app/cost_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/simulation.h"
#include "solid/body_dynamics.h"
#include "solid/materials/johnson_cook.h"

namespace slamsph {

CostPrediction predict_cost(const Simulation& sim, const CostConstants& k) {
  const CaseConfig& cfg = sim.config();
  const NumericsConfig& num = cfg.numerics;
  const FluidParticles& fluid = sim.fluid();
  CostPrediction c;
  c.fluid_particles = fluid.size();
  c.contact_particles = sim.contact().size();

  // The speed of the step prediction (see the header).
  double v = 0.0;
  double amax = 0.0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    v = std::max(v, norm(fluid.v[i]));
    amax = std::max(amax, norm(fluid.a[i]));
  }
  for (const SolidBody& b : sim.bodies()) {
    for (const Vec2& u : b.v) v = std::max(v, norm(u));
    for (const PrescribedVelocity& p : b.motion) v = std::max(v, norm(p.v));
  }
  const double g = norm(num.gravity);
  if (fluid.size() > 0 && g > 0.0) {
    const Vec2 up = -1.0 / g * num.gravity;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vec2& x : fluid.x) {
      lo = std::min(lo, dot(x, up));
      hi = std::max(hi, dot(x, up));
    }
    v = std::max(v, std::sqrt(2.0 * g * (hi - lo)));
  }
  c.speed = v;

  const bool share = !num.dual_time_stepping || fluid.size() == 0;
  double dt = std::numeric_limits<double>::infinity();
  if (fluid.size() > 0) {
    const double h = num.h_over_dx * num.dx;
    dt = num.cfl * h / (cfg.fluid.sound_speed + v);
    c.limiter = "fluid acoustic CFL";
    if (amax > 0.0 && 0.25 * std::sqrt(h / amax) < dt) {
      dt = 0.25 * std::sqrt(h / amax);
      c.limiter = "fluid acceleration (initial)";
    }
  }
  for (const SolidBody& b : sim.bodies()) {
    BodyCost bc{b.name, b.size(), b.is_elastic(), stable_time_step(b), 0};
    if (std::holds_alternative<JohnsonCook>(b.material.law)) bc.law_factor = k.johnson_cook_factor;
    if (share && bc.stable_step < dt) {
      dt = bc.stable_step;
      c.limiter = "solid CFL (body " + b.name + ")";
    }
    c.bodies.push_back(bc);
  }
  if (!std::isfinite(dt)) {
    dt = num.end_time / 100.0;
    c.limiter = "end time / 100";
  }
  c.dt = dt;
  c.fluid_steps = static_cast<long>(std::ceil(num.end_time / dt * (1.0 - 1e-12)));

  c.fluid_seconds = 1e-9 * k.fluid_ns * static_cast<double>(c.fluid_particles) *
                    static_cast<double>(c.fluid_steps);
  c.contact_seconds = 1e-9 * k.contact_ns * static_cast<double>(c.contact_particles) *
                      static_cast<double>(c.fluid_steps);
  for (BodyCost& bc : c.bodies) {
    if (!bc.elastic) continue;
    // As solid/body_dynamics.cpp: ceil(Δt/Δt_s), at least one.
    bc.substeps_per_step =
        std::max(1L, static_cast<long>(std::ceil(dt / bc.stable_step * (1.0 - 1e-12))));
    const long total = bc.substeps_per_step * c.fluid_steps;
    c.solid_substeps += total;
    c.solid_seconds += 1e-9 * k.solid_ns * bc.law_factor * static_cast<double>(bc.particles) *
                       static_cast<double>(total);
  }
  return c;
}

std::string describe_cost(const CostPrediction& c) {
  char buf[512];
  std::string s;
  std::snprintf(buf, sizeof buf,
                "predicted: %zu water and %zu contact particles; fluid step %.3g s (%s, speed "
                "%.3g m/s), %ld fluid steps\n",
                c.fluid_particles, c.contact_particles, c.dt, c.limiter.c_str(), c.speed,
                c.fluid_steps);
  s += buf;
  for (const BodyCost& b : c.bodies) {
    if (b.elastic)
      std::snprintf(buf, sizeof buf,
                    "  body %s: %zu particles, elastic, stable step %.3g s, %ld sub-steps per "
                    "fluid step\n",
                    b.name.c_str(), b.particles, b.stable_step, b.substeps_per_step);
    else
      std::snprintf(buf, sizeof buf, "  body %s: %zu particles, rigid\n", b.name.c_str(),
                    b.particles);
    s += buf;
  }
  std::snprintf(buf, sizeof buf,
                "predicted CPU time on 1 thread: %.3g s (water %.3g s, contact %.3g s, solid "
                "%.3g s; per-particle costs of app/cost_model.h, measured on a 2-core x86 "
                "machine)\n",
                c.cpu_seconds(), c.fluid_seconds, c.contact_seconds, c.solid_seconds);
  s += buf;
  return s;
}

}  // namespace slamsph
