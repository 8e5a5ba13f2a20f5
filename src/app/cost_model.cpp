#include "app/cost_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>

#include "app/simulation.h"
#include "core/parallel.h"
#include "fluid/gsph_pair_band.h"
#include "io/case_file.h"
#include "solid/body_dynamics.h"
#include "solid/elastic_substep.h"
#include "solid/eulerian_failed_interaction.h"
#include "solid/materials/johnson_cook.h"
#include "solid/solid_body.h"
#include "solid/substep_pair_lanes.h"

namespace slamsph {
namespace {

// The particles of an elastic body that run the Eulerian path from its first step: the switch
// is made by advance_body (update_eulerian_switch), not when the body is built, so a body
// whose particles start failed (`[body.pre_failed]`) with `failed_particles = "eulerian"`
// has body.eulerian.active false here; the switch is made on a copy, as the first step will.
std::size_t switched_at_start(const SolidBody& body) {
  if (!body.is_elastic() || !body.eulerian_switch) return 0;
  if (body.eulerian.active) return body.eulerian.members.size();
  const std::vector<double>* failed = failed_flags(body);
  if (failed == nullptr ||
      std::none_of(failed->begin(), failed->end(), [](double f) { return f > 0.5; }))
    return 0;
  SolidBody b = body;
  update_eulerian_switch(b, Executor(1));
  return b.eulerian.members.size();
}

// y_small at x ≤ x_small, y_large at x ≥ x_large, linear in log x between.
double log_interpolate(double x, double x_small, double x_large, double y_small, double y_large) {
  if (x <= x_small) return y_small;
  if (x >= x_large) return y_large;
  const double f = std::log(x / x_small) / std::log(x_large / x_small);
  return y_small + f * (y_large - y_small);
}

// The water and the solids in columns two fluid spacings wide across gravity, for the fall
// height and the spreading of the water (see the header). Per column: the top and bottom of
// its water; the highest solid (wall or body particle, not debris: a failed particle does not
// hold water, coupling/contact_particles.h) below the water's overall top, and below the
// column's lowest water particle; the level `base` its water rests on: its lowest water
// particle where that stands on a solid (the solid at most two spacings below it), else one
// spacing above its highest solid (the position of a water particle resting on it; for
// water over a breach the solid under the breach), or the water's lowest particle where the
// column has no solid (no floor).
struct Columns {
  Vec2 up, across;
  double a0 = 0.0, width = 0.0, lo = 0.0, hi = 0.0;
  std::size_t n = 0;
  std::vector<double> top, bottom, floor_top, floor_bottom, base;
  std::size_t of(Vec2 x) const {
    return std::min(n - 1, static_cast<std::size_t>(std::max(0.0, dot(x, across) - a0) / width));
  }
  bool wet(std::size_t c) const { return top[c] > -std::numeric_limits<double>::infinity(); }
};

Columns make_columns(const FluidParticles& fluid, const ContactParticles& contact, Vec2 up,
                     double dx) {
  Columns col;
  col.up = up;
  col.across = Vec2{up.y, -up.x};
  const double inf = std::numeric_limits<double>::infinity();
  col.lo = inf;
  col.hi = -inf;
  double a1 = -inf;
  col.a0 = inf;
  for (const Vec2& x : fluid.x) {
    col.lo = std::min(col.lo, dot(x, up));
    col.hi = std::max(col.hi, dot(x, up));
  }
  for (const std::vector<Vec2>* xs : {&fluid.x, &contact.x})
    for (const Vec2& x : *xs) {
      col.a0 = std::min(col.a0, dot(x, col.across));
      a1 = std::max(a1, dot(x, col.across));
    }
  col.width = 2.0 * dx;
  col.n = static_cast<std::size_t>(std::floor((a1 - col.a0) / col.width)) + 1;
  col.top.assign(col.n, -inf);
  col.bottom.assign(col.n, inf);
  col.floor_top.assign(col.n, -inf);
  col.floor_bottom.assign(col.n, -inf);
  for (const Vec2& x : fluid.x) {
    const std::size_t c = col.of(x);
    col.top[c] = std::max(col.top[c], dot(x, up));
    col.bottom[c] = std::min(col.bottom[c], dot(x, up));
  }
  for (std::size_t s = 0; s < contact.size(); ++s) {
    if (s < contact.debris.size() && contact.debris[s]) continue;
    const std::size_t c = col.of(contact.x[s]);
    const double y = dot(contact.x[s], up);
    if (y < col.hi) col.floor_top[c] = std::max(col.floor_top[c], y);
    if (y < col.bottom[c]) col.floor_bottom[c] = std::max(col.floor_bottom[c], y);
  }
  auto resting_on = [&](double floor) { return floor > -inf ? floor + dx : col.lo; };
  col.base.resize(col.n);
  for (std::size_t c = 0; c < col.n; ++c) {
    if (col.wet(c) && col.floor_bottom[c] >= col.bottom[c] - 2.0 * dx)
      col.base[c] = col.bottom[c];  // water standing on a solid
    else if (col.wet(c))
      col.base[c] = resting_on(col.floor_bottom[c]);  // water over a breach
    else
      col.base[c] = resting_on(col.floor_top[c]);  // a dry column
  }
  return col;
}

// The height the water can fall through [m]: its highest particle above the lowest level some
// of it can reach, the water's top in a column where it stands on a solid, the base of any
// other column. A flat free surface at rest falls nowhere (still water: 0); a dam-break
// column falls by its height (the dry floor beside it); the water over a breached plate by
// the depth of the chamber under it.
double fall_height(const Columns& col) {
  double level = col.hi;
  for (std::size_t c = 0; c < col.n; ++c) {
    const bool standing = col.wet(c) && col.base[c] == col.bottom[c];
    level = std::min(level, standing ? col.top[c] : col.base[c]);
  }
  return std::max(0.0, col.hi - level);
}

// Surface contact particles (a non-zero outward normal: one per spacing of wetted wall, floor
// or body surface, whatever its orientation and the layers behind it) that face a water region
// given per column as [b_c, t_c] across the column's width (none where t_c < b_c) within `r`.
std::size_t wetted_contact(const Columns& col, const ContactParticles& contact,
                           const std::vector<double>& b, const std::vector<double>& t, double r) {
  const std::size_t k = static_cast<std::size_t>(std::ceil(r / col.width)) + 1;
  std::size_t count = 0;
  for (std::size_t s = 0; s < contact.size(); ++s) {
    if (s >= contact.normal.size()) break;
    const Vec2 n = contact.normal[s];
    if (n.x == 0.0 && n.y == 0.0) continue;
    const Vec2 x = contact.x[s];
    const std::size_t c = col.of(x);
    const double a = dot(x, col.across), y = dot(x, col.up);
    for (std::size_t d = c > k ? c - k : 0; d <= std::min(col.n - 1, c + k); ++d) {
      if (t[d] < b[d]) continue;
      const double a_lo = col.a0 + static_cast<double>(d) * col.width;
      const double da = std::clamp(a, a_lo, a_lo + col.width) - a;
      const double dy = std::clamp(y, b[d], t[d]) - y;
      if (da * da + dy * dy < r * r && da * dot(n, col.across) + dy * dot(n, col.up) >= 0.0) {
        ++count;
        break;
      }
    }
  }
  return count;
}

// The water at rest in its container: spread over every column its area reaches, to one level
// (its top particle) no higher than its top now — the state a flow that is not at rest tends
// to (a dam break's water over the whole floor of its tank).
struct Spread {
  double level = 0.0;       // the top water particle at rest [m]
  double dry_length = 0.0;  // [m] the floor it covers at rest that is dry at the start
  double ratio = 1.0;       // wetted contact particles at rest over those at the start
};

Spread spread_at_rest(const Columns& col, const ContactParticles& contact, double dx, double r,
                      std::size_t n_water) {
  Spread sp;
  // Area held below level L: a column based at b holds (L - b)/dx + 1 rows of water.
  auto held = [&](double L) {
    double a = 0.0;
    for (std::size_t c = 0; c < col.n; ++c)
      if (L >= col.base[c]) a += col.width * (L - col.base[c] + dx);
    return a;
  };
  const double area = static_cast<double>(n_water) * dx * dx;
  double a = *std::min_element(col.base.begin(), col.base.end()) - dx, b = col.hi;
  if (held(b) > area) {
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b);
      (held(m) > area ? b : a) = m;
    }
  }
  sp.level = b;
  const std::vector<double> t1(col.n, sp.level);
  for (std::size_t c = 0; c < col.n; ++c)
    if (!col.wet(c) && col.base[c] <= sp.level) sp.dry_length += col.width;
  const std::size_t n0 = wetted_contact(col, contact, col.bottom, col.top, r);
  const std::size_t n1 = wetted_contact(col, contact, col.base, t1, r);
  if (n0 > 0) sp.ratio = static_cast<double>(n1) / static_cast<double>(n0);
  return sp;
}

// Yield and damage of a Johnson–Cook body from its loading (the header comment): the
// clamps' velocities against the free material's initial velocity, the body's elastic
// constants, the Johnson–Cook hardening and failure constants and the end time T.
struct PlasticEstimate {
  std::string loading = "no clamps";
  double yield_fraction = 0.0;  // of the particle-sub-steps over [0, T]
  double yield_start = std::numeric_limits<double>::infinity();
  double damage_start = std::numeric_limits<double>::infinity();
};

PlasticEstimate estimate_plastic(const SolidBody& b, const JohnsonCookModel& jc, double T) {
  PlasticEstimate e;
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t n = b.size();
  if (n == 0 || T <= 0.0) return e;
  const double E = b.material.youngs_modulus, nu = b.material.poisson_ratio;
  const double rho = b.material.density;
  // The plane-strain bar (σ_yy = 0, ε_zz = 0): E' = E/(1-ν²), c = sqrt(E'/ρ); its elastic
  // state σ_zz = ν σ_xx reaches the yield stress A at σ_xx = A / sqrt(1-ν+ν²).
  const double Ep = E / (1.0 - nu * nu), c = std::sqrt(Ep / rho);
  const double sigma_y = jc.a / std::sqrt(1.0 - nu + nu * nu);
  const double eps_y = sigma_y / Ep, v_y = sigma_y / (rho * c);
  // The Johnson–Cook failure strain at the triaxiality of plane-strain tension, 1/√3 (σ_zz =
  // σ_xx/2 once plastic), without its rate and temperature terms.
  double eps_f = inf;
  if (jc.failure.kind == FailureKind::JohnsonCook)
    eps_f = jc.failure.d1 + jc.failure.d2 * std::exp(jc.failure.d3 / std::sqrt(3.0));
  else if (jc.failure.kind == FailureKind::CriticalPlasticStrain)
    eps_f = jc.failure.critical_plastic_strain;
  // Clamp groups (by clamp velocity) and the free material's mean initial velocity.
  struct Group {
    Vec2 v, centre;
    std::vector<std::size_t> members;
  };
  std::vector<Group> groups;
  Vec2 v_free{};
  std::size_t n_free = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i < b.clamped.size() && b.clamped[i]) {
      const Vec2 v = i < b.clamp_velocity.size() ? b.clamp_velocity[i] : Vec2{};
      auto g = std::find_if(groups.begin(), groups.end(),
                            [&](const Group& q) { return q.v.x == v.x && q.v.y == v.y; });
      if (g == groups.end()) g = groups.insert(groups.end(), Group{v, {}, {}});
      g->members.push_back(i);
      g->centre = g->centre + b.X[i];
    } else {
      v_free = v_free + b.v[i];
      ++n_free;
    }
  }
  if (groups.empty() || n_free == 0) return e;
  for (Group& g : groups) g.centre = 1.0 / static_cast<double>(g.members.size()) * g.centre;
  v_free = 1.0 / static_cast<double>(n_free) * v_free;
  const double support = b.kernel.support();
  // Fraction of the particles that are free and lie between `lo` and `hi` along `dir`.
  auto between = [&](Vec2 dir, double lo, double hi) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double s = dot(b.X[i], dir);
      if (!(i < b.clamped.size() && b.clamped[i]) && s > lo && s < hi) ++k;
    }
    return static_cast<double>(k) / static_cast<double>(n);
  };
  // ∫ fraction dt over [0, T], the fraction `f` from t0 until the damage at td, then the band
  // `f_band` at the failed section.
  auto fraction = [&](double f, double t0, double td, double f_band) {
    double a = f * std::max(0.0, std::min(T, td) - t0);
    if (td < T) a += f_band * (T - td);
    return std::clamp(a / T, 0.0, 1.0);
  };
  // An impact: the largest jump between a clamp and the free material.
  const Group* hit = nullptr;
  double dv_jump = 0.0;
  for (const Group& g : groups)
    if (norm(v_free - g.v) > dv_jump) {
      dv_jump = norm(v_free - g.v);
      hit = &g;
    }
  if (hit != nullptr && dv_jump > v_y) {
    e.loading = "impact";
    const Vec2 dir = 1.0 / dv_jump * (v_free - hit->v);
    double clamp_edge = -inf, far = -inf;
    for (std::size_t i : hit->members) clamp_edge = std::max(clamp_edge, dot(b.X[i], dir));
    for (std::size_t i = 0; i < n; ++i)
      if (!(i < b.clamped.size() && b.clamped[i])) far = std::max(far, dot(b.X[i], dir));
    const double L = std::max(far - clamp_edge, support);
    const double f_free = between(dir, clamp_edge, inf);
    const double t_cross = L / c;
    // The plastic strain at the clamp (von Kármán): Δv − v_y = sqrt(B n/ρ) 2/(n+1) ε^((n+1)/2).
    double eps_1 = inf;
    if (jc.b > 0.0 && jc.n > 0.0)
      eps_1 = std::pow((dv_jump - v_y) * 0.5 * (jc.n + 1.0) / std::sqrt(jc.b * jc.n / rho),
                       2.0 / (jc.n + 1.0));
    e.yield_start = 0.0;
    if (eps_1 >= eps_f) e.damage_start = t_cross;
    // While the elastic front crosses, the part behind it yields (on average half of it).
    const double t1 = std::min(T, e.damage_start);
    const double cross = std::min(t1, t_cross);
    double a = f_free * (cross * cross / (2.0 * t_cross) + std::max(0.0, t1 - t_cross));
    if (e.damage_start < T) a += f_free * std::min(1.0, 2.0 * support / L) * (T - e.damage_start);
    e.yield_fraction = std::clamp(a / T, 0.0, 1.0);
    return e;
  }
  // Clamps pulled apart (or pushed together): the fastest-straining gauge between two groups.
  double rate = 0.0, gauge = 0.0, f_gauge = 0.0;
  for (std::size_t p = 0; p < groups.size(); ++p)
    for (std::size_t q = p + 1; q < groups.size(); ++q) {
      const Vec2 d = groups[q].centre - groups[p].centre;
      if (norm(d) == 0.0) continue;
      const Vec2 dir = 1.0 / norm(d) * d;
      double lo = -inf, hi = inf;
      for (std::size_t i : groups[p].members) lo = std::max(lo, dot(b.X[i], dir));
      for (std::size_t i : groups[q].members) hi = std::min(hi, dot(b.X[i], dir));
      if (hi <= lo) continue;
      const double r = std::abs(dot(groups[q].v - groups[p].v, dir)) / (hi - lo);
      if (r > rate) {
        rate = r;
        gauge = hi - lo;
        f_gauge = between(dir, lo, hi);
      }
    }
  if (rate > 0.0) {
    e.loading = "clamps pulled apart";
    e.yield_start = eps_y / rate;
    // Damage once the nominal plastic strain reaches the failure strain: the axial plastic
    // strain of plane-strain flow is √3/2 of the equivalent one.
    e.damage_start = (eps_y + 0.5 * std::sqrt(3.0) * eps_f) / rate;
    e.yield_fraction = fraction(f_gauge, e.yield_start, e.damage_start,
                                f_gauge * std::min(1.0, 2.0 * support / gauge));
  }
  return e;
}

}  // namespace

double CostPrediction::wall_seconds(int threads) const {
  if (threads <= 1) return cpu_seconds();
  double w = (fluid_seconds + lists_seconds + contact_seconds) / fluid_speedup + output_seconds;
  double solid = 0.0;
  bool one_thread_bodies = true;
  for (const BodyCost& b : bodies) {
    if (!b.elastic) continue;
    solid += b.seconds / b.speedup;
    one_thread_bodies = one_thread_bodies && b.speedup == 1.0;
  }
  // Bodies whose sub-steps take one thread run them beside the water's pair pass when that
  // is faster (app/beside_choice.h): the pass then takes its one-thread time beside them
  // instead of its share of the water phase after them.
  if (one_thread_bodies && solid > 0.0 && water_pass_seconds > 0.0) {
    const double in_turn = solid + water_pass_seconds / fluid_speedup;
    const double beside = std::max(solid, water_pass_seconds);
    return w - water_pass_seconds / fluid_speedup + std::min(in_turn, beside);
  }
  return w + solid;
}

CostPrediction predict_cost(const Simulation& sim, const CostConstants& k) {
  const CaseConfig& cfg = sim.config();
  const NumericsConfig& num = cfg.numerics;
  const FluidParticles& fluid = sim.fluid();
  CostPrediction c;
  c.fluid_particles = fluid.size();
  c.contact_particles = sim.contact().size();
  const InteractionLists& lists = sim.stepper().lists();
  c.water_pairs = lists.ff().half.index.size();
  c.contact_pairs = lists.fc().index.size() + lists.cf().index.size();

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
  Spread spread;
  double fall_speed = 0.0;
  if (fluid.size() > 0 && g > 0.0) {
    const Columns col = make_columns(fluid, sim.contact(), -1.0 / g * num.gravity, num.dx);
    c.fall_height = fall_height(col);
    fall_speed = std::sqrt(2.0 * g * c.fall_height);
    v = std::max(v, fall_speed);
    spread = spread_at_rest(col, sim.contact(), num.dx, 2.0 * num.h_over_dx * num.dx, fluid.size());
  }
  c.speed = v;
  // The contact pairs over the run: the water that falls spreads over the dry floor at about
  // its fall speed, taking the pairs from the initial count to the count at rest (in
  // proportion to the wetted contact particles) in dry_length / fall_speed, and they stay
  // there: the peer dam break's rose from 4 446 to ~10 000 in its first 1.3 s of 6.4 and
  // averaged 9 639; cases/dam_break.toml's from 5 382 to 9 352 at its end (0.48 s), 7 147 on
  // average (docs/validation.md §6 "Cost model", session 14).
  c.contact_pairs_mean = static_cast<double>(c.contact_pairs);
  if (spread.dry_length > 0.0 && fall_speed > 0.0) {
    const double p0 = c.contact_pairs_mean, p1 = p0 * spread.ratio;
    const double ts = spread.dry_length / fall_speed, t = num.end_time;
    c.spread_seconds = ts;
    c.contact_pairs_rest = p1;
    c.contact_pairs_mean = t >= ts ? p1 - 0.5 * (p1 - p0) * ts / t : p0 + 0.5 * (p1 - p0) * t / ts;
  }

  const bool share = !num.dual_time_stepping || fluid.size() == 0;
  double dt = std::numeric_limits<double>::infinity();
  if (fluid.size() > 0) {
    const double h = num.h_over_dx * num.dx;
    dt = num.cfl * h / (cfg.fluid.sound_speed + v);
    c.limiter = "fluid acoustic CFL";
    const double ca = num.acceleration_cfl;  // 0: the bound is off
    if (ca > 0.0 && amax > 0.0 && ca * std::sqrt(h / amax) < dt) {
      dt = ca * std::sqrt(h / amax);
      c.limiter = "fluid acceleration (initial)";
    }
  }
  for (const SolidBody& b : sim.bodies()) {
    BodyCost bc;
    bc.name = b.name;
    bc.particles = b.size();
    bc.pairs = b.topology.pairs.index.size();
    bc.elastic = b.is_elastic();
    bc.stable_step = stable_time_step(b);
    bc.johnson_cook = std::holds_alternative<JohnsonCook>(b.material.law);
    bc.switched = switched_at_start(b);
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

  const double steps = static_cast<double>(c.fluid_steps);
  const double nw = static_cast<double>(c.fluid_particles);
  const double nc = static_cast<double>(c.contact_particles);
  const bool symplectic = num.fluid_integrator == FluidIntegrator::Symplectic;
  const double pass_factor = symplectic ? k.symplectic_step_factor : 1.0;
  if (c.fluid_particles > 0) {
    double pair_ns = log_interpolate(nw, k.water_n_small, k.water_n_large, k.water_pair_ns_small,
                                     k.water_pair_ns_large);
    // The lane loops run for the Wendland kernel only (fluid/gsph_pair_band.h).
    const bool wendland = sim.stepper().system().kernel_f.type() == KernelType::WendlandC2;
    if (wendland && gsph_band_avx2_available())
      pair_ns *= log_interpolate(nw, k.water_n_small, k.water_n_large, k.water_pair_lanes_small,
                                 k.water_pair_lanes_large);
    if (wendland && gsph_band_avx512_available())
      pair_ns *= log_interpolate(nw, k.water_n_small, k.water_n_large, k.water_pair_eight_small,
                                 k.water_pair_eight_large);
    c.water_pass_seconds =
        1e-9 * steps * pass_factor * pair_ns * static_cast<double>(c.water_pairs);
    c.fluid_seconds = c.water_pass_seconds + 1e-9 * steps * pass_factor * k.water_ns * nw;
    const FsiStepper& st = sim.stepper();
    const double per_rebuild =
        v * dt > 0.0 ? st.params().neighbour_skin * st.system().kernel_c.h() / (v * dt)
                     : std::numeric_limits<double>::infinity();
    c.rebuilds = static_cast<long>(std::ceil(steps / std::max(1.0, per_rebuild)));
    c.lists_seconds = 1e-9 * static_cast<double>(c.rebuilds) * k.rebuild_ns * (nw + nc);
    c.contact_seconds = 1e-9 * steps * pass_factor * k.contact_pair_ns * c.contact_pairs_mean;
  } else {
    c.contact_seconds = 1e-9 * steps * k.dry_contact_ns * nc;
  }
  // Without water the contact phase's loops are over a few thousand contact particles, under
  // Executor::kMinParallelCheap: they run on one thread (the tension bar 0.46-0.50 s on 1
  // thread and 0.47-0.52 s on 2, the Johnson-Cook bar 0.54 and 0.56-0.64 s, the oscillating
  // plate 9.2 and 8.0-9.8 s; docs/validation.md §6 "Cost model", session 18).
  c.fluid_speedup = c.fluid_particles == 0
                        ? 1.0
                        : log_interpolate(nw, k.fluid_n_small, k.fluid_n_large,
                                          k.fluid_speedup_small, k.fluid_speedup_large);
  // Field snapshots (and the skin's profile with them), drawn on one thread.
  for (double t : cfg.output.snapshots)
    if (t <= num.end_time * (1.0 + 1e-12)) ++c.snapshots;
  const bool profile = !cfg.output.skin_profile.empty() && cfg.output.skin_profile != "none";
  c.output_seconds = c.snapshots * (k.snapshot_s + (profile ? k.skin_profile_s : 0.0));
  // The sub-steps of a run with water share the caches with it (see CostConstants).
  const double wet = c.fluid_particles > 0 ? k.solid_wet_factor : 1.0;
  const Executor two(2);
  for (std::size_t i = 0; i < c.bodies.size(); ++i) {
    BodyCost& bc = c.bodies[i];
    if (!bc.elastic) continue;
    // As solid/body_dynamics.cpp: ceil(Δt/Δt_s), at least one, per call (two calls of Δt/2
    // with the symplectic step, app/fsi_stepper.cpp).
    const double calls = symplectic ? 2.0 : 1.0;
    bc.substeps_per_step =
        static_cast<long>(calls) *
        std::max(1L, static_cast<long>(std::ceil(dt / calls / bc.stable_step * (1.0 - 1e-12))));
    const long total = bc.substeps_per_step * c.fluid_steps;
    c.solid_substeps += total;
    const SolidBody& body = sim.bodies()[i];
    const double n = static_cast<double>(bc.particles);
    const double subs = static_cast<double>(total);
    // The pair loops run in lanes in calls of at least kMinLaneSubsteps sub-steps on an
    // AVX-512F CPU, without an Eulerian switch (solid/elastic_substep.cpp); then the sub-step
    // costs per particle, else per pair entry (see the header).
    bc.lanes = bc.substeps_per_step / static_cast<long>(calls) >= kMinLaneSubsteps &&
               substep_lanes_avx512_available() && bc.switched == 0;
    const double sub_seconds = bc.lanes
                                   ? 1e-9 * n * subs *
                                         log_interpolate(n, k.solid_n_small, k.solid_n_large,
                                                         k.solid_lane_ns, k.solid_lane_ns_large)
                                   : 1e-9 * static_cast<double>(bc.pairs) * subs *
                                         log_interpolate(n, k.solid_n_small, k.solid_n_large,
                                                         k.solid_pair_ns, k.solid_pair_ns_large);
    bc.seconds = wet * sub_seconds + 1e-9 * k.solid_call_ns * n * calls * steps;
    // The Eulerian path (see CostConstants): the current pairs rebuilt every sub-step over the
    // body, the switched particles' velocity gradients, stress maps and pair forces; beyond
    // the scalar Lagrangian sub-step of the same body over its reference pairs.
    if (bc.switched > 0)
      bc.seconds +=
          1e-9 * subs *
          (k.eulerian_particle_ns * n + k.eulerian_switched_ns * static_cast<double>(bc.switched));
    if (bc.johnson_cook) {
      const PlasticEstimate pe = estimate_plastic(
          body, std::get<JohnsonCook>(body.material.law).parameters().jc, num.end_time);
      bc.loading = pe.loading;
      bc.yield_fraction = pe.yield_fraction;
      bc.yield_start = pe.yield_start;
      bc.damage_start = pe.damage_start;
      bc.seconds += 1e-9 * n * subs *
                    (k.johnson_cook_elastic_ns + pe.yield_fraction * k.johnson_cook_yield_ns);
      if (pe.damage_start < num.end_time)
        bc.failure_seconds =
            1e-9 * k.failure_zone_ns * n * steps * (num.end_time - pe.damage_start) / num.end_time;
      c.contact_seconds += bc.failure_seconds;
    }
    c.solid_seconds += bc.seconds;
    // The team the sub-steps run on (solid/elastic_substep.cpp).
    bc.speedup = two.threads_for(bc.particles, kSubstepParticlesPerThread) > 1
                     ? log_interpolate(n, k.solid_speedup_n_small, k.solid_speedup_n_large,
                                       k.solid_speedup_small, k.solid_speedup_large)
                     : 1.0;
  }
  return c;
}

namespace {

// Repeats of each probe, the fastest taken: on the shared virtual machines of this kind the
// host takes a core away for tenths of a second now and then (session 13: 2 of 8 solid probes
// 40 % slow with three repeats).
constexpr int kProbeRepeats = 5;

// The built-in water probe of measure_machine_factors: CPU seconds of `steps` fluid steps on
// one thread (the fastest of kProbeRepeats) and their prediction.
std::pair<double, double> probe(const std::string& text, long steps, const CostConstants& k) {
  double best = std::numeric_limits<double>::infinity(), predicted = 0.0;
  for (int r = 0; r < kProbeRepeats; ++r) {
    Simulation sim(parse_case_string(text, "cost_probe.toml"), silent_options(1));
    const CostPrediction p = predict_cost(sim, k);
    predicted = p.cpu_seconds() * static_cast<double>(steps) /
                static_cast<double>(std::max(1L, p.fluid_steps));
    const std::clock_t c0 = std::clock();
    for (long s = 0; s < steps; ++s) sim.step();
    best = std::min(best, static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  return {best, predicted};
}

// CPU seconds per call of advance_body on one thread taking `substeps` sub-steps each (the
// fastest of kProbeRepeats repeats of `calls` calls, after one call that sizes the
// workspace), on a copy of `body`.
double seconds_per_call(const SolidBody& body, int substeps, int calls) {
  SolidBody b = body;
  const Executor one(1);
  double t = 0.0;
  auto advance = [&] {
    const double dt = substeps * stable_time_step(b) * (1.0 - 1e-9);
    advance_body(b, t, dt, {}, one);
    t += dt;
  };
  advance();
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < kProbeRepeats; ++r) {
    const std::clock_t c0 = std::clock();
    for (int c = 0; c < calls; ++c) advance();
    best = std::min(best, static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / calls);
  }
  return best;
}

}  // namespace

MachineFactors measure_machine_factors(const CostConstants& k) {
  const std::string water = R"(
schema_version = 1
name = "cost_probe_water"
[numerics]
dx = 0.01
end_time = 1.0
gravity = [0.0, -9.81]
[numerics.domain]
min = [-0.1, -0.1]
max = [0.9, 0.6]
[fluid]
sound_speed = 20.0
[[fluid.block]]
min = [0.0, 0.0]
max = [0.8, 0.4]
[[body]]
name = "tank"
kind = "rigid_fixed"
density = 1000.0
[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [0.8, 0.5]
layers = 4
)";
  // The fuselage skins' body (cases/skin_ring_reduced.toml, cases/fuselage/skin_cylinder.toml):
  // a 2-layer aluminium ring, 3.0 pair entries per particle.
  const std::string ring = R"(
schema_version = 1
name = "cost_probe_ring"
[numerics]
dx = 0.0015
end_time = 1.0
gravity = [0.0, 0.0]
[numerics.domain]
min = [-0.4, -0.4]
max = [0.4, 0.4]
[materials.aluminium]
model = "svk"
density = 2700.0
youngs_modulus = 67.5e9
poisson_ratio = 0.34
[[body]]
name = "ring"
material = "aluminium"
gravity = false
velocity = [0.0, 0.01]
[body.shape]
type = "ring"
centre = [0.0, 0.0]
inner_radius = 0.297
outer_radius = 0.3
layers = 2
)";
  MachineFactors f;
  const auto [wt, wp] = probe(water, 40, k);
  if (wp > 0.0 && wt > 0.0) f.fluid = wt / wp;
  // The solid's costs (per sub-step in lanes and in the scalar loops, per call) from the same
  // ring advanced one sub-step per call, kScalar and kLanes per call: the differences are
  // kScalar - 1 scalar sub-steps and kLanes - 1 sub-steps in lanes (whose call also lays the
  // pairs out for the lanes: a set-up per call, ~1/40 of the difference).
  const Simulation sim(parse_case_string(ring, "cost_probe.toml"), silent_options(1));
  const SolidBody& body = sim.bodies().front();
  const double n = static_cast<double>(body.size());
  const double lane =
      1e-9 * n *
      log_interpolate(n, k.solid_n_small, k.solid_n_large, k.solid_lane_ns, k.solid_lane_ns_large);
  const double scalar =
      1e-9 * static_cast<double>(body.topology.pairs.index.size()) *
      log_interpolate(n, k.solid_n_small, k.solid_n_large, k.solid_pair_ns, k.solid_pair_ns_large);
  const double call = 1e-9 * n * k.solid_call_ns;
  constexpr int kScalar = kMinLaneSubsteps - 1, kLanes = 40;
  const double one = seconds_per_call(body, 1, 100);
  const double few = seconds_per_call(body, kScalar, 20);
  const double many = seconds_per_call(body, kLanes, 5);
  if (lane > 0.0 && many > one) f.solid = (many - one) / ((kLanes - 1) * lane);
  if (scalar > 0.0 && few > one) {
    f.solid_scalar = (few - one) / ((kScalar - 1) * scalar);
    // The per-call part: what one call costs beyond its sub-step, at least a tenth of the
    // constant (a faster set-up than that is within the probes' noise).
    if (call > 0.0) f.solid_call = std::max(0.1, (one - f.solid_scalar * scalar) / call);
  }
  return f;
}

CostConstants scaled(const CostConstants& k, const MachineFactors& f) {
  CostConstants c = k;
  for (double* x : {&c.water_pair_ns_small, &c.water_pair_ns_large, &c.water_ns, &c.rebuild_ns,
                    &c.contact_pair_ns, &c.dry_contact_ns})
    *x *= f.fluid;
  for (double* x : {&c.solid_lane_ns, &c.solid_lane_ns_large}) *x *= f.solid;
  // The laws' own work runs scalar in either loop (solid/substep_law_lanes.h: SVK's excepted).
  for (double* x : {&c.solid_pair_ns, &c.solid_pair_ns_large, &c.johnson_cook_elastic_ns,
                    &c.johnson_cook_yield_ns, &c.eulerian_particle_ns, &c.eulerian_switched_ns})
    *x *= f.solid_scalar;
  c.solid_call_ns *= f.solid_call;
  // A failure zone's gathers: a cell grid, normals and layers, scalar loops over the body.
  c.failure_zone_ns *= f.solid_call;
  return c;
}

std::string describe_cost(const CostPrediction& c, int threads) {
  char buf[640];
  std::string s;
  std::snprintf(buf, sizeof buf,
                "predicted: %zu water and %zu contact particles (%zu water and %zu contact "
                "pairs listed); fluid step %.3g s (%s, speed %.3g m/s), %ld fluid steps, %ld "
                "neighbour rebuilds\n",
                c.fluid_particles, c.contact_particles, c.water_pairs, c.contact_pairs, c.dt,
                c.limiter.c_str(), c.speed, c.fluid_steps, c.rebuilds);
  s += buf;
  if (c.fluid_particles > 0) {
    std::snprintf(buf, sizeof buf,
                  "  the water can fall %.3g m; contact pairs %.0f on average over the run",
                  c.fall_height, c.contact_pairs_mean);
    s += buf;
    if (c.spread_seconds > 0.0) {
      std::snprintf(buf, sizeof buf,
                    " (the water spreads over the dry floor in ~%.2g s: %.0f pairs at rest)",
                    c.spread_seconds, c.contact_pairs_rest);
      s += buf;
    }
    s += "\n";
  }
  for (const BodyCost& b : c.bodies) {
    if (b.elastic)
      std::snprintf(
          buf, sizeof buf,
          "  body %s: %zu particles, elastic, %.3g pairs per particle, stable step "
          "%.3g s, %ld sub-steps per fluid step (pair loops %s%s), law %s\n",
          b.name.c_str(), b.particles,
          static_cast<double>(b.pairs) / static_cast<double>(b.particles), b.stable_step,
          b.substeps_per_step, b.lanes ? "in lanes" : "scalar",
          b.switched > 0
              ? ("; " + std::to_string(b.switched) + " particles on the Eulerian path").c_str()
              : "",
          b.johnson_cook ? "johnson_cook" : "svk");
    else
      std::snprintf(buf, sizeof buf, "  body %s: %zu particles, rigid\n", b.name.c_str(),
                    b.particles);
    s += buf;
    if (!b.elastic || !b.johnson_cook) continue;
    // Yield and failure are estimated from the loading (see the header): say so, and what.
    if (b.loading == "no clamps") {
      s += "    yield not estimated (no clamps: a load from water or contact is not seen); "
           "costed elastic, a body that yields throughout takes up to 3x longer\n";
      continue;
    }
    auto at = [](double t) {
      char w[48];
      if (std::isfinite(t))
        std::snprintf(w, sizeof w, "at %.3g s", t);
      else
        std::snprintf(w, sizeof w, "not within the run");
      return std::string(w);
    };
    std::snprintf(
        buf, sizeof buf,
        "    estimated from the loading (%s): starts to yield %s, yields in %.0f %% of its "
        "particle-sub-steps, fails %s (its cost: the solid and contact phases below)\n",
        b.loading.c_str(), at(b.yield_start).c_str(), 100.0 * b.yield_fraction,
        at(b.damage_start).c_str());
    s += buf;
  }
  std::snprintf(buf, sizeof buf,
                "predicted CPU time on 1 thread: %.3g s (water %.3g s, neighbour lists %.3g s, "
                "contact %.3g s, solid %.3g s, %d snapshots %.3g s)\n",
                c.cpu_seconds(), c.fluid_seconds, c.lists_seconds, c.contact_seconds,
                c.solid_seconds, c.snapshots, c.output_seconds);
  s += buf;
  const int t = std::max(1, threads);
  double solid_wall = 0.0;  // the sub-steps' share of wall_seconds(t)
  for (const BodyCost& b : c.bodies)
    if (b.elastic) solid_wall += t > 1 ? b.seconds / b.speedup : b.seconds;
  std::snprintf(buf, sizeof buf,
                "predicted wall time on an idle machine of this kind (2 cores): %.3g s on 1 "
                "thread, %.3g s on %d thread%s (solid sub-steps %.3g s; per-particle costs of "
                "app/cost_model.h)\n",
                c.wall_seconds(1), c.wall_seconds(t), t, t == 1 ? "" : "s", solid_wall);
  s += buf;
  return s;
}

}  // namespace slamsph
