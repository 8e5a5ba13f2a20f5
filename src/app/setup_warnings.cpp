#include "app/setup_warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/lattice_stability.h"

namespace slamsph {

namespace {

// Measured limit of still water against walls finer than the water (docs/model.md §4):
// ratio 3 and 4 unstable at h = 1.38 dx, ratio 2 (3.7 % of sqrt(gH)) and h = 1.5 dx at
// every ratio to 8 (<= 2.2 %) not.
constexpr double kUnstableSpacingRatio = 3.0;
constexpr double kStableHOverDxNextToFineBodies = 1.5;

// The finest particle spacing of a body as the case gives it: a fuselage's finest part
// (app/case_builder gives the body that spacing), else the body's dx.
double finest_body_spacing(const BodyConfig& b) {
  if (b.shape.type != "fuselage") return b.dx;
  const FuselageShape& f = b.shape.fuselage;
  double d = f.skin_spacing();
  if (f.floor.present) d = std::min(d, f.floor_spacing());
  return d;
}

void warn_fine_bodies_at_small_h(const CaseConfig& cfg, std::vector<std::string>& out) {
  const NumericsConfig& num = cfg.numerics;
  if (norm(num.gravity) == 0.0) return;  // no pressure at rest, nothing pushes the lattice
  if (num.h_over_dx >= kStableHOverDxNextToFineBodies * (1.0 - 1e-9)) return;
  for (std::size_t i = 0; i < cfg.bodies.size(); ++i) {
    const double d = finest_body_spacing(cfg.bodies[i]);
    if (!(d > 0.0)) continue;
    const double ratio = num.dx / d;
    if (ratio < kUnstableSpacingRatio * (1.0 - 1e-9)) continue;
    char buf[1000];
    std::snprintf(buf, sizeof buf,
                  "body[%zu] '%s' is %.3g times finer than the water (numerics.dx / body dx) at "
                  "numerics.h_over_dx = %.3g: water at rest next to a body 3 or more times finer "
                  "was measured unstable at h = 1.38 dx (spurious speeds 18 %% of sqrt(gH) at "
                  "ratio 3, 33 %% at ratio 4, growing, in a 0.5 m x 0.3 m tank over 0.6 s; "
                  "1.3 %% at ratio 4 in a 1 m x 0.5 m tank) and stable at h_over_dx = 1.5 (at "
                  "most 2.2 %% up to ratio 8, although the square-lattice analysis flags 1.5 for "
                  "long runs under pressure) and at ratio 2 (3.7 %%); use a spacing ratio below 3 "
                  "or numerics.h_over_dx = 1.5 (docs/model.md §4, \"Bodies finer than the "
                  "water\"; an elastic body that inherits it takes 15 %% more solid sub-steps, "
                  "docs/model.md §3 \"Solid stable step\").",
                  i, cfg.bodies[i].name.c_str(), ratio, num.h_over_dx);
    out.emplace_back(buf);
  }
}

// A ring's particles are spaced t/layers through the thickness and along the arc
// (geometry/polar_lattice.h) whatever the body's dx, while dx sets the body's smoothing
// length (docs/model.md §1, "Three smoothing lengths") and the spacing of its ghost layers
// (docs/model.md §4): with layers given explicitly, t/layers far from dx gives the solid
// kernel too few or too many neighbours and misplaces the ghosts. 25 % covers rounding.
constexpr double kRingSpacingTolerance = 0.25;

void warn_ring_spacing_mismatch(const CaseConfig& cfg, std::vector<std::string>& out) {
  for (std::size_t i = 0; i < cfg.bodies.size(); ++i) {
    const BodyConfig& b = cfg.bodies[i];
    if (b.shape.type != "ring" || b.shape.layers <= 0 || !(b.dx > 0.0)) continue;
    const double t = (b.shape.outer_radius - b.shape.inner_radius) / b.shape.layers;
    if (std::abs(t / b.dx - 1.0) <= kRingSpacingTolerance) continue;
    char buf[600];
    std::snprintf(buf, sizeof buf,
                  "body[%zu] '%s': the ring's %d layers space its particles %.3g m apart, but "
                  "the body's dx is %.3g m (it sets the body's smoothing length and ghost "
                  "spacing); set body[%zu].dx = %.3g (or spacing_ratio = numerics.dx / %.3g) "
                  "or drop shape.layers",
                  i, b.name.c_str(), b.shape.layers, t, b.dx, i, t, t);
    out.emplace_back(buf);
  }
}

}  // namespace

std::vector<std::string> setup_warnings(const CaseConfig& cfg) {
  std::vector<std::string> out;
  const NumericsConfig& num = cfg.numerics;
  warn_ring_spacing_mismatch(cfg, out);
  if (cfg.fluid.blocks.empty()) return out;
  warn_fine_bodies_at_small_h(cfg, out);
  // Two pressure scales load the start lattice: the hydrostatic rho g H of water at rest and
  // the acoustic impact pressure rho c0 V of a body entering at V (the first instants of a
  // slam, issue 9). The larger decides.
  const double g = norm(num.gravity);
  double depth = 0.0;
  for (const FluidBlockConfig& b : cfg.fluid.blocks)
    depth = std::max(depth, b.surface - b.box.min.y);
  double speed = 0.0;
  for (const BodyConfig& b : cfg.bodies) {
    if (b.kind == "rigid_fixed") continue;
    speed = std::max(speed, norm(b.velocity));
    for (const MotionPoint& m : b.motion) speed = std::max(speed, norm(m.v));
  }
  const double p_static = cfg.fluid.density * g * depth;
  const double p_impact = cfg.fluid.density * cfg.fluid.sound_speed * speed;
  if (p_static <= 0.0 && p_impact <= 0.0) return out;
  const LatticeStability s =
      square_lattice_stability(Kernel(num.kernel, num.h_over_dx * num.dx), num.dx);
  const double rate =
      lattice_growth_rate(s, std::max(p_static, p_impact), num.dx, cfg.fluid.density);
  char load[200];
  if (p_impact > p_static)
    std::snprintf(load, sizeof load,
                  "under the impact pressure rho c0 V = %.3g Pa of a body entering at %.3g m/s",
                  p_impact, speed);
  else
    std::snprintf(load, sizeof load, "under %.3g m of water", depth);
  if (rate * num.end_time <= 10.0) return out;
  const double stable = nearest_stable_h_over_dx(num.kernel, num.h_over_dx);
  char advice[128] = "no h_over_dx in [1.2, 2] is stable for this kernel";
  if (stable > 0.0)
    std::snprintf(advice, sizeof advice, "the nearest stable ratio for this kernel is %.2f",
                  stable);
  char buf[800];
  std::snprintf(buf, sizeof buf,
                "fluid under pressure on the square start lattice is unstable at "
                "numerics.h_over_dx = %.3g with the %s kernel: %s a zig-zag mode grows "
                "%.3g-fold per 0.1 s (e-folding %.3g s, end_time %.3g s). Water that stays under "
                "that pressure longer than ~%.2g s leaves the lattice (spurious speeds of a few "
                "%% of the flow's); %s (docs/model.md, \"Lattice stability\").",
                num.h_over_dx, kernel_name(num.kernel).c_str(), load, std::exp(0.1 * rate),
                1.0 / rate, num.end_time, 10.0 / rate, advice);
  out.emplace_back(buf);
  return out;
}

}  // namespace slamsph
