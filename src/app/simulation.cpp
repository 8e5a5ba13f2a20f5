#include "app/simulation.h"

#include "app/setup_warnings.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "coupling/contact_rates.h"
#include "coupling/fluid_force_correction.h"
#include "coupling/leak_counter.h"
#include "coupling/surface_normals.h"
#include "coupling/virtual_pressure.h"
#include "fluid/gsph_fluid_rates.h"
#include "fluid/hydrostatic_init.h"
#include "geometry/geometry.h"
#include "solid/body_dynamics.h"

namespace slamsph {

namespace {

BodyKind body_kind(const std::string& k) {
  if (k == "elastic") return BodyKind::Elastic;
  if (k == "rigid_prescribed") return BodyKind::RigidPrescribed;
  if (k == "rigid_free") return BodyKind::RigidFree;
  return BodyKind::RigidFixed;
}

}  // namespace

Simulation::Simulation(CaseConfig config, const RunOptions& options)
    : cfg_(std::move(config)),
      opt_(options),
      exec_(options.threads > 0 ? options.threads : Executor::hardware_threads()) {
  if (opt_.end_time) cfg_.numerics.end_time = *opt_.end_time;
  warnings_ = setup_warnings(cfg_);
  const NumericsConfig& num = cfg_.numerics;
  kernel_f_ = Kernel(num.kernel, num.h_over_dx * num.dx);
  eos_ = TaitEos{cfg_.fluid.density, cfg_.fluid.sound_speed, cfg_.fluid.gamma};
  build_bodies();
  build_fluid();
  // Contact uses the larger smoothing length of fluid and body (spec §4, issue: finer skins).
  double hc = kernel_f_.h();
  for (const SolidBody& b : bodies_) hc = std::max(hc, b.kernel.h());
  kernel_c_ = Kernel(num.kernel, hc);
  const double skin = num.neighbour_skin * kernel_c_.support();
  lists_ = std::make_unique<InteractionLists>(kernel_f_.support(), kernel_c_.support(), skin);
  build_contact();
  loads_.assign(bodies_.size(), BodyLoad{});
  attach_probes();
  evaluate_rates();
}

Simulation::~Simulation() = default;

// The fluid's view of all solid particles: every body's particles, then the ghost layers
// behind thin bodies (coupling/ghost_layers.h).
void Simulation::build_contact() {
  contact_offset_.assign(bodies_.size() + 1, 0);
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    contact_offset_[b + 1] = contact_offset_[b] + bodies_[b].size();
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    for (const GhostSpec& g :
         plan_ghost_layers(bodies_[b].X, ref_normals_[b], bodies_[b].dx, kernel_c_.support()))
      ghosts_.push_back({static_cast<std::uint32_t>(b), g});
  contact_.resize(contact_offset_.back() + ghosts_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    for (std::size_t i = 0; i < bodies_[b].size(); ++i) {
      contact_.body[contact_offset_[b] + i] = static_cast<std::uint32_t>(b);
      contact_.local[contact_offset_[b] + i] = static_cast<std::uint32_t>(i);
    }
  for (std::size_t g = 0; g < ghosts_.size(); ++g) {
    const std::size_t c = contact_offset_.back() + g;
    contact_.body[c] = ghosts_[g].body;
    contact_.local[c] = ghosts_[g].spec.parent;
    contact_.ghost[c] = 1;
  }
}

// Probes attached to bodies follow the body particle nearest to their start position.
void Simulation::attach_probes() {
  attached_.assign(cfg_.output.probes.size(), AttachedProbe{});
  for (std::size_t k = 0; k < cfg_.output.probes.size(); ++k) {
    const ProbeConfig& pc = cfg_.output.probes[k];
    if (pc.body.empty()) continue;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      if (bodies_[b].name != pc.body) continue;
      double best = std::numeric_limits<double>::max();
      for (std::size_t i = 0; i < bodies_[b].size(); ++i) {
        const double d = norm2(bodies_[b].X[i] - pc.position);
        if (d < best) best = d, attached_[k] = {b, i};
      }
    }
  }
}

void Simulation::build_bodies() {
  const NumericsConfig& num = cfg_.numerics;
  for (const BodyConfig& bc : cfg_.bodies) {
    SolidBody body;
    body.name = bc.name;
    body.kind = body_kind(bc.kind);
    body.scheme = bc.scheme == "tlsph" ? SolidScheme::TlSph : SolidScheme::TlSfpm;
    body.dx = bc.dx > 0.0 ? bc.dx : num.dx;
    const ParticleLattice lat = build_shape(bc.shape, body.dx);
    const MaterialConfig* mat = cfg_.find_material(bc.material);
    const double rho = bc.density > 0.0 ? bc.density : (mat ? mat->density : cfg_.fluid.density);
    body.X = lat.x;
    body.x = lat.x;
    body.V0 = lat.volume;
    body.layer = lat.layer;
    body.rho0.assign(lat.x.size(), rho);
    body.m.resize(lat.x.size());
    for (std::size_t i = 0; i < lat.x.size(); ++i) body.m[i] = rho * lat.volume[i];
    body.v.assign(lat.x.size(), Vec2{});
    body.a.assign(lat.x.size(), Vec2{});
    body.f_fluid.assign(lat.x.size(), Vec2{});
    body.clamped.assign(lat.x.size(), 0);
    try {
      setup_body(body, bc, mat, num);
    } catch (const InputError& e) {
      // Setup finds what the parser cannot (e.g. a shape too small for its spacing): name
      // the file and the key like the parser does.
      throw InputError(cfg_.source_path + ": body[" + std::to_string(bodies_.size()) +
                       "].shape: " + e.what() + "; expected a shape several particle " +
                       "spacings across (dx = " + std::to_string(body.dx) + " m)");
    }
    ref_normals_.push_back(reference_surface_normals(body.X, body.V0, body.kernel));
    bodies_.push_back(std::move(body));
  }
}

void Simulation::build_fluid() {
  const NumericsConfig& num = cfg_.numerics;
  std::vector<Vec2> solid_pts;
  double solid_dx = num.dx;
  for (const SolidBody& b : bodies_) {
    solid_pts.insert(solid_pts.end(), b.x.begin(), b.x.end());
    solid_dx = std::min(solid_dx, b.dx);
  }
  for (const FluidBlockConfig& blk : cfg_.fluid.blocks) {
    const ParticleLattice lat = fill_box(blk.box, num.dx);
    // Keep fluid one half spacing off any body surface (1e-9 guards exact ties).
    const double gap = 0.5 * (num.dx + solid_dx) * (1.0 - 1e-9);
    const std::vector<std::size_t> keep = remove_overlap(lat.x, solid_pts, gap);
    std::vector<Vec2> pts;
    pts.reserve(keep.size());
    for (std::size_t k : keep) pts.push_back(lat.x[k]);
    append_hydrostatic_block(fluid_, pts, num.dx, blk.surface, num.gravity, eos_);
  }
}

void Simulation::gather_contact() {
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const SolidBody& body = bodies_[b];
    const std::size_t o = contact_offset_[b];
    const bool moves = body.kind != BodyKind::RigidFixed;
    for (std::size_t i = 0; i < body.size(); ++i) {
      contact_.x[o + i] = body.x[i];
      contact_.v[o + i] = body.v[i];
      contact_.a[o + i] = body.a[i];
      contact_.volume[o + i] = body.volume(i);
      Vec2 n = ref_normals_[b][i];
      if (moves && norm2(n) > 0.0) {
        if (body.kind == BodyKind::Elastic) {
          n = transpose(inverse(body.F[i])) * n;  // Nanson: n ∝ F^-T N
        } else {
          const double c = std::cos(body.rigid.angle), s = std::sin(body.rigid.angle);
          n = Vec2{c * n.x - s * n.y, s * n.x + c * n.y};
        }
        n = n / norm(n);
      }
      contact_.normal[o + i] = n;
    }
  }
  // Ghosts follow their parent along its current normal (coupling/ghost_layers.h).
  for (std::size_t g = 0; g < ghosts_.size(); ++g) {
    const std::size_t c = contact_offset_.back() + g;
    const SolidBody& body = bodies_[ghosts_[g].body];
    const std::size_t parent = contact_offset_[ghosts_[g].body] + ghosts_[g].spec.parent;
    const Vec2 n = contact_.normal[parent];
    contact_.anchor[c] = contact_.x[parent];
    contact_.x[c] = contact_.x[parent] - (ghosts_[g].spec.depth * body.dx) * n;
    contact_.v[c] = contact_.v[parent];
    contact_.a[c] = contact_.a[parent];
    contact_.volume[c] = contact_.volume[parent];
    contact_.normal[c] = n;
  }
}

void Simulation::evaluate_rates() {
  gather_contact();
  lists_->update(fluid_, contact_, exec_);
  const NumericsConfig& num = cfg_.numerics;
  const GsphParams gp{eos_.c0, cfg_.fluid.limiter_omega, cfg_.fluid.viscosity, num.gravity};
  const ContactParams cp{eos_.c0, cfg_.fluid.limiter_omega, cfg_.fluid.viscosity, num.gravity};
  if (fluid_.size() > 0) {
    compute_virtual_state(contact_, fluid_, lists_->cf(), kernel_c_, eos_, num.gravity, exec_);
    compute_gsph_fluid_rates(fluid_, lists_->ff(), kernel_f_, gp, exec_);
    add_contact_to_fluid(fluid_, contact_, lists_->fc(), kernel_c_, cp, exec_);
    compute_contact_reaction(contact_, fluid_, lists_->cf(), kernel_c_, cp, exec_);
    leaked_ = update_leak_flags(fluid_, contact_, lists_->fc(), exec_);
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    SolidBody& body = bodies_[b];
    const std::size_t o = contact_offset_[b];
    for (std::size_t i = 0; i < body.size(); ++i) body.f_fluid[i] = contact_.force[o + i];
  }
  // A ghost's force acts on its parent particle.
  for (std::size_t g = 0; g < ghosts_.size(); ++g) {
    const std::size_t c = contact_offset_.back() + g;
    bodies_[ghosts_[g].body].f_fluid[ghosts_[g].spec.parent] += contact_.force[c];
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    BodyLoad load;
    for (const Vec2& f : bodies_[b].f_fluid) load.total += f;
    loads_[b] = load;
  }
  for (std::size_t c = 0; c < contact_.size(); ++c)
    loads_[contact_.body[c]].viscous += contact_.force_viscous[c];
}

StepLimit Simulation::compute_step() const {
  const NumericsConfig& num = cfg_.numerics;
  StepLimit lim{std::numeric_limits<double>::infinity(), "none"};
  if (fluid_.size() > 0) {
    const double vmax = std::sqrt(exec_.max_of(
        fluid_.size(), [&](std::size_t i) { return norm2(fluid_.v[i]); }, 0.0));
    const double amax = std::sqrt(exec_.max_of(
        fluid_.size(), [&](std::size_t i) { return norm2(fluid_.a[i]); }, 0.0));
    const double h = kernel_f_.h();
    lim = {num.cfl * h / (eos_.c0 + vmax), "fluid acoustic CFL"};
    if (amax > 0.0) {
      const double dta = 0.25 * std::sqrt(h / amax);
      if (dta < lim.dt) lim = {dta, "fluid acceleration"};
    }
  }
  // Solids: one global step unless dual time stepping (or no fluid to sub-cycle within).
  const bool global = !num.dual_time_stepping || fluid_.size() == 0;
  for (const SolidBody& b : bodies_) {
    const double dts = stable_time_step(b);
    if (global && dts < lim.dt) lim = {dts, "solid CFL (body " + b.name + ")"};
  }
  if (!std::isfinite(lim.dt)) lim = {cfg_.numerics.end_time / 100.0, "end time / 100"};
  return lim;
}

void Simulation::step() {
  limit_ = compute_step();
  const double dt = limit_.dt;
  if (!(dt >= cfg_.numerics.dt_floor)) {
    std::ostringstream os;
    os << "time step " << dt << " s fell below numerics.dt_floor = " << cfg_.numerics.dt_floor
       << " s at t = " << time_ << " s; limiting criterion: " << limit_.limiter;
    if (limit_.limiter.rfind("fluid", 0) == 0 && fluid_.size() > 0) {
      std::size_t worst = 0;
      double best = -1.0;
      const bool acc = limit_.limiter == "fluid acceleration";
      for (std::size_t i = 0; i < fluid_.size(); ++i) {
        const double q = norm2(acc ? fluid_.a[i] : fluid_.v[i]);
        if (q > best) best = q, worst = i;
      }
      os << "; fluid particle " << fluid_.id[worst] << " has |" << (acc ? "a" : "v")
         << "| = " << std::sqrt(best);
    }
    throw DivergenceError(os.str());
  }
  FluidParticles& f = fluid_;
  const double hdt = 0.5 * dt;
  exec_.for_each(f.size(), [&](std::size_t i) {
    f.v_half[i] = f.v[i] + hdt * f.a[i];
    f.rho_half[i] = f.rho[i] + hdt * f.drho[i];
    f.x[i] += dt * f.v_half[i];
    f.v[i] = f.v_half[i] + hdt * f.a[i];  // predicted, for the velocity-dependent rates
    f.rho[i] = f.rho_half[i] + hdt * f.drho[i];
    f.p[i] = eos_.pressure(f.rho[i]);
  });
  f_old_.resize(bodies_.size());  // the fluid force each body is advanced with (reused storage)
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    f_old_[b] = bodies_[b].f_fluid;
    advance_body(bodies_[b], time_, dt, cfg_.numerics.gravity, exec_);
    if (bodies_[b].is_elastic()) solid_substeps_ += bodies_[b].last_substeps;
  }
  time_ += dt;
  evaluate_rates();
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    correct_for_new_fluid_force(bodies_[b], f_old_[b], dt);
  exec_.for_each(f.size(), [&](std::size_t i) {
    f.v[i] = f.v_half[i] + hdt * f.a[i];
    f.rho[i] = f.rho_half[i] + hdt * f.drho[i];
    f.p[i] = eos_.pressure(f.rho[i]);
  });
  ++steps_;
  check_state();
}

void Simulation::check_state() const {
  const Box& d = cfg_.numerics.domain;
  auto bad_fluid = [&](std::size_t i) {
    const Vec2 x = fluid_.x[i];
    const bool finite = std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(fluid_.v[i].x) &&
                        std::isfinite(fluid_.v[i].y) && std::isfinite(fluid_.rho[i]);
    return !finite || x.x < d.min.x || x.x > d.max.x || x.y < d.min.y || x.y > d.max.y;
  };
  const double any = exec_.max_of(
      fluid_.size(), [&](std::size_t i) { return bad_fluid(i) ? 1.0 : 0.0; }, 0.0);
  if (any > 0.0) {
    for (std::size_t i = 0; i < fluid_.size(); ++i) {
      if (!bad_fluid(i)) continue;
      std::ostringstream os;
      const Vec2 x = fluid_.x[i];
      const bool finite = std::isfinite(x.x) && std::isfinite(x.y);
      os << "fluid particle " << fluid_.id[i] << " at t = " << time_ << " s: ";
      if (!finite || !std::isfinite(fluid_.v[i].x) || !std::isfinite(fluid_.v[i].y))
        os << "position/velocity is not finite";
      else if (!std::isfinite(fluid_.rho[i]))
        os << "density is not finite";
      else
        os << "left the domain at (" << x.x << ", " << x.y << ") m with velocity (" << fluid_.v[i].x
           << ", " << fluid_.v[i].y << ") m/s";
      os << "; last step " << limit_.dt << " s limited by " << limit_.limiter;
      throw DivergenceError(os.str());
    }
  }
  for (const SolidBody& b : bodies_) {
    for (std::size_t i = 0; i < b.size(); ++i) {
      const Vec2 x = b.x[i];
      if (std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(b.v[i].x) &&
          std::isfinite(b.v[i].y) && x.x >= d.min.x && x.x <= d.max.x && x.y >= d.min.y &&
          x.y <= d.max.y)
        continue;
      std::ostringstream os;
      os << "body '" << b.name << "' particle " << i << " at t = " << time_ << " s: "
         << (std::isfinite(x.x) && std::isfinite(x.y) ? "left the domain"
                                                      : "position/velocity is not finite")
         << "; last step " << limit_.dt << " s limited by " << limit_.limiter;
      throw DivergenceError(os.str());
    }
  }
}

Vec2 Simulation::total_momentum() const {
  Vec2 p;
  for (std::size_t i = 0; i < fluid_.size(); ++i) p += fluid_.m[i] * fluid_.v[i];
  for (const SolidBody& b : bodies_) {
    if (b.kind == BodyKind::RigidFixed || b.kind == BodyKind::RigidPrescribed) continue;
    if (b.kind == BodyKind::RigidFree) {
      p += b.rigid.mass * b.rigid.vel;
      continue;
    }
    for (std::size_t i = 0; i < b.size(); ++i) p += b.m[i] * b.v[i];
  }
  return p;
}

std::vector<std::string> Simulation::probe_headers() const {
  std::vector<std::string> h;
  for (const ProbeConfig& pc : cfg_.output.probes) {
    if (pc.kind == "pressure" || pc.kind == "body_pressure") {
      h.push_back(pc.name + " [Pa]");
    } else if (pc.kind == "max_speed") {
      h.push_back(pc.name + " [m/s]");
    } else if (pc.kind == "body_displacement") {
      h.push_back(pc.name + "_x [m]");
      h.push_back(pc.name + "_y [m]");
    } else {
      h.push_back(pc.name + " [m]");
    }
  }
  return h;
}

std::vector<double> Simulation::probe_row() const {
  std::vector<double> row;
  const double dx = cfg_.numerics.dx;
  for (std::size_t k = 0; k < cfg_.output.probes.size(); ++k) {
    const ProbeConfig& pc = cfg_.output.probes[k];
    if (pc.kind == "pressure") {
      // Shepard-normalised kernel average of the fluid pressure at the point.
      double sw = 0.0, spw = 0.0;
      lists_->fluid_grid().for_each_candidate(pc.position, [&](std::uint32_t j) {
        const double w = kernel_f_.w(norm(fluid_.x[j] - pc.position));
        sw += w;
        spw += w * fluid_.p[j];
      });
      row.push_back(sw > 0.0 ? spw / sw : 0.0);
    } else if (pc.kind == "surge_front") {
      // Leading edge: the largest particle x plus half a spacing (the particle's extent).
      const double xmax = exec_.max_of(fluid_.size(), [&](std::size_t i) { return fluid_.x[i].x; });
      row.push_back(fluid_.size() ? xmax + 0.5 * dx : 0.0);
    } else if (pc.kind == "water_height") {
      const double ymax = exec_.max_of(fluid_.size(), [&](std::size_t i) {
        return std::abs(fluid_.x[i].x - pc.x) < 0.5 * dx ? fluid_.x[i].y
                                                         : -std::numeric_limits<double>::max();
      });
      row.push_back(ymax > -1e300 ? ymax + 0.5 * dx : 0.0);
    } else if (pc.kind == "max_speed") {
      // Largest fluid particle speed: spurious currents in water meant to be at rest.
      row.push_back(std::sqrt(exec_.max_of(
          fluid_.size(), [&](std::size_t i) { return norm2(fluid_.v[i]); }, 0.0)));
    } else if (pc.kind == "body_pressure") {
      const AttachedProbe& a = attached_[k];
      const std::size_t s = contact_offset_[a.body] + a.particle;
      row.push_back(contact_.wetted[s] ? contact_.p[s] : 0.0);
    } else if (pc.kind == "body_displacement") {
      const AttachedProbe& a = attached_[k];
      const SolidBody& b = bodies_[a.body];
      row.push_back(b.x[a.particle].x - b.X[a.particle].x);
      row.push_back(b.x[a.particle].y - b.X[a.particle].y);
    }
  }
  return row;
}

double Simulation::probe_value(std::size_t k) const {
  std::size_t col = 0;
  for (std::size_t q = 0; q < k; ++q)
    col += cfg_.output.probes[q].kind == "body_displacement" ? 2 : 1;
  return probe_row()[col];
}

}  // namespace slamsph
