// The notched plane-strain Al 2024-T3 specimen (cases/johnson_cook_notched.toml; issue 11
// "Failure"; docs/validation.md "Johnson–Cook notched specimen"), coarsened to dx = 0.5 mm
// and pulled at ±2 m/s so that it breaks within seconds. Checked after every solid step,
// from the stress and not from the law's own bookkeeping:
// (a) the first particle fails where the Johnson–Cook damage integral of its own history,
//     D = Σ Δε̄p / ε_f(σ*, ε̇*), evaluated here with the constants of the validation
//     README §8 (D1..D4 = 0.13, 0.13, −1.5, 0.011) and with σ* = σ_m/σ_vM computed from its
//     Cauchy stress (P Fᵀ/J, plane-strain σ_zz from the law), reaches 1 (within 10 %);
// (b) it fails at a notch root, in the region where the triaxiality of the plastically
//     strained material just before the first failure is highest (within 1.5 mm);
// (c) kinetic + stored elastic + hourglass + viscous + plastic work (whose 0.9 is heat) equals
//     the work of the moving grips (SolidBody::clamp_work) to 1 % up to the first failure.
// SLAMSPH_NOTCHED_DX, SLAMSPH_NOTCHED_V (grip speed, m/s) and SLAMSPH_NOTCHED_AFTER (time run
// after the first failure, s) override the resolution, the speed and the time after failure;
// scripts/validate_notched.sh runs the case's own dx 0.25 mm and ±1 m/s this way.
// Broken on purpose (docs/validation.md): D3's sign flipped fails it (no failure within
// end_time). Not yet tried: σ* from the trial stress, σ_zz left out of σ*.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "app/simulation.h"
#include "io/case_file.h"
#include "io/case_resolution.h"
#include "solid/body_energy.h"
#include "solid/materials/johnson_cook.h"

using namespace slamsph;

namespace {

double env_or(const char* name, double def) {
  const char* s = std::getenv(name);
  return s ? std::atof(s) : def;
}

// Johnson & Cook (1985) failure strain of Al 2024-T3 (validation README §8), written here
// independently of solid/materials/johnson_cook_failure.cpp. The rate ratio is clipped at 1
// as in the flow stress (docs/model.md §3).
double failure_strain(double triax, double rate) {
  return (0.13 + 0.13 * std::exp(-1.5 * triax)) * (1.0 + 0.011 * std::log(std::max(rate, 1.0)));
}

// σ* = σ_m / σ_vM of particle i from its first Piola–Kirchhoff stress and the law's σ_zz.
double triaxiality_of(const SolidBody& b, const JohnsonCook& law, std::size_t i) {
  const Mat2& F = b.F[i];
  const double J = det(F);
  const Mat2 s = (1.0 / J) * (b.P[i] * transpose(F));
  std::array<double, JohnsonCook::kSlots> h{};
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = b.history.values[k][i];
  const double zz = law.cauchy_zz(F, h);
  const double sxy = 0.5 * (s.xy + s.yx);
  const double m = (s.xx + s.yy + zz) / 3.0;
  const double dx = s.xx - m, dy = s.yy - m, dz = zz - m;
  const double vm = std::sqrt(1.5 * (dx * dx + dy * dy + dz * dz + 2.0 * sxy * sxy));
  return vm > 0.0 ? m / vm : 0.0;
}

struct NotchedResult {
  bool failed = false;
  double t_fail = 0.0;
  std::size_t first = 0;
  Vec2 X_fail;              // reference position of the first failed particle [m]
  double ep_fail = 0.0;     // its ε̄p at failure
  double D_pred = 0.0;      // the damage integral of its history computed here
  double triax_mean = 0.0;  // its ε̄p-weighted mean triaxiality
  double rate_mean = 0.0;   // its mean plastic strain rate [1/s]
  Vec2 X_max_triax;         // where the plastic material's σ* peaks before the first failure
  double max_triax = 0.0;
  double triax_at_first = 0.0;  // σ* of the first failed particle just before failure
  Vec2 X_max_ep;                // where ε̄p peaks before the first failure
  double clamp_work = 0.0;      // grips' work up to the first failure [J/m]
  double residual = 0.0;        // largest |energy residual| up to the first failure [J/m]
  double residual_end = 0.0;    // energy residual at the end of the run [J/m]
  double clamp_work_end = 0.0;
  double plastic = 0.0;  // plastic work up to the first failure [J/m]
  int failed_count = 0;
  long steps = 0;
};

NotchedResult run_notched() {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/johnson_cook_notched.toml");
  rescale_resolution(cfg, env_or("SLAMSPH_NOTCHED_DX", 0.0005));
  const double v = env_or("SLAMSPH_NOTCHED_V", 2.0);
  cfg.bodies[0].clamp.velocities = {Vec2{-v, 0.0}, Vec2{v, 0.0}};
  cfg.output.vtk = false;
  cfg.output.plot.clear();
  const double after = env_or("SLAMSPH_NOTCHED_AFTER", 2e-6);
  Simulation sim(std::move(cfg), silent_options(1));
  SolidBody& b = sim.bodies()[0];
  const JohnsonCook& law = std::get<JohnsonCook>(b.material.law);
  const std::size_t n = b.size();
  const std::vector<double>& ep = b.history.values[JohnsonCook::kPlasticStrain];
  const std::vector<double>& failed = b.history.values[JohnsonCook::kFailed];
  std::vector<double> ep_old(n, 0.0), D(n, 0.0), triax_w(n, 0.0), triax(n, 0.0);
  const BodyEnergyTerms e0 = body_energy_terms(b, Vec2{});
  const double stored0 = e0.kinetic + e0.strain + e0.hourglass;
  NotchedResult r;
  double t_old = sim.time();
  while (sim.time() < sim.config().numerics.end_time) {
    sim.step();
    ++r.steps;
    const double dt = sim.time() - t_old;
    t_old = sim.time();
    const BodyEnergyTerms et = body_energy_terms(b, Vec2{});
    const double res = et.kinetic + et.strain + et.hourglass - stored0 + et.dissipated -
                       et.external_work - et.clamp_work;
    r.residual_end = res;
    r.clamp_work_end = et.clamp_work;
    bool now = false;
    for (std::size_t i = 0; i < n; ++i) {
      const double dep = ep[i] - ep_old[i];
      if (dep > 0.0) {
        const double tr = triaxiality_of(b, law, i);
        // A failed particle's stress is a pressure: its last step's σ* is the one of its
        // returned stress, which the law kept (ε̇p and σ* are frozen at failure).
        const double trs = failed[i] > 0.5 ? b.history.values[JohnsonCook::kTriaxiality][i] : tr;
        D[i] += dep / failure_strain(trs, dep / dt);
        triax_w[i] += trs * dep;
      }
      ep_old[i] = ep[i];
      if (!r.failed && !now && failed[i] > 0.5) {  // the symmetric notches fail together:
        now = true;                                // the first of them in particle order
        r.first = i;
      }
    }
    r.failed = r.failed || now;
    if (now) {
      const std::size_t i = r.first;
      r.t_fail = sim.time();
      r.X_fail = b.X[i];
      r.ep_fail = ep[i];
      r.D_pred = D[i];
      r.triax_mean = triax_w[i] / ep[i];
      r.rate_mean = ep[i] / sim.time();
      r.triax_at_first = triax[i];
      r.plastic = et.plastic;
      r.clamp_work = et.clamp_work;
      // the field of the step before the failure (triax[] below is not yet overwritten)
      double best = -1e9, best_ep = -1.0;
      for (std::size_t j = 0; j < n; ++j) {
        if (b.clamped[j]) continue;
        if (ep[j] > 0.02 && triax[j] > best) best = triax[j], r.X_max_triax = b.X[j];
        if (ep[j] > best_ep) best_ep = ep[j], r.X_max_ep = b.X[j];
      }
      r.max_triax = best;
    }
    if (!r.failed) {
      r.residual = std::max(r.residual, std::abs(res));
      for (std::size_t i = 0; i < n; ++i) triax[i] = triaxiality_of(b, law, i);
    }
    if (r.failed && sim.time() > r.t_fail + after) break;
  }
  for (std::size_t i = 0; i < n; ++i) r.failed_count += failed[i] > 0.5;
  return r;
}

}  // namespace

TEST(JohnsonCookNotched, FailsAtTheJohnsonCookStrainAtTheNotchRootWithEnergyAccounted) {
  const NotchedResult r = run_notched();
  ASSERT_TRUE(r.failed) << "the specimen did not fail within end_time";
  const double ef_mean = failure_strain(r.triax_mean, r.rate_mean);
  std::printf(
      "[notched] %ld steps; first failure t = %.2f us at X = (%.3f, %.3f) mm: eps_p %.4f, "
      "damage integral of its history %.4f, effective eps_f = eps_p/D %.4f; mean triaxiality "
      "%.3f, mean rate %.0f /s -> eps_f(mean) %.4f (%+.1f %%)\n",
      r.steps, 1e6 * r.t_fail, 1e3 * r.X_fail.x, 1e3 * r.X_fail.y, r.ep_fail, r.D_pred,
      r.ep_fail / r.D_pred, r.triax_mean, r.rate_mean, ef_mean,
      100.0 * (r.ep_fail / ef_mean - 1.0));
  std::printf(
      "[notched] before failure: max triaxiality (eps_p > 0.02) %.3f at (%.3f, %.3f) mm, the "
      "first failed particle's %.3f; max eps_p at (%.3f, %.3f) mm; %d failed at the end\n",
      r.max_triax, 1e3 * r.X_max_triax.x, 1e3 * r.X_max_triax.y, r.triax_at_first,
      1e3 * r.X_max_ep.x, 1e3 * r.X_max_ep.y, r.failed_count);
  std::printf(
      "[notched] energy: grips' work %.4g J/m up to the first failure (plastic work %.4g), max "
      "|residual| %.3g J/m (%.2g of it); at the end %.4g J/m, residual %.3g J/m (%.2g)\n",
      r.clamp_work, r.plastic, r.residual, r.residual / r.clamp_work, r.clamp_work_end,
      r.residual_end, r.residual_end / r.clamp_work_end);
  // (a) the failure strain of the particle's own history (10 %).
  EXPECT_NEAR(r.D_pred, 1.0, 0.1);
  // (b) at a notch root (|x| within the 1 mm half-opening, |y| at the 3 mm root line), and
  // where the plastic material's triaxiality peaks (1.5 mm).
  EXPECT_LT(std::abs(r.X_fail.x), 0.0015);
  EXPECT_GT(std::abs(r.X_fail.y), 0.0015);
  EXPECT_LT(norm(r.X_fail - r.X_max_triax), 0.0015);
  // (c) the grips did the work, and it is accounted for.
  EXPECT_GT(r.plastic, 0.3 * r.clamp_work);
  EXPECT_LT(r.residual, 0.01 * r.clamp_work);
}
