#include "solid/body_dynamics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/parallel.h"
#include "solid/artificial_viscosity.h"
#include "solid/cantilever_mode.h"
#include "solid/deformation_gradient.h"
#include "solid/elastic_substep.h"
#include "solid/eulerian_failed_interaction.h"
#include "solid/hourglass_control.h"
#include "solid/rigid_motion.h"
#include "solid/stress_update.h"
#include "solid/tl_pair_force.h"

namespace slamsph {
namespace {

// Scratch of the solid step.
struct ForceScratch {
  std::vector<Vec2> f_stress;
  std::vector<double> heat;
  std::vector<Mat2> F_old;  // F of the previous sub-step (swapped, not copied)
};

// The material update of one sub-step (exactly once per sub-step, spec §3): F from the
// current x, then the law's committing stress update (solid/stress_update.h). h is the
// sub-step [s] (0 for the initial state at set-up).
void update_material(SolidBody& body, double h, const Executor& exec, ForceScratch& s) {
  std::swap(body.F, s.F_old);
  compute_deformation_gradients(body, body.topology, exec);
  update_stress(body, s.F_old, h, exec);
}

// f_int = stress + viscosity (with velocities vel) + hourglass from the current P and F;
// heat rate per particle from the viscosity. Reads the material state, never advances it.
void internal_forces(SolidBody& body, std::span<const Vec2> vel, const Executor& exec,
                     ForceScratch& s) {
  const std::size_t n = body.size();
  s.f_stress.resize(n);
  s.heat.resize(n);
  body.f_av.resize(n);
  body.f_hg.resize(n);
  body.f_int.resize(n);
  compute_stress_forces(body, body.topology, exec, s.f_stress);
  compute_artificial_viscosity(body, body.topology, vel, exec, body.f_av, s.heat);
  compute_hourglass_forces(body, body.topology, body.material.hourglass, exec, body.f_hg);
  add_eulerian_forces(body, vel, exec, s.f_stress, body.f_av, s.heat);  // none if none failed
  exec.for_each(
      n, [&](std::size_t i) { body.f_int[i] = s.f_stress[i] + body.f_av[i] + body.f_hg[i]; });
}

// More sub-steps than this in one fluid step means the body's speed has blown up (the case
// checks refuse stiff materials before the run); it also keeps the count inside an int.
constexpr double kMaxSubstepsInRun = 1e7;

void advance_elastic(SolidBody& body, double t, double dt, Vec2 gravity, const Executor& exec) {
  const std::size_t n = body.size();
  // Particles that failed in the previous step leave the total-Lagrangian sums before the
  // stable step reads the (rebuilt) topology (solid/eulerian_failed_interaction.h).
  update_eulerian_switch(body, exec);
  const double dts = stable_time_step(body);
  const double ratio = dt / dts;
  if (!(ratio <= kMaxSubstepsInRun)) {
    std::size_t fast = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (!(norm(body.v[i]) <= norm(body.v[fast]))) fast = i;
    std::ostringstream os;
    os << "body '" << body.name << "' particle " << fast << " at t = " << t << " s: velocity ("
       << body.v[fast].x << ", " << body.v[fast].y << ") m/s at (" << body.x[fast].x << ", "
       << body.x[fast].y << ") m makes the solid CFL step " << dts << " s, " << ratio
       << " sub-steps for a step of " << dt
       << " s (limit 1e7); limiting criterion: solid CFL (body " << body.name << ")";
    throw DivergenceError(os.str());
  }
  const int steps = std::max(1, static_cast<int>(std::ceil(ratio * (1.0 - 1e-12))));
  const double h = dt / steps;
  body.last_substeps = steps;
  const Vec2 g = body.feels_gravity ? gravity : Vec2{};
  if (body.f_int.size() != n) {
    ForceScratch s;
    internal_forces(body, body.v, exec, s);
  }
  run_elastic_substeps(body, steps, h, g, exec);
  // And again at the end, so that between steps the topology always matches the `failed`
  // flags: the next step's size (choose_time_step reads the topology's max_gradient) is then
  // the same in a run resumed from this point, whose restore rebuilds from the flags.
  update_eulerian_switch(body, exec);
}

// The smoothing-length ratio at which solid_cfl = 0.5 was measured to sit at 85-90 % of the
// leapfrog limit with the default artificial viscosity α = 1 (docs/model.md §3 "Solid stable
// step").
constexpr double kCalibratedHOverDx = 1.3;

// The length ℓ of the solid stable step (docs/model.md §3 "Solid stable step"). The leapfrog
// with the viscous force taken at the half-step velocity is stable while
// (Δt ω/2)² + Δt γ/2 < 1, ω the fastest stress-wave frequency and γ the fastest viscous
// damping rate. TL-SFPM's gradient is a nearest-neighbour stencil, so ω ∝ c/dx whatever h,
// while the viscosity's μ_ij ∝ h gives γ ∝ α c h/dx². The step ℓ/c therefore keeps ℓ ≤ h_c
// and α h ℓ ≤ h_c² (h_c = 1.3 dx, the calibrated point), which holds both terms at or below
// their calibrated values; ℓ = h exactly for h ≤ h_c and α ≤ 1. The full-support TLSPH
// gradient spreads over the kernel (ω ∝ c/h), so there only α > 1 shortens the step.
double step_length(const SolidBody& body) {
  const double h = body.kernel.h();
  const double alpha = body.material.av_alpha;
  if (body.scheme == SolidScheme::TlSph) return alpha > 1.0 ? h / alpha : h;
  const double hc = kCalibratedHOverDx * body.dx;
  double l = std::min(h, hc);
  const double viscous = alpha * h;
  if (viscous > hc) l = std::min(l, hc * (hc / viscous));
  return l;
}

}  // namespace

void refresh_internal_forces(SolidBody& body, const Executor& exec) {
  if (!body.is_elastic()) return;
  ForceScratch s;
  internal_forces(body, body.v, exec, s);  // from the committed P: no material update
}

void setup_body(SolidBody& body, const BodySetup& cfg) {
  const std::size_t n = body.size();
  body.name = cfg.name;
  body.kind = cfg.kind;
  body.scheme = cfg.scheme;
  body.dx = cfg.dx;
  if (!(body.dx > 0.0)) throw InputError("body '" + cfg.name + "': particle spacing dx <= 0");
  const double hdx = cfg.h_over_dx;
  body.kernel = Kernel(cfg.kernel, hdx * body.dx);
  body.feels_gravity = cfg.gravity;
  body.cfl = cfg.solid_cfl;
  if (body.x.size() != n) body.x = body.X;
  if (body.m.size() != n || body.V0.size() != n || body.rho0.size() != n)
    throw InputError("body '" + cfg.name + "': geometry did not set m, V0, rho0");
  body.v.assign(n, Vec2{});
  body.a.assign(n, Vec2{});
  body.f_fluid.assign(n, Vec2{});
  body.impulse_due.assign(n, Vec2{});
  if (body.layer.size() != n) body.layer.assign(n, -1);
  if (body.part.size() != n) body.part.assign(n, 0);
  if (body.spacing.size() != n) body.spacing.assign(n, body.dx);
  if (body.part_names.empty()) body.part_names = {"body"};
  for (std::size_t i = 0; i < n; ++i) {
    if (body.part[i] >= body.part_names.size())
      throw InputError("body '" + cfg.name + "': particle part id without a part name");
    if (!(body.spacing[i] >= body.dx))
      throw InputError("body '" + cfg.name + "': dx must be the finest particle spacing");
  }
  body.dissipated = body.hourglass_work = body.external_work = body.clamp_work = 0.0;
  body.switch_released = 0.0;
  body.last_substeps = 0;

  // Clamps.
  body.clamped.assign(n, 0);
  body.clamp_velocity.assign(n, Vec2{});
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < cfg.clamp_boxes.size(); ++k)
      if (inside(cfg.clamp_boxes[k], body.X[i])) {
        body.clamped[i] = 1;
        if (k < cfg.clamp_velocities.size()) body.clamp_velocity[i] = cfg.clamp_velocities[k];
      }
    for (int l : cfg.clamp_layers)
      if (body.layer[i] == l) body.clamped[i] = 1;
  }

  // Rigid state (also gives the centre of mass for the initial spin of any kind).
  init_rigid_state(body, cfg.mass.value_or(-1.0), cfg.inertia.value_or(-1.0));
  RigidState& r = body.rigid;
  r.allow_rotation = cfg.allow_rotation;
  r.vel = cfg.velocity;
  r.omega = cfg.angular_velocity;
  r.acc = Vec2{};
  r.alpha = 0.0;
  body.motion = cfg.motion;
  std::stable_sort(
      body.motion.begin(), body.motion.end(),
      [](const PrescribedVelocity& a, const PrescribedVelocity& b) { return a.t < b.t; });
  if (body.kind == BodyKind::RigidPrescribed) {
    if (body.motion.empty())
      throw InputError("body '" + cfg.name + "': rigid_prescribed needs a motion table");
    r.vel = prescribed_velocity(body.motion, 0.0);
    r.omega = 0.0;
  }
  if (body.kind == BodyKind::RigidFixed) {
    r.vel = Vec2{};
    r.omega = 0.0;
  }
  if (body.kind == BodyKind::RigidFree && !r.allow_rotation) r.omega = 0.0;

  // Initial velocities.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 arm = body.X[i] - r.com0;
    body.v[i] = r.vel + r.omega * Vec2{-arm.y, arm.x};
  }

  if (!body.is_elastic()) {
    body.F.clear();
    body.P.clear();
    body.topology = SolidTopology{};
    body.e.clear();
    body.f_int.clear();
    return;
  }

  // Elastic body.
  if (!cfg.material) throw InputError("body '" + cfg.name + "': elastic body needs a material");
  const ElasticMaterialInput& mat = *cfg.material;
  if (const auto* j2 = std::get_if<J2LinearHardeningModel>(&mat.model))
    if (!(j2->yield_stress > 0.0) || !(j2->hardening_modulus >= 0.0))
      throw InputError("body '" + cfg.name + "': material '" + mat.name +
                       "' needs yield_stress > 0 and hardening_modulus >= 0");
  // Plane-strain stability (positive P-wave modulus and shear modulus): -1 < ν < 0.5;
  // auxetic materials (ν < 0) are valid.
  if (!(mat.youngs_modulus > 0.0) || !(mat.poisson_ratio > -1.0 && mat.poisson_ratio < 0.5))
    throw InputError("body '" + cfg.name + "': material '" + mat.name +
                     "' needs youngs_modulus > 0 and -1 < poisson_ratio < 0.5");
  SolidMaterial& sm = body.material;
  sm.density = mat.density > 0.0 ? mat.density : body.rho0.empty() ? 0.0 : body.rho0[0];
  sm.youngs_modulus = mat.youngs_modulus;
  sm.poisson_ratio = mat.poisson_ratio;
  try {
    sm.law = make_material_law(mat.model, mat.youngs_modulus, mat.poisson_ratio, sm.density);
  } catch (const std::invalid_argument& e) {
    throw InputError("body '" + cfg.name + "': material '" + mat.name + "': " + e.what());
  }
  sm.av_alpha = mat.av_alpha;
  sm.av_beta = mat.av_beta;
  sm.hourglass = mat.hourglass;
  const double nu = mat.poisson_ratio;
  sm.sound_speed =
      std::sqrt(mat.youngs_modulus * (1.0 - nu) / (sm.density * (1.0 + nu) * (1.0 - 2.0 * nu)));

  if (cfg.cantilever_mode) {
    const CantileverModeInput& cm = *cfg.cantilever_mode;
    if (!(cm.length > 0.0))
      throw InputError("body '" + cfg.name +
                       "': cantilever_mode needs shape.box.max.x beyond the clamp");
    const double c0 = bulk_sound_speed(mat.youngs_modulus, nu, sm.density);
    for (std::size_t i = 0; i < n; ++i)
      if (!body.clamped[i])
        body.v[i].y += cantilever_mode_velocity(body.X[i].x - cm.clamp_edge, cm.length, cm.vf, c0);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (body.clamped[i]) body.v[i] = body.clamp_velocity[i];

  const Executor serial(1);
  try {
    // The parts of one body are bonded (a fuselage's skin, stringers, floor, columns).
    body.topology = build_solid_topology(
        body.X, body.V0,
        TopologySpec{body.scheme, body.dx, body.kernel, body.part, true, body.spacing}, serial);
  } catch (const std::invalid_argument& e) {
    throw InputError("body '" + cfg.name + "': " + e.what());
  }
  body.F.assign(n, Mat2::identity());
  body.F_rebase.assign(n, Mat2::identity());
  body.F_rebase_failed = 0;
  body.P.assign(n, Mat2{});
  body.e.assign(n, 0.0);
  body.history.reset(history_fields(sm.law), n, initial_history(sm.law));
  if (!cfg.pre_failed_boxes.empty()) {
    // A pre-cut breach: failed (and fully damaged) before the first update, so the first
    // committed stress is already the failed one (compression only).
    std::vector<double>*failed = nullptr, *damage = nullptr;
    for (std::size_t k = 0; k < body.history.fields.size(); ++k) {
      if (body.history.fields[k].name == "failed") failed = &body.history.values[k];
      if (body.history.fields[k].name == "damage") damage = &body.history.values[k];
    }
    if (failed == nullptr)
      throw InputError("body '" + cfg.name + "': material '" + mat.name +
                       "' cannot fail, so no particle can start failed (pre_failed)");
    // (A box around no particle is the case builder's input error, with file and line.)
    for (std::size_t i = 0; i < n; ++i)
      for (const Box& b : cfg.pre_failed_boxes)
        if (inside(b, body.X[i])) {
          (*failed)[i] = 1.0;
          if (damage != nullptr) (*damage)[i] = 1.0;
        }
  }
  // The initial state (F from x = X, i.e. I to round-off) is the first committed update;
  // afterwards the law is evaluated once per sub-step by advance_elastic.
  ForceScratch s;
  update_material(body, 0.0, serial, s);
  internal_forces(body, body.v, serial, s);
  for (std::size_t i = 0; i < n; ++i)
    body.a[i] = body.clamped[i] ? Vec2{} : body.f_int[i] / body.m[i];
}

double stable_time_step(const SolidBody& body) {
  if (!body.is_elastic()) return std::numeric_limits<double>::infinity();
  double vmax = 0.0;
  for (const Vec2& v : body.v) vmax = std::max(vmax, norm(v));
  // The hourglass penalty (stiffness ~ α E per pair) raises the fastest wave speed to at most
  // c_s sqrt(1 + α); without this factor α = 10 is unstable on the plate.
  const double c = body.material.sound_speed * std::sqrt(1.0 + body.material.hourglass);
  // Irregular joints between parts (solid_topology.h) have gradient weights above the
  // regular lattice's 1/dx: the step shrinks by that ratio (1 for one-part lattices, which
  // measure max |g| dx <= 1; the fuselage joints 1.1-1.3). Without it a 2-layer skin with a
  // floor diverges within 100 sub-steps (tests/unit/test_app_fuselage.cpp).
  const double stiff = std::max(1.0, body.topology.max_gradient * body.dx);
  return body.cfl * step_length(body) / (stiff * (c + vmax));
}

void advance_body(SolidBody& body, double t, double dt, Vec2 gravity, const Executor& exec) {
  if (body.is_elastic()) {
    advance_elastic(body, t, dt, gravity, exec);
  } else {
    body.last_substeps = 1;
    advance_rigid(body, t, dt, gravity);
  }
}

BodyEnergies body_energies(const SolidBody& body) {
  BodyEnergies en;
  for (std::size_t i = 0; i < body.size(); ++i) en.kinetic += 0.5 * body.m[i] * norm2(body.v[i]);
  if (!body.is_elastic()) return en;
  for (std::size_t i = 0; i < body.size(); ++i)
    en.strain += body.V0[i] * strain_energy_density(body, i);
  en.dissipated = body.dissipated;
  en.hourglass = hourglass_energy(body, body.topology, body.material.hourglass, Executor(1));
  return en;
}

BodySummary body_summary(const SolidBody& body) {
  BodySummary s;
  double m = 0.0;
  for (std::size_t i = 0; i < body.size(); ++i) {
    m += body.m[i];
    s.com += body.m[i] * body.x[i];
    s.mean_velocity += body.m[i] * body.v[i];
    s.mean_acceleration += body.m[i] * body.a[i];
  }
  if (m > 0.0) {
    s.com = s.com / m;
    s.mean_velocity = s.mean_velocity / m;
    s.mean_acceleration = s.mean_acceleration / m;
  }
  return s;
}

}  // namespace slamsph
