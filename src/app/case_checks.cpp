#include "app/case_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/cell_grid.h"
#include "core/error.h"
#include "geometry/shape_bounds.h"
#include "solid/body_dynamics.h"

namespace slamsph {

namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

double shape_area(const ShapeConfig& s, double dx) {
  if (s.type == "rectangle") return (s.box.max.x - s.box.min.x) * (s.box.max.y - s.box.min.y);
  if (s.type == "disc") return std::numbers::pi * s.radius * s.radius;
  if (s.type == "ring" || s.type == "fuselage")  // fuselage: its skin
    return std::numbers::pi * (s.outer_radius * s.outer_radius - s.inner_radius * s.inner_radius);
  if (s.type == "polygon") {
    double a = 0.0;
    for (std::size_t i = 0, j = s.vertices.size() - 1; i < s.vertices.size(); j = i++)
      a += cross(s.vertices[j], s.vertices[i]);
    return 0.5 * std::abs(a);
  }
  if (s.type == "tank") {
    const Box outer = shape_bounds(s, dx);
    return (outer.max.x - outer.min.x) * (outer.max.y - outer.min.y) -
           (s.box.max.x - s.box.min.x) * (s.box.max.y - s.box.min.y);
  }
  return 0.0;
}

double body_dx(const CaseConfig& cfg, const BodyConfig& b) {
  return b.dx > 0.0 ? b.dx : cfg.numerics.dx;
}

Box merge(const Box& a, const Box& b) {
  return {{std::min(a.min.x, b.min.x), std::min(a.min.y, b.min.y)},
          {std::max(a.max.x, b.max.x), std::max(a.max.y, b.max.y)}};
}

double cells(const Box& b, double cell) {
  return (std::floor((b.max.x - b.min.x) / cell) + 1.0) *
         (std::floor((b.max.y - b.min.y) / cell) + 1.0);
}

std::string key(const char* base, std::size_t i, const char* tail) {
  return std::string(base) + "[" + std::to_string(i) + "]" + tail;
}

}  // namespace

double estimate_particles(const CaseConfig& cfg) {
  const double dx = cfg.numerics.dx;
  double n = 0.0;
  for (const FluidBlockConfig& b : cfg.fluid.blocks)
    n += (b.box.max.x - b.box.min.x) * (b.box.max.y - b.box.min.y) / (dx * dx);
  for (const BodyConfig& b : cfg.bodies) {
    if (b.shape.type == "fuselage") {  // parts with their own spacings
      const FuselageShape& f = b.shape.fuselage;
      const double ds = f.skin_spacing(), df = f.floor_spacing();
      const double r_in = 0.5 * f.diameter - f.skin_thickness;
      n += shape_area(b.shape, ds) / (ds * ds);
      const FuselageStringers& g = f.stringers;
      n += g.count * (g.height * g.web_thickness + 2.0 * g.flange_width * g.flange_thickness) /
           (ds * ds);
      if (f.floor.present) n += 2.0 * r_in * f.floor.thickness / (df * df);
      n += static_cast<double>(f.columns.x.size()) * r_in * f.columns.width / (df * df);
      continue;
    }
    const double d = body_dx(cfg, b);
    n += shape_area(b.shape, d) / (d * d);
  }
  return n;
}

void check_case_size(const CaseConfig& cfg, double max_particles) {
  const double n = estimate_particles(cfg);
  if (!(n <= max_particles))
    throw InputError(cfg.where("numerics.dx") + ": the case would have about " + num(n) +
                     " particles (about " + num(n * 1e3 / 1e9) +
                     " GB at ~1 kB each), above the limit of " + num(max_particles) +
                     "; expected a larger dx, smaller bodies and blocks, or a higher "
                     "--max-particles");
  // The neighbour search bins particles into cells of the kernel support over their
  // bounding box (core/cell_grid.h): a body far from the rest makes that box, and the
  // memory of the grid, huge although the particle count is small.
  const double cell = 2.0 * cfg.numerics.h_over_dx * cfg.numerics.dx;
  std::vector<Box> parts;
  std::vector<std::string> part_keys;
  for (std::size_t i = 0; i < cfg.fluid.blocks.size(); ++i) {
    parts.push_back(cfg.fluid.blocks[i].box);
    part_keys.push_back(key("fluid.block", i, ""));
  }
  for (std::size_t i = 0; i < cfg.bodies.size(); ++i) {
    parts.push_back(shape_bounds(cfg.bodies[i].shape, body_dx(cfg, cfg.bodies[i])));
    part_keys.push_back(key("body", i, ".shape"));
  }
  if (!parts.empty()) {
    Box all = parts[0];
    for (const Box& b : parts) all = merge(all, b);
    const double c = cells(all, cell);
    const double limit = std::max(kMaxGridCells / 100.0, 50.0 * std::max(n, 1.0));
    if (c > std::min(limit, kMaxGridCells)) {
      // Name the part whose removal shrinks the box most: the one far from the others.
      std::size_t worst = 0;
      double best = c;
      for (std::size_t k = 0; k < parts.size() && parts.size() > 1; ++k) {
        Box rest = parts[k == 0 ? 1 : 0];
        for (std::size_t j = 0; j < parts.size(); ++j)
          if (j != k) rest = merge(rest, parts[j]);
        if (cells(rest, cell) < best) best = cells(rest, cell), worst = k;
      }
      throw InputError(cfg.where(part_keys[worst]) + ": the particles span " + num(c) +
                       " neighbour-search cells of " + num(cell) + " m for about " + num(n) +
                       " particles (limit " + num(std::min(limit, kMaxGridCells)) +
                       "); expected bodies and fluid close together");
    }
  }
  const double dc = cells(cfg.numerics.domain, cell);
  if (dc > kMaxGridCells)
    throw InputError(cfg.where("numerics.domain.max") + ": the domain spans " + num(dc) +
                     " neighbour-search cells of " + num(cell) + " m (limit " + num(kMaxGridCells) +
                     "), which particles leaving the water could fill; expected a domain "
                     "closer to the bodies and the fluid");
}

void check_built_case(const CaseConfig& cfg, const FsiSystem& sys) {
  const std::vector<SolidBody>& bodies = sys.bodies;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].size() == 0)
      throw InputError(cfg.where(key("body", b, ".shape")) + ": body '" + bodies[b].name +
                       "' has no particles at dx = " + num(bodies[b].dx) +
                       " m; expected a shape at least a particle spacing across");

  // Overlap: a particle of one body closer than a quarter of the sum of the spacings to a
  // particle of another (fluid is kept off bodies by the builder, bodies are not). Bodies
  // that only touch (a gate against its wall) have lattices about half that sum apart, or
  // a little less when a spacing does not divide a box; overlapping ones come much closer.
  for (std::size_t a = 0; a < bodies.size(); ++a)
    for (std::size_t b = a + 1; b < bodies.size(); ++b) {
      const SolidBody& A = bodies[a];
      const SolidBody& B = bodies[b];
      const double gap = 0.25 * (A.dx + B.dx);
      CellGrid grid;
      grid.build(B.X, std::max(A.dx, B.dx));
      for (std::size_t i = 0; i < A.size(); ++i) {
        bool hit = false;
        grid.for_each_candidate(A.X[i],
                                [&](std::uint32_t j) { hit = hit || norm(A.X[i] - B.X[j]) < gap; });
        if (hit)
          throw InputError(cfg.where(key("body", b, ".shape")) + ": body '" + B.name +
                           "' overlaps body '" + A.name + "' near (" + num(A.X[i].x) + ", " +
                           num(A.X[i].y) + ") m; expected bodies that do not overlap");
      }
    }

  // Stiffness: the solid's stable step against the largest fluid step (fluid at rest).
  const bool has_fluid = sys.fluid.size() > 0;
  const double dt_fluid = has_fluid ? cfg.numerics.cfl * sys.kernel_f.h() / cfg.fluid.sound_speed
                                    : cfg.numerics.end_time;
  const bool global = !cfg.numerics.dual_time_stepping || !has_fluid;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const double dts = stable_time_step(bodies[b]);
    if (!std::isfinite(dts)) continue;
    const BodyConfig& bc = cfg.bodies[b];
    const std::string k = "materials." + bc.material + ".youngs_modulus";
    if (!global && dt_fluid / dts > kMaxSubsteps)
      throw InputError(cfg.where(k) + ": body '" + bc.name +
                       "' is too stiff for the fluid step: each fluid step of up to " +
                       num(dt_fluid) + " s (fluid acoustic CFL) would need " + num(dt_fluid / dts) +
                       " solid sub-steps of " + num(dts) + " s (limit " + num(kMaxSubsteps) +
                       "); expected a softer material, a larger body dx or a faster fluid "
                       "sound speed");
    if (global && cfg.numerics.end_time / dts > kMaxSteps)
      throw InputError(cfg.where(k) + ": body '" + bc.name + "' is too stiff for a run of " +
                       num(cfg.numerics.end_time) + " s: its stable step " + num(dts) +
                       " s means " + num(cfg.numerics.end_time / dts) + " time steps (limit " +
                       num(kMaxSteps) + "); expected a softer material or a shorter end_time");
  }
}

}  // namespace slamsph
