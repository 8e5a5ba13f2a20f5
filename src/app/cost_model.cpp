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
#include "solid/materials/johnson_cook.h"
#include "solid/solid_body.h"

namespace slamsph {
namespace {

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

}  // namespace

double CostPrediction::wall_seconds(int threads) const {
  if (threads <= 1) return cpu_seconds();
  double w = (fluid_seconds + lists_seconds + contact_seconds) / fluid_speedup;
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
    BodyCost bc{
        b.name, b.size(), b.topology.pairs.index.size(), b.is_elastic(), stable_time_step(b), 0};
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
    const double n = static_cast<double>(bc.particles);
    const double pair_ns = log_interpolate(n, k.solid_n_small, k.solid_n_large, k.solid_pair_ns,
                                           k.solid_pair_ns_large);
    bc.seconds = 1e-9 * (pair_ns * bc.law_factor * static_cast<double>(bc.pairs) *
                             static_cast<double>(total) +
                         k.solid_call_ns * n * calls * steps);
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
  const std::string plate = R"(
schema_version = 1
name = "cost_probe_plate"
[numerics]
dx = 0.002
end_time = 1.0
gravity = [0.0, 0.0]
[numerics.domain]
min = [-0.1, -0.1]
max = [0.3, 0.1]
[materials.plate]
density = 1000.0
youngs_modulus = 2.0e6
poisson_ratio = 0.3975
[[body]]
name = "plate"
material = "plate"
gravity = false
velocity = [0.0, 0.01]
[body.shape]
type = "rectangle"
min = [0.0, 0.0]
max = [0.2, 0.04]
)";
  MachineFactors f;
  const auto [wt, wp] = probe(water, 40, k);
  if (wp > 0.0 && wt > 0.0) f.fluid = wt / wp;
  // The solid's two costs (per sub-step, per call) from the same vibrating plate advanced one
  // sub-step per call and kSubsteps per call: their difference is kSubsteps - 1 sub-steps.
  const Simulation sim(parse_case_string(plate, "cost_probe.toml"), silent_options(1));
  const SolidBody& body = sim.bodies().front();
  const double n = static_cast<double>(body.size());
  const double sub =
      1e-9 * static_cast<double>(body.topology.pairs.index.size()) *
      log_interpolate(n, k.solid_n_small, k.solid_n_large, k.solid_pair_ns, k.solid_pair_ns_large);
  const double call = 1e-9 * n * k.solid_call_ns;
  constexpr int kSubsteps = 40;
  const double one = seconds_per_call(body, 1, 100);
  const double many = seconds_per_call(body, kSubsteps, 5);
  if (sub > 0.0 && many > one) {
    f.solid = (many - one) / ((kSubsteps - 1) * sub);
    // The per-call part: what one call costs beyond its sub-step, at least a tenth of the
    // calibration runs' (a faster set-up than that is within the probes' noise).
    if (call > 0.0) f.solid_call = std::max(0.1, (one - f.solid * sub) / call);
  }
  return f;
}

CostConstants scaled(const CostConstants& k, const MachineFactors& f) {
  CostConstants c = k;
  for (double* x : {&c.water_pair_ns_small, &c.water_pair_ns_large, &c.water_ns, &c.rebuild_ns,
                    &c.contact_pair_ns, &c.dry_contact_ns})
    *x *= f.fluid;
  for (double* x : {&c.solid_pair_ns, &c.solid_pair_ns_large}) *x *= f.solid;
  c.solid_call_ns *= f.solid_call;
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
      std::snprintf(buf, sizeof buf,
                    "  body %s: %zu particles, elastic, %.3g pairs per particle, stable step "
                    "%.3g s, %ld sub-steps per fluid step, law cost x%.3g\n",
                    b.name.c_str(), b.particles,
                    static_cast<double>(b.pairs) / static_cast<double>(b.particles), b.stable_step,
                    b.substeps_per_step, b.law_factor);
    else
      std::snprintf(buf, sizeof buf, "  body %s: %zu particles, rigid\n", b.name.c_str(),
                    b.particles);
    s += buf;
    // The law factor is the elastic path's with little yield (fitted on 60 steps); a body that
    // yields throughout iterates its return mapping in every sub-step: x5.7-7.8 an SVK sub-step
    // on a plate that yields everywhere (docs/validation.md §6 "Cost model", session 14; the
    // notched specimen's sub-steps ran 2.3x the prediction).
    if (b.elastic && b.law_factor != 1.0)
      s += "    (its law cost assumes mostly elastic sub-steps: a body that yields throughout "
           "takes up to 3x longer)\n";
  }
  std::snprintf(buf, sizeof buf,
                "predicted CPU time on 1 thread: %.3g s (water %.3g s, neighbour lists %.3g s, "
                "contact %.3g s, solid %.3g s)\n",
                c.cpu_seconds(), c.fluid_seconds, c.lists_seconds, c.contact_seconds,
                c.solid_seconds);
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
