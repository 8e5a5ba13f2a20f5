#include "solid/elastic_substep.h"

#include <span>
#include <utility>
#include <variant>

#include "core/parallel.h"
#include "solid/artificial_viscosity.h"
#include "solid/deformation_gradient.h"
#include "solid/hourglass_control.h"
#include "solid/stress_update.h"
#include "solid/tl_pair_force.h"

namespace slamsph {
namespace {

template <class Law>
void substeps_with(const Law& law, SolidBody& body, int steps, double h, Vec2 g,
                   const Executor& exec) {
  const std::size_t n = body.size();
  const SolidTopology& topo = body.topology;
  const SolidMaterial& mat = body.material;
  SubstepWorkspace& w = body.substep;
  w.resize(n, topo.pairs.index.size());
  body.f_av.resize(n);
  body.f_hg.resize(n);
  const double alpha = mat.hourglass;
  const bool hourglass = alpha != 0.0;
  const bool viscous = !(mat.av_alpha == 0.0 && mat.av_beta == 0.0);
  const double hh = 0.5 * h;
  const std::span<const std::uint32_t> start = topo.pairs.start, index = topo.pairs.index;
  auto kappa = [&](std::uint32_t k) { return w.kappa[k]; };
  auto weight = [&](std::uint32_t k) { return w.viscous_weight[k]; };
  // Work of the sub-step whose half-step velocities are vh (spec §3 energy bookkeeping):
  // force at level n+1 times the synchronised velocity, external force over the drift.
  auto account = [&](std::span<const Vec2> vh) {
    double diss = 0.0, hg = 0.0, ext = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      diss -= dot(body.f_av[i], body.v[i]);
      hg -= dot(body.f_hg[i], body.v[i]);
      ext += dot(w.fext[i], vh[i]);
    }
    body.dissipated += h * diss;
    body.hourglass_work += h * hg;
    body.external_work += h * ext;
  };
  // First half kick and drift of particle i from v and a into (vh, x).
  auto kick_drift = [&](std::size_t i, std::span<const Vec2> x, std::span<Vec2> vh_out,
                        std::span<Vec2> x_out) {
    if (body.clamped[i]) {
      vh_out[i] = Vec2{};
      x_out[i] = body.X[i];
      return;
    }
    vh_out[i] = body.v[i] + hh * body.a[i];
    x_out[i] = x[i] + h * vh_out[i];
  };

  const int threads = exec.threads_for(n, kSubstepParticlesPerThread);
  bool swapped = false;  // the current positions are in w.x_next
  exec.run_team(threads, [&](const Team& team) {
    std::span<Vec2> x = body.x, xn = w.x_next, vh = w.vhalf, vhn = w.vhalf_next;
    const auto [b, e] = team.share(n);
    for (std::size_t i = b; i < e; ++i) {
      for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) {
        w.kappa[k] = hourglass ? hourglass_pair_stiffness(body, topo, alpha, i, index[k], k) : 0.0;
        w.viscous_weight[k] = viscous ? viscous_pair_weight(body, topo, i, k) : 0.0;
      }
      w.fext[i] = body.f_fluid[i] + body.m[i] * g;
      body.a[i] = body.clamped[i] ? Vec2{} : (body.f_int[i] + w.fext[i]) / body.m[i];
      kick_drift(i, x, vh, x);
    }
    team.barrier();
    for (int step = 0; step < steps; ++step) {
      // Pass 1: deformation, the law's committing update, stress power, hourglass moment.
      for (std::size_t i = b; i < e; ++i) {
        Mat2 F, Fdot;
        gradients_of_motion(topo, x, vh, i, F, Fdot);
        const Mat2 F_old = body.F[i], P_old = body.P[i];
        body.F[i] = F;
        const Mat2 P = commit_stress_at(law, body.history, F_old, F, h, i);
        body.P[i] = P;
        // de/dt = P : Ḟ / ρ0 with P trapezoidal over the sub-step (spec §3).
        w.stress_power[i] = ddot(0.5 * (P_old + P), Fdot) / body.rho0[i];
        if (hourglass) w.G[i] = hourglass_moment(body, topo, x, i, kappa, w.keps);
      }
      if (team.leader() && step > 0) account(vhn);  // the previous sub-step's v½
      team.barrier();
      // Pass 2: forces, second half kick, internal energy; next kick and drift.
      const bool more = step + 1 < steps;
      for (std::size_t i = b; i < e; ++i) {
        const Vec2 fs = stress_force_on(body, topo, i);
        double heat = 0.0;
        const Vec2 fav = viscous ? viscous_force_on(body, topo, x, vh, i, weight, heat) : Vec2{};
        const Vec2 fhg = hourglass ? hourglass_force_on(topo, w.G, w.keps, i) : Vec2{};
        body.f_av[i] = fav;
        body.f_hg[i] = fhg;
        body.f_int[i] = fs + fav + fhg;
        body.a[i] = body.clamped[i] ? Vec2{} : (body.f_int[i] + w.fext[i]) / body.m[i];
        body.v[i] = body.clamped[i] ? Vec2{} : vh[i] + hh * body.a[i];
        body.e[i] += h * (w.stress_power[i] + heat / body.m[i]);
        if (more) kick_drift(i, x, vhn, xn);
      }
      team.barrier();
      if (more) {
        std::swap(x, xn);
        std::swap(vh, vhn);
        if (team.leader()) swapped = !swapped;
      }
    }
    if (team.leader() && steps > 0) account(vh);
  });
  if (swapped) std::swap(body.x, w.x_next);
  body.history.updates += static_cast<std::uint64_t>(steps);
}

}  // namespace

void run_elastic_substeps(SolidBody& body, int steps, double h, Vec2 g, const Executor& exec) {
  std::visit([&](const auto& law) { substeps_with(law, body, steps, h, g, exec); },
             body.material.law);
}

}  // namespace slamsph
