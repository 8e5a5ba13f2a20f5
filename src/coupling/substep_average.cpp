#include "coupling/substep_average.h"

namespace slamsph {

void SubstepAverage::begin(const SolidBody& body) {
  x0 = body.x;
  v0 = body.v;
  valid = false;
}

void SubstepAverage::end(const SolidBody& body, double dt) {
  const std::size_t n = body.size();
  v_mean.resize(n);
  a_mean.resize(n);
  const double inv_dt = 1.0 / dt;
  for (std::size_t i = 0; i < n; ++i) {
    v_mean[i] = (body.x[i] - x0[i]) * inv_dt;
    a_mean[i] = (body.v[i] - v0[i]) * inv_dt;
  }
  valid = dt > 0.0;
}

void apply_substep_average(ContactParticles& contact, const ContactLayout& layout, std::size_t b,
                           const SubstepAverage& avg) {
  if (!avg.valid) return;
  const std::size_t o = layout.offset[b];
  for (std::size_t i = 0; i < avg.v_mean.size(); ++i) {
    contact.v[o + i] = avg.v_mean[i];
    contact.a[o + i] = avg.a_mean[i];
  }
  for (std::size_t g = 0; g < layout.ghosts.size(); ++g) {
    const ContactGhost& gh = layout.ghosts[g];
    if (gh.body != b) continue;
    const std::size_t c = layout.first_ghost() + g, parent = o + gh.spec.parent;
    contact.v[c] = contact.v[parent];
    contact.a[c] = contact.a[parent];
  }
}

}  // namespace slamsph
