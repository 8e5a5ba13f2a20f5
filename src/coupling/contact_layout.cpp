#include "coupling/contact_layout.h"

#include <cmath>
#include <span>

#include "coupling/surface_normals.h"

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
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (const GhostSpec& g : plan_ghost_layers(
             bodies[b].X, l.ref_normals[b], particle_spacing(bodies[b]), support, 0.5 * fluid_dx))
      l.ghosts.push_back({static_cast<std::uint32_t>(b), g});
  return l;
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
                       const std::vector<SolidBody>& bodies) {
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const SolidBody& body = bodies[b];
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
    }
    // Faces opened by a crack: normals from the current configuration near failed particles.
    if (body.kind == BodyKind::Elastic)
      update_normals_near_failure(body, std::span<Vec2>(contact.normal).subspan(o, body.size()));
  }
  // Ghosts follow their parent along its current normal (coupling/ghost_layers.h).
  for (std::size_t g = 0; g < layout.ghosts.size(); ++g) {
    const ContactGhost& gh = layout.ghosts[g];
    const std::size_t c = layout.first_ghost() + g;
    const SolidBody& body = bodies[gh.body];
    const std::size_t parent = layout.offset[gh.body] + gh.spec.parent;
    const Vec2 n = contact.normal[parent];
    contact.anchor[c] = contact.x[parent];
    const double d = body.spacing.empty() ? body.dx : body.spacing[gh.spec.parent];
    contact.x[c] = contact.x[parent] - (gh.spec.depth * d) * n;
    contact.v[c] = contact.v[parent];
    contact.a[c] = contact.a[parent];
    contact.volume[c] = gh.spec.weight * contact.volume[parent];
    contact.normal[c] = n;
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
