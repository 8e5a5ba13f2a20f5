#include "app/case_builder.h"

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "coupling/surface_normals.h"
#include "fluid/hydrostatic_init.h"
#include "geometry/geometry.h"
#include "solid/body_dynamics.h"

namespace slamsph {

namespace {

std::string body_key(const CaseConfig& cfg, std::size_t index, const char* key) {
  return cfg.source_path + ": body[" + std::to_string(index) + "]." + key;
}

SolidBody build_body(const CaseConfig& cfg, std::size_t index) {
  const BodyConfig& bc = cfg.bodies[index];
  BodySetup setup = body_setup_from_case(cfg, index);
  SolidBody body;
  body.name = bc.name;
  body.kind = setup.kind;
  body.scheme = setup.scheme;
  body.eulerian_switch = setup.eulerian_switch;
  body.dx = setup.dx;
  ParticleLattice lat;
  try {
    lat = build_shape(bc.shape, body.dx);
    // Elastic bodies are stored along the structure, not part by part and layer by layer:
    // the sub-step's pair sums then read nearby memory and each thread's share touches the
    // other's in few places (geometry/structure_order.h, docs/model.md §3 "Particle order").
    if (setup.kind == BodyKind::Elastic) lat = ordered_along_structure(lat, body.dx);
  } catch (const FuselageShapeError& e) {
    throw InputError(cfg.where("body[" + std::to_string(index) + "].shape." + e.key) + ": " +
                     e.what());
  }
  // Shapes made of parts with their own spacings (a fuselage): the body's dx, kernel and
  // stable step are those of the finest part.
  double finest = 0.0;
  for (double d : lat.spacing)
    if (d > 0.0 && (finest == 0.0 || d < finest)) finest = d;
  if (finest > 0.0) setup.dx = body.dx = finest;
  body.spacing = lat.spacing;
  for (double& d : body.spacing)
    if (d == 0.0) d = body.dx;
  body.part = lat.part;
  if (bc.shape.type == "fuselage") body.part_names = fuselage_part_names();
  const MaterialConfig* mat = cfg.find_material(bc.material);
  const double rho = bc.density > 0.0 ? bc.density : (mat ? mat->density : cfg.fluid.density);
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
  if (!bc.pre_failed.empty()) {
    bool any = false;
    for (const Vec2& X : body.X)
      for (const Box& b : bc.pre_failed) any = any || inside(b, X);
    if (!any)
      throw InputError(cfg.where("body[" + std::to_string(index) + "].pre_failed") +
                       ": no particle of the body lies inside its boxes; expected boxes around "
                       "particles of the body, in reference coordinates (m)");
  }
  try {
    setup_body(body, setup);
  } catch (const InputError& e) {
    // Setup finds what the parser cannot (e.g. a shape too small for its spacing): name
    // the file and the key like the parser does.
    throw InputError(cfg.where("body[" + std::to_string(index) + "].shape") + ": " + e.what() +
                     "; expected a shape several particle " +
                     "spacings across (dx = " + std::to_string(body.dx) + " m)");
  }
  return body;
}

void build_fluid(const CaseConfig& cfg, const std::vector<SolidBody>& bodies, const TaitEos& eos,
                 FluidParticles& fluid) {
  const NumericsConfig& num = cfg.numerics;
  std::vector<Vec2> solid_pts;
  double solid_dx = num.dx;
  for (const SolidBody& b : bodies) {
    solid_pts.insert(solid_pts.end(), b.x.begin(), b.x.end());
    solid_dx = std::min(solid_dx, b.dx);
  }
  for (const FluidBlockConfig& blk : cfg.fluid.blocks) {
    const ParticleLattice lat = fill_box(blk.box, num.dx);
    // Keep fluid one half spacing off any body surface (1e-9 guards exact ties).
    const double gap = 0.5 * (num.dx + solid_dx) * (1.0 - 1e-9);
    const std::vector<std::size_t> keep = remove_overlap(lat.x, solid_pts, gap);
    std::vector<Vec2> pts;
    pts.reserve(keep.size());
    for (std::size_t k : keep) pts.push_back(lat.x[k]);
    append_hydrostatic_block(fluid, pts, num.dx, blk.surface, num.gravity, eos);
  }
}

}  // namespace

BodySetup body_setup_from_case(const CaseConfig& cfg, std::size_t index) {
  const BodyConfig& bc = cfg.bodies.at(index);
  const NumericsConfig& num = cfg.numerics;
  BodySetup s;
  s.name = bc.name;
  const std::optional<BodyKind> kind = body_kind_from_name(bc.kind);
  if (!kind) throw InputError(body_key(cfg, index, "kind") + ": unknown kind '" + bc.kind + "'");
  s.kind = *kind;
  const std::optional<SolidScheme> scheme = solid_scheme_from_name(bc.scheme);
  if (!scheme)
    throw InputError(body_key(cfg, index, "scheme") + ": unknown scheme '" + bc.scheme + "'");
  s.scheme = *scheme;
  s.dx = bc.dx > 0.0 ? bc.dx : num.dx;
  s.h_over_dx = bc.h_over_dx > 0.0 ? bc.h_over_dx : num.h_over_dx;
  s.kernel = num.kernel;
  s.solid_cfl = num.solid_cfl;
  s.gravity = bc.gravity;
  s.velocity = bc.velocity;
  s.angular_velocity = bc.angular_velocity;
  s.clamp_boxes = bc.clamp.boxes;
  s.clamp_velocities = bc.clamp.velocities;
  s.clamp_layers = bc.clamp.layers;
  s.pre_failed_boxes = bc.pre_failed;
  for (const MotionPoint& p : bc.motion) s.motion.push_back({p.t, p.v});
  s.mass = bc.mass;
  s.inertia = bc.inertia;
  s.allow_rotation = bc.allow_rotation;
  if (s.kind != BodyKind::Elastic) return s;

  const MaterialConfig* mat = cfg.find_material(bc.material);
  if (mat == nullptr)
    throw InputError(body_key(cfg, index, "material") + ": elastic body needs a material ('" +
                     bc.material + "' not found)");
  s.material =
      ElasticMaterialInput{mat->name,          mat->model,    mat->density, mat->youngs_modulus,
                           mat->poisson_ratio, mat->av_alpha, mat->av_beta, mat->hourglass};
  s.eulerian_switch = bc.failed_particles == "eulerian";
  if (bc.initial_profile == "cantilever_mode") {
    // The parser requires exactly one clamp box with a cantilever mode.
    const double clamp_edge =
        bc.clamp.boxes.empty() ? bc.shape.box.min.x : bc.clamp.boxes.front().max.x;
    s.cantilever_mode =
        CantileverModeInput{clamp_edge, bc.shape.box.max.x - clamp_edge, bc.mode_vf};
  } else if (!bc.initial_profile.empty()) {
    throw InputError(body_key(cfg, index, "initial_profile") + ": unknown initial_profile '" +
                     bc.initial_profile + "'");
  }
  return s;
}

BuiltCase build_case(const CaseConfig& cfg) {
  const NumericsConfig& num = cfg.numerics;
  BuiltCase out;
  FsiParams& p = out.params;
  p.gravity = num.gravity;
  p.cfl = num.cfl;
  p.acceleration_cfl = num.acceleration_cfl;
  p.dt_floor = num.dt_floor;
  p.end_time = num.end_time;
  p.dual_time_stepping = num.dual_time_stepping;
  p.fluid_force_correction = num.fluid_force_correction;
  p.fluid_integrator = num.fluid_integrator;
  p.domain = num.domain;
  p.limiter_omega = cfg.fluid.limiter_omega;
  p.viscosity = cfg.fluid.viscosity;
  p.cavitation_pressure = cfg.fluid.cavitation_pressure;
  p.hydrostatic_correction = cfg.fluid.hydrostatic_correction;
  p.contact_barrier = cfg.fluid.contact_barrier;
  p.substep_average = num.substep_average;
  p.wall_acceleration = num.wall_acceleration;
  p.neighbour_skin = num.neighbour_skin;
  if (cfg.fluid.absorbing_zone.active()) {
    // The zone lines the walls of the case's one tank (checked by the parser); the
    // hydrostatic reference is the still surface of the highest water block.
    const AbsorbingZoneConfig& a = cfg.fluid.absorbing_zone;
    AbsorbingZone& z = p.absorbing_zone;
    for (const BodyConfig& b : cfg.bodies)
      if (b.shape.type == "tank") z.inner = b.shape.box;
    z.width = {a.left, a.right, a.bottom, a.top};
    for (int w = 0; w < 4; ++w)
      z.sigma_wall[w] = z.width[w] > 0.0 ? a.strength * cfg.fluid.sound_speed / z.width[w] : 0.0;
    z.surface = -std::numeric_limits<double>::infinity();
    for (const FluidBlockConfig& blk : cfg.fluid.blocks)
      z.surface = std::max(z.surface, blk.surface);
    if (cfg.fluid.blocks.empty()) z.surface = z.inner.min.y;
    z.gravity = num.gravity;
  }

  FsiSystem& s = out.system;
  s.kernel_f = Kernel(num.kernel, num.h_over_dx * num.dx);
  s.eos = TaitEos{cfg.fluid.density, cfg.fluid.sound_speed, cfg.fluid.gamma};
  std::vector<std::vector<Vec2>> ref_normals;
  for (std::size_t b = 0; b < cfg.bodies.size(); ++b) {
    s.bodies.push_back(build_body(cfg, b));
    const SolidBody& body = s.bodies.back();
    ref_normals.push_back(reference_surface_normals(body.X, body.V0, body.kernel));
  }
  build_fluid(cfg, s.bodies, s.eos, s.fluid);
  // Contact uses the larger smoothing length of fluid and body (spec §4, finer skins).
  double hc = s.kernel_f.h();
  for (const SolidBody& b : s.bodies) hc = std::max(hc, b.kernel.h());
  s.kernel_c = Kernel(num.kernel, hc);
  s.layout = plan_contact_layout(s.bodies, std::move(ref_normals), s.kernel_c.support(), num.dx);
  init_contact_particles(s.contact, s.layout);
  return out;
}

}  // namespace slamsph
