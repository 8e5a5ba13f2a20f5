#include "coupling/contact_layout.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "coupling/failure_zone_ghosts.h"
#include "coupling/surface_normals.h"
#include "solid/eulerian_failed_interaction.h"

namespace slamsph {

namespace {

// Each particle's own spacing (a body of parts: SolidBody::spacing; ghosts are planned and
// placed at the parent's spacing, coupling/ghost_layers.h), the body's dx if none is set.
std::vector<double> particle_spacing(const SolidBody& body) {
  if (body.spacing.size() == body.size()) return body.spacing;
  return std::vector<double>(body.size(), body.dx);
}

}  // namespace

ContactLayout plan_contact_layout(const std::vector<SolidBody>& bodies,
                                  std::vector<std::vector<Vec2>> ref_normals, double support,
                                  double fluid_dx) {
  ContactLayout l;
  l.ref_normals = std::move(ref_normals);
  l.offset.assign(bodies.size() + 1, 0);
  for (std::size_t b = 0; b < bodies.size(); ++b) l.offset[b + 1] = l.offset[b] + bodies[b].size();
  l.support = support;
  l.ghost_spacing = 0.5 * fluid_dx;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (const GhostSpec& g : plan_ghost_layers(
             bodies[b].X, l.ref_normals[b], particle_spacing(bodies[b]), support, l.ghost_spacing))
      l.ghosts.push_back({static_cast<std::uint32_t>(b), g});
  l.reference_ghosts = l.ghosts;
  l.planned_failed.assign(bodies.size(), 0);
  l.zone.assign(bodies.size(), {});
  return l;
}

bool replan_around_failures(ContactLayout& l, const std::vector<SolidBody>& bodies) {
  bool changed = false;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const std::vector<double>* failed = bodies[b].is_elastic() ? failed_flags(bodies[b]) : nullptr;
    std::size_t count = 0;
    if (failed != nullptr)
      for (double f : *failed) count += f > 0.5 ? 1 : 0;
    if (count != l.planned_failed[b]) changed = true;
    l.planned_failed[b] = count;
  }
  if (!changed) return false;
  // Per body: the reference ghosts of particles outside the failure zone, then the slots of
  // the intact zone particles (in particle order), so the layout is a function of the flags.
  std::vector<ContactGhost> ghosts;
  std::size_t r = 0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const SolidBody& body = bodies[b];
    l.zone[b] = l.planned_failed[b] > 0 ? failure_zone(body) : std::vector<std::uint8_t>{};
    const std::vector<std::uint8_t>& zone = l.zone[b];
    for (; r < l.reference_ghosts.size() && l.reference_ghosts[r].body == b; ++r)
      if (zone.empty() || !zone[l.reference_ghosts[r].spec.parent])
        ghosts.push_back(l.reference_ghosts[r]);
    if (zone.empty()) continue;
    const std::vector<double>& failed = *failed_flags(body);
    const std::vector<double> spacing = particle_spacing(body);
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (!zone[i] || failed[i] > 0.5) continue;
      const int slots = ghost_depths(spacing[i], l.support, l.ghost_spacing).slots();
      for (int j = 0; j < slots; ++j) {
        ContactGhost g{static_cast<std::uint32_t>(b), GhostSpec{}, j};
        g.spec.parent = static_cast<std::uint32_t>(i);
        g.spec.weight = 0.0;
        ghosts.push_back(g);
      }
    }
  }
  l.ghosts = std::move(ghosts);
  return true;
}

void init_contact_particles(ContactParticles& contact, const ContactLayout& layout) {
  contact.resize(layout.size());
  const std::size_t nb = layout.offset.size() - 1;
  for (std::size_t b = 0; b < nb; ++b)
    for (std::size_t c = layout.offset[b]; c < layout.offset[b + 1]; ++c) {
      contact.body[c] = static_cast<std::uint32_t>(b);
      contact.local[c] = static_cast<std::uint32_t>(c - layout.offset[b]);
    }
  for (std::size_t g = 0; g < layout.ghosts.size(); ++g) {
    const std::size_t c = layout.first_ghost() + g;
    contact.body[c] = layout.ghosts[g].body;
    contact.local[c] = layout.ghosts[g].spec.parent;
    contact.ghost[c] = 1;
  }
}

void gather_body_state(ContactParticles& contact, const ContactLayout& layout,
                       const std::vector<SolidBody>& bodies, bool refresh_fixed) {
  std::vector<std::vector<int>> present(bodies.size());  // layers behind slot parents
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const SolidBody& body = bodies[b];
    if (!refresh_fixed && body.kind == BodyKind::RigidFixed) continue;
    const std::size_t o = layout.offset[b];
    const bool moves = body.kind != BodyKind::RigidFixed;
    for (std::size_t i = 0; i < body.size(); ++i) {
      contact.x[o + i] = body.x[i];
      contact.v[o + i] = body.v[i];
      contact.a[o + i] = body.a[i];
      contact.volume[o + i] = body.volume(i);
      Vec2 n = layout.ref_normals[b][i];
      if (moves && norm2(n) > 0.0) {
        if (body.kind == BodyKind::Elastic) {
          n = transpose(inverse(body.F[i])) * n;  // Nanson: n ∝ F^-T N
        } else {
          const double c = std::cos(body.rigid.angle), s = std::sin(body.rigid.angle);
          n = Vec2{c * n.x - s * n.y, s * n.x + c * n.y};
        }
        n = n / norm(n);
      }
      contact.normal[o + i] = n;
      contact.debris[o + i] = 0;
    }
    if (body.kind != BodyKind::Elastic) continue;
    // Faces opened by a crack: normals from the current configuration near failed particles,
    // and the layers behind the slots' parents counted there (coupling/failure_zone_ghosts.h).
    if (layout.zone.size() <= b || layout.zone[b].empty()) continue;
    const std::vector<std::uint8_t>& zone = layout.zone[b];
    const std::span<Vec2> normals = std::span<Vec2>(contact.normal).subspan(o, body.size());
    // One cell list over the body's current positions for both (cells of the kernel support,
    // and at least the layer probe's 0.75 d of the coarsest part).
    double cell = body.kernel.support();
    for (double d : body.spacing) cell = std::max(cell, d);
    CellGrid grid;
    grid.build(body.x, cell);
    update_normals_near_failure(body, grid, zone, normals);
    const std::vector<double>& failed = *failed_flags(body);
    for (std::size_t i = 0; i < body.size(); ++i) contact.debris[o + i] = failed[i] > 0.5;
    present[b] = layers_behind_now(body, grid, normals, zone, layout.support);
  }
  // Ghosts follow their parent along its current normal (coupling/ghost_layers.h).
  for (std::size_t g = 0; g < layout.ghosts.size(); ++g) {
    const ContactGhost& gh = layout.ghosts[g];
    const std::size_t c = layout.first_ghost() + g;
    const SolidBody& body = bodies[gh.body];
    if (!refresh_fixed && body.kind == BodyKind::RigidFixed) continue;
    const std::size_t parent = layout.offset[gh.body] + gh.spec.parent;
    const Vec2 n = contact.normal[parent];
    contact.anchor[c] = contact.x[parent];
    const double d = body.spacing.empty() ? body.dx : body.spacing[gh.spec.parent];
    double depth = gh.spec.depth, weight = gh.spec.weight;
    if (gh.slot >= 0) {
      const GhostDepths gd = ghost_depths(d, layout.support, layout.ghost_spacing);
      const int behind = present[gh.body][gh.spec.parent];
      depth = gd.depth(behind, gh.slot);
      weight = norm2(n) > 0.0 ? gd.weight(behind, gh.slot) : 0.0;
    }
    contact.x[c] = contact.x[parent] - (depth * d) * n;
    contact.v[c] = contact.v[parent];
    contact.a[c] = contact.a[parent];
    contact.volume[c] = weight * contact.volume[parent];
    contact.normal[c] = n;
    contact.debris[c] = 0;
  }
}

void scatter_contact_forces(const ContactParticles& contact, const ContactLayout& layout,
                            std::vector<SolidBody>& bodies) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    SolidBody& body = bodies[b];
    const std::size_t o = layout.offset[b];
    for (std::size_t i = 0; i < body.size(); ++i) body.f_fluid[i] = contact.force[o + i];
  }
  // A ghost's force acts on its parent particle.
  for (std::size_t g = 0; g < layout.ghosts.size(); ++g) {
    const std::size_t c = layout.first_ghost() + g;
    bodies[layout.ghosts[g].body].f_fluid[layout.ghosts[g].spec.parent] += contact.force[c];
  }
}

}  // namespace slamsph
