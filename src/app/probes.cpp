#include "app/probes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.h"

namespace slamsph {

ProbeSet::ProbeSet(std::vector<ProbeConfig> probes, const std::vector<SolidBody>& bodies, double dx)
    : probes_(std::move(probes)), attached_(probes_.size()), dx_(dx) {
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    const ProbeConfig& pc = probes_[k];
    if (pc.body.empty()) continue;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].name != pc.body) continue;
      double best = std::numeric_limits<double>::max();
      for (std::size_t i = 0; i < bodies[b].size(); ++i) {
        const double d = norm2(bodies[b].X[i] - pc.position);
        if (d < best) best = d, attached_[k] = {b, i};
      }
    }
  }
}

std::vector<std::string> ProbeSet::headers() const {
  std::vector<std::string> h;
  for (const ProbeConfig& pc : probes_) {
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

std::vector<double> ProbeSet::row(const FsiStepper& st, const Executor& exec) const {
  const FsiSystem& sys = st.system();
  const FluidParticles& fluid = sys.fluid;
  std::vector<double> row;
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    const ProbeConfig& pc = probes_[k];
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
    } else if (pc.kind == "body_pressure") {
      const Attached& a = attached_[k];
      const std::size_t s = sys.layout.offset[a.body] + a.particle;
      // The pressure the contact can apply there: not below the cavitation limit (§4).
      const double p_cav = st.params().cavitation_pressure;
      row.push_back(sys.contact.wetted[s] ? std::max(sys.contact.p[s], p_cav) : 0.0);
    } else if (pc.kind == "body_displacement") {
      const Attached& a = attached_[k];
      const SolidBody& b = sys.bodies[a.body];
      row.push_back(b.x[a.particle].x - b.X[a.particle].x);
      row.push_back(b.x[a.particle].y - b.X[a.particle].y);
    }
  }
  return row;
}

double ProbeSet::value(std::size_t k, const FsiStepper& st, const Executor& exec) const {
  std::size_t col = 0;
  for (std::size_t q = 0; q < k; ++q) col += probes_[q].kind == "body_displacement" ? 2 : 1;
  return row(st, exec)[col];
}

}  // namespace slamsph
