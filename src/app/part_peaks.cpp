#include "app/part_peaks.h"

#include "app/keel_angle.h"

#include <string>

#include "io/json_writer.h"
#include "solid/materials/st_venant_kirchhoff.h"

namespace slamsph {
namespace {

std::size_t part_count(const SolidBody& b) {
  return b.part_names.empty() ? std::size_t{1} : b.part_names.size();
}

std::size_t part_of(const SolidBody& b, std::size_t i) {
  return b.part.size() == b.size() ? std::size_t{b.part[i]} : std::size_t{0};
}

}  // namespace

void PartPeaks::reset(const std::vector<SolidBody>& bodies) {
  offset_.clear();
  std::size_t n = 0;
  for (const SolidBody& b : bodies) offset_.push_back(n), n += part_count(b) * kFields;
  state.assign(n, 0.0);
}

void PartPeaks::update(const std::vector<SolidBody>& bodies, double time) {
  for (std::size_t bi = 0; bi < bodies.size() && bi < offset_.size(); ++bi) {
    const SolidBody& b = bodies[bi];
    if (!b.is_elastic() || b.F.size() != b.size()) continue;
    const std::size_t parts = part_count(b);
    for (std::size_t i = 0; i < b.size(); ++i) {
      const std::size_t p = part_of(b, i);
      if (p >= parts) continue;
      const double e = equivalent_strain(green_lagrange(b.F[i]));
      double* s = &state[offset_[bi] + p * kFields];
      if (e > s[0]) s[0] = e, s[1] = time, s[2] = double(i), s[3] = b.x[i].x, s[4] = b.x[i].y;
    }
  }
}

std::vector<JsonObject> PartPeaks::summary(const std::vector<SolidBody>& bodies) const {
  std::vector<JsonObject> out;
  for (std::size_t bi = 0; bi < bodies.size() && bi < offset_.size(); ++bi) {
    const SolidBody& b = bodies[bi];
    const std::size_t parts = part_count(b);
    std::vector<long> count(parts, 0);
    for (std::size_t i = 0; i < b.size(); ++i)
      if (part_of(b, i) < parts) ++count[part_of(b, i)];
    const bool strained = b.is_elastic() && b.F.size() == b.size();
    const Vec2 centre = reference_mass_centre(b);
    std::vector<JsonObject> table;
    for (std::size_t p = 0; p < parts; ++p) {
      JsonObject o;
      o.set("id", static_cast<long>(p));
      o.set("name", b.part_names.empty() ? std::string("body") : b.part_names[p]);
      o.set("particles", count[p]);
      if (strained && count[p] > 0) {
        const double* s = &state[offset_[bi] + p * kFields];
        o.set("peak_equivalent_strain", s[0]);
        o.set("peak_time_s", s[1]);
        o.set("peak_particle", static_cast<long>(s[2]));
        o.set("peak_position_m", std::vector<double>{s[3], s[4]});
        // Where on the structure: the particle's reference position and its angle from the
        // keel about the reference mass centre (as failure.csv), which a moving body's
        // current position does not tell.
        const std::size_t i = static_cast<std::size_t>(s[2]);
        if (i < b.size()) {
          o.set("peak_reference_position_m", std::vector<double>{b.X[i].x, b.X[i].y});
          o.set("peak_angle_deg", keel_angle_deg(b.X[i] - centre));
        }
      }
      table.push_back(o);
    }
    JsonObject body;
    body.set("body", b.name);
    body.set("parts", table);
    out.push_back(body);
  }
  return out;
}

}  // namespace slamsph
