#include "app/failure_log.h"

#include <cmath>
#include <numbers>

#include "app/keel_angle.h"
#include "io/json_writer.h"
#include "solid/materials/material_law_choice.h"

namespace slamsph {
namespace {

int slot_of(const SolidBody& b, std::string_view name) {
  for (std::size_t k = 0; k < b.history.fields.size(); ++k)
    if (b.history.fields[k].name == name) return static_cast<int>(k);
  return -1;
}

double value_of(const SolidBody& b, std::string_view name, std::size_t i) {
  const int k = slot_of(b, name);
  return k < 0 ? std::nan("") : b.history.values[static_cast<std::size_t>(k)][i];
}

// Column order of headers() and of a row.
enum Column { kTime, kBody, kParticle, kX, kY, kPart, kAngle, kTriax, kRate, kStrain, kTemp };

}  // namespace

void FailureLog::reset(const std::vector<SolidBody>& bodies) {
  active_ = false;
  failed_slot_.assign(bodies.size(), -1);
  centre_.assign(bodies.size(), Vec2{});
  seen_.assign(bodies.size(), {});
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const SolidBody& body = bodies[b];
    const int k = slot_of(body, "failed");
    if (k < 0) continue;
    if (const auto* jc = std::get_if<JohnsonCook>(&body.material.law))
      active_ = active_ || jc->parameters().jc.failure.kind != FailureKind::None;
    failed_slot_[b] = k;
    centre_[b] = reference_mass_centre(body);
    seen_[b].assign(body.size(), 0);
    const std::vector<double>& f = body.history.values[static_cast<std::size_t>(k)];
    for (std::size_t i = 0; i < body.size(); ++i) seen_[b][i] = f[i] > 0.5;
  }
}

std::vector<std::string> FailureLog::headers() {
  return {"time [s]",
          "body [-]",
          "particle [-]",
          "x [m]",
          "y [m]",
          "part [-]",
          "angle [deg]",
          "triaxiality [-]",
          "plastic_strain_rate [1/s]",
          "equivalent_plastic_strain [-]",
          "temperature [K]"};
}

std::vector<std::vector<double>> FailureLog::scan(const std::vector<SolidBody>& bodies,
                                                  double time) {
  std::vector<std::vector<double>> rows;
  for (std::size_t b = 0; b < bodies.size() && b < failed_slot_.size(); ++b) {
    if (failed_slot_[b] < 0) continue;
    const SolidBody& body = bodies[b];
    const std::vector<double>& f = body.history.values[static_cast<std::size_t>(failed_slot_[b])];
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (seen_[b][i] || f[i] < 0.5) continue;
      seen_[b][i] = 1;
      const Vec2 r = body.X[i] - centre_[b];
      const double angle = keel_angle_deg(r);
      const double part = body.part.size() == body.size() ? double(body.part[i]) : 0.0;
      rows.push_back({time, double(b), double(i), body.x[i].x, body.x[i].y, part, angle,
                      value_of(body, "triaxiality", i), value_of(body, "plastic_strain_rate", i),
                      value_of(body, "equivalent_plastic_strain", i),
                      value_of(body, "temperature", i)});
      if (first.empty()) first = rows.back();
    }
  }
  return rows;
}

JsonObject FailureLog::summary(const std::vector<SolidBody>& bodies) const {
  JsonObject out, counts;
  for (std::size_t b = 0; b < bodies.size() && b < failed_slot_.size(); ++b) {
    if (failed_slot_[b] < 0) continue;
    long n = 0;
    for (double v : bodies[b].history.values[static_cast<std::size_t>(failed_slot_[b])])
      n += v > 0.5;
    counts.set(bodies[b].name, n);
  }
  out.set("failed_particles", counts);
  if (first.empty()) {
    out.set_null("first");
  } else {
    JsonObject f;
    f.set("time_s", first[kTime]);
    f.set("body", bodies[static_cast<std::size_t>(first[kBody])].name);
    f.set("particle", static_cast<long>(first[kParticle]));
    f.set("position_m", std::vector<double>{first[kX], first[kY]});
    f.set("part", static_cast<long>(first[kPart]));
    f.set("angle_deg", first[kAngle]);
    f.set("triaxiality", first[kTriax]);
    f.set("plastic_strain_rate_per_s", first[kRate]);
    out.set("first", f);
  }
  return out;
}

}  // namespace slamsph
