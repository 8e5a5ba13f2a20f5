#include "app/probes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.h"
#include "solid/body_dynamics.h"
#include "solid/materials/st_venant_kirchhoff.h"
#include "solid/stress_update.h"

namespace slamsph {

namespace {

std::size_t nearest_particle(const SolidBody& b, Vec2 p) {
  double best = std::numeric_limits<double>::max();
  std::size_t k = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double d = norm2(b.X[i] - p);
    if (d < best) best = d, k = i;
  }
  return k;
}

// The particle whose reference position maximises key(X); ties (within 1e-9 m) go to the
// one nearest `centre` along the other axis, so a symmetric body gets its centre line.
template <class Key, class Across>
std::size_t extreme_particle(const SolidBody& b, Key key, Across across) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < b.size(); ++i) {
    const double d = key(b.X[i]) - key(b.X[k]);
    if (d > 1e-9 || (d > -1e-9 && across(b.X[i]) < across(b.X[k]))) k = i;
  }
  return k;
}

Vec2 centre_of_mass(const std::vector<Vec2>& x, const std::vector<double>& m) {
  Vec2 s;
  double ms = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) s += m[i] * x[i], ms += m[i];
  return ms > 0.0 ? (1.0 / ms) * s : s;
}

double strain_at(const SolidBody& b, std::size_t i) {
  if (!b.is_elastic() || b.F.size() != b.size()) return 0.0;
  return equivalent_strain(green_lagrange(b.F[i]));
}

}  // namespace

ProbeSet::ProbeSet(std::vector<ProbeConfig> probes, const std::vector<SolidBody>& bodies, double dx)
    : probes_(std::move(probes)), attached_(probes_.size()), dx_(dx) {
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    const ProbeConfig& pc = probes_[k];
    if (pc.body.empty()) continue;
    for (std::size_t bi = 0; bi < bodies.size(); ++bi) {
      const SolidBody& b = bodies[bi];
      if (b.name != pc.body || b.size() == 0) continue;
      Attached& a = attached_[k];
      a.body = bi;
      a.particle = nearest_particle(b, pc.position);
      a.to = nearest_particle(b, pc.to);
      a.at = nearest_particle(b, pc.at);
      a.com0 = centre_of_mass(b.X, b.m);
      const double cx = a.com0.x, cy = a.com0.y;
      a.top = extreme_particle(
          b, [](Vec2 p) { return p.y; }, [&](Vec2 p) { return std::abs(p.x - cx); });
      a.bottom = extreme_particle(
          b, [](Vec2 p) { return -p.y; }, [&](Vec2 p) { return std::abs(p.x - cx); });
      a.right = extreme_particle(
          b, [](Vec2 p) { return p.x; }, [&](Vec2 p) { return std::abs(p.y - cy); });
      a.left = extreme_particle(
          b, [](Vec2 p) { return -p.x; }, [&](Vec2 p) { return std::abs(p.y - cy); });
    }
  }
}

std::vector<std::string> ProbeSet::headers() const {
  std::vector<std::string> h;
  for (const ProbeConfig& pc : probes_) {
    const std::string& n = pc.name;
    if (pc.kind == "pressure" || pc.kind == "body_pressure") {
      h.push_back(n + " [Pa]");
    } else if (pc.kind == "max_speed") {
      h.push_back(n + " [m/s]");
    } else if (pc.kind == "fluid_volume") {
      h.push_back(n + " [m^2]");
    } else if (pc.kind == "body_displacement") {
      h.insert(h.end(), {n + "_x [m]", n + "_y [m]"});
    } else if (pc.kind == "body_strain") {
      h.push_back(n + " [-]");
    } else if (pc.kind == "body_stress") {
      h.insert(h.end(), {n + "_von_mises [Pa]", n + "_Pyy [Pa]"});
    } else if (pc.kind == "body_max_strain") {
      h.insert(h.end(), {n + " [-]", n + "_X [m]", n + "_Y [m]"});
    } else if (pc.kind == "ovalisation") {
      h.insert(h.end(), {n + "_dDv [m]", n + "_dDh [m]"});
    } else {
      h.push_back(n + " [m]");
    }
  }
  return h;
}

std::vector<double> ProbeSet::row(const FsiStepper& st, const Executor& exec) const {
  const FsiSystem& sys = st.system();
  const FluidParticles& fluid = sys.fluid;
  std::vector<double> row;
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    const ProbeConfig& pc = probes_[k];
    const Attached& a = attached_[k];
    const SolidBody* body = pc.body.empty() ? nullptr : &sys.bodies[a.body];
    auto u = [&](std::size_t i) { return body->x[i] - body->X[i]; };
    if (pc.kind == "pressure") {
      // Shepard-normalised kernel average of the fluid pressure at the point.
      double sw = 0.0, spw = 0.0;
      st.lists().fluid_grid().for_each_candidate(pc.position, [&](std::uint32_t j) {
        const double w = sys.kernel_f.w(norm(fluid.x[j] - pc.position));
        sw += w;
        spw += w * fluid.p[j];
      });
      row.push_back(sw > 0.0 ? spw / sw : 0.0);
    } else if (pc.kind == "surge_front") {
      // Leading edge: the largest particle x plus half a spacing (the particle's extent).
      const double xmax = exec.max_of(fluid.size(), [&](std::size_t i) { return fluid.x[i].x; });
      row.push_back(fluid.size() ? xmax + 0.5 * dx_ : 0.0);
    } else if (pc.kind == "water_height") {
      const double ymax = exec.max_of(fluid.size(), [&](std::size_t i) {
        return std::abs(fluid.x[i].x - pc.x) < 0.5 * dx_ ? fluid.x[i].y
                                                         : -std::numeric_limits<double>::max();
      });
      row.push_back(ymax > -1e300 ? ymax + 0.5 * dx_ : 0.0);
    } else if (pc.kind == "max_speed") {
      // Largest fluid particle speed: spurious currents in water meant to be at rest.
      row.push_back(std::sqrt(exec.max_of(
          fluid.size(), [&](std::size_t i) { return norm2(fluid.v[i]); }, 0.0)));
    } else if (pc.kind == "fluid_volume") {
      // Water inside the box (per unit depth): e.g. what came through a breach.
      row.push_back(exec.sum_of<double>(fluid.size(), [&](std::size_t i) {
        return inside(pc.box, fluid.x[i]) ? fluid.m[i] / fluid.rho[i] : 0.0;
      }));
    } else if (body && body->size() == 0) {
      row.insert(row.end(), headers_of_kind(pc.kind), 0.0);
    } else if (pc.kind == "body_pressure") {
      const std::size_t s = sys.layout.offset[a.body] + a.particle;
      // The pressure the contact can apply there: not below the cavitation limit (§4).
      const double p_cav = st.params().cavitation_pressure;
      row.push_back(sys.contact.wetted[s] ? std::max(sys.contact.p[s], p_cav) : 0.0);
    } else if (pc.kind == "body_displacement") {
      row.push_back(u(a.particle).x);
      row.push_back(u(a.particle).y);
    } else if (pc.kind == "body_strain") {
      row.push_back(strain_at(*body, a.particle));
    } else if (pc.kind == "body_stress") {
      const std::size_t i = a.particle;
      const bool el = body->is_elastic() && body->F.size() == body->size();
      row.push_back(
          el ? von_mises_stress(cauchy_from_pk1(body->P[i], body->F[i], cauchy_zz(*body, i)))
             : 0.0);
      row.push_back(el ? body->P[i].yy : 0.0);
    } else if (pc.kind == "body_max_strain") {
      // Serial scan: the first particle with the largest value, whatever the thread count.
      std::size_t best = 0;
      double emax = -1.0;
      for (std::size_t i = 0; i < body->size(); ++i) {
        const double e = strain_at(*body, i);
        if (e > emax) emax = e, best = i;
      }
      row.insert(row.end(), {emax, body->X[best].x, body->X[best].y});
    } else if (pc.kind == "keel_deflection") {
      const Vec2 c = centre_of_mass(body->x, body->m);
      row.push_back((body->x[a.bottom].y - c.y) - (body->X[a.bottom].y - a.com0.y));
    } else if (pc.kind == "ovalisation") {
      const auto& X = body->X;
      const auto& x = body->x;
      row.push_back((x[a.top].y - x[a.bottom].y) - (X[a.top].y - X[a.bottom].y));
      row.push_back((x[a.right].x - x[a.left].x) - (X[a.right].x - X[a.left].x));
    } else if (pc.kind == "shortening") {
      const auto& X = body->X;
      const auto& x = body->x;
      row.push_back(norm(X[a.to] - X[a.particle]) - norm(x[a.to] - x[a.particle]));
    } else if (pc.kind == "midspan_deflection") {
      // Chord from A (position) to B (to) in the reference configuration; the mid point's
      // displacement minus the chord's, interpolated at its projection, along the normal.
      const Vec2 A = body->X[a.particle], B = body->X[a.to], M = body->X[a.at];
      const Vec2 chord = B - A;
      const double s = std::clamp(dot(M - A, chord) / norm2(chord), 0.0, 1.0);
      const Vec2 n = (1.0 / norm(chord)) * Vec2{-chord.y, chord.x};
      const Vec2 rel = u(a.at) - ((1.0 - s) * u(a.particle) + s * u(a.to));
      row.push_back(dot(rel, n));
    }
  }
  return row;
}

double ProbeSet::value(std::size_t k, const FsiStepper& st, const Executor& exec) const {
  std::size_t col = 0;
  for (std::size_t q = 0; q < k; ++q) col += headers_of_kind(probes_[q].kind);
  return row(st, exec)[col];
}

std::size_t headers_of_kind(const std::string& kind) {
  if (kind == "body_displacement" || kind == "body_stress" || kind == "ovalisation") return 2;
  if (kind == "body_max_strain") return 3;
  return 1;
}

}  // namespace slamsph
