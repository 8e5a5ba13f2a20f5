// Stability of the solid sub-step on a dry elastic skin or strip (docs/model.md §3 "Solid
// stable step"). Not a test: it prints, for one smoothing length and artificial viscosity,
//  - 2/ω_max, ω_max² the largest eigenvalue of M⁻¹K for the stress + hourglass force
//    linearised about the reference state (power iteration on finite differences);
//  - Δt γ_max/2, γ_max the largest rate of the viscous operator with every pair taken as
//    approaching (a bound: Π acts on approaching pairs only);
//  - the body's stable step Δt_s, and the growth of the fastest speed over 10 steps of 30 µs
//    from random particle speeds of 1 mm/s (every mode excited).
// Run: build/bench/solid_step_limit skin|strip LAYERS H_OVER_DX [AV_ALPHA [HOURGLASS
// [tl_sfpm|tlsph]]]
//   skin: the aluminium skin of cases/fuselage/skin_cylinder.toml (D 0.6 m, 3 mm); strip: a
//   200 × LAYERS lattice at 1 mm. One thread.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "geometry/fuselage_section.h"
#include "solid/artificial_viscosity.h"
#include "solid/body_dynamics.h"
#include "solid/deformation_gradient.h"
#include "solid/hourglass_control.h"
#include "solid/stress_update.h"
#include "solid/tl_pair_force.h"

using namespace slamsph;

namespace {

// Largest eigenvalue of a symmetric positive operator (mass-weighted) by power iteration.
template <class Op>
double largest_rate(std::size_t n, Op&& apply) {
  std::vector<Vec2> u(n), f(n);
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  for (Vec2& p : u) p = {r(gen), r(gen)};
  double lam = 0.0;
  for (int it = 0; it < 3000; ++it) {
    double nn = 0.0;
    for (const Vec2& p : u) nn += norm2(p);
    nn = std::sqrt(nn);
    for (Vec2& p : u) p = (1.0 / nn) * p;
    apply(u, f);  // f = −(M⁻¹ A) u
    lam = 0.0;
    for (std::size_t i = 0; i < n; ++i) lam -= dot(f[i], u[i]);
    for (std::size_t i = 0; i < n; ++i) u[i] = -1.0 * f[i];
  }
  return lam;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s skin|strip LAYERS H_OVER_DX [AV_ALPHA [HOURGLASS [SCHEME]]]\n",
                 argv[0]);
    return 2;
  }
  const std::string shape = argv[1];
  const int layers = std::atoi(argv[2]);
  const double hdx = std::atof(argv[3]);
  ElasticMaterialInput mat;
  mat.name = "aluminium";
  mat.density = 2700.0;
  mat.youngs_modulus = 67.5e9;
  mat.poisson_ratio = 0.34;
  mat.av_alpha = argc > 4 ? std::atof(argv[4]) : 1.0;
  mat.hourglass = argc > 5 ? std::atof(argv[5]) : 0.1;
  const std::string scheme = argc > 6 ? argv[6] : "tl_sfpm";

  SolidBody b;
  double dx = 0.001;
  if (shape == "skin") {
    FuselageShape f;
    f.diameter = 0.6;
    f.skin_thickness = 0.003;
    f.skin_layers = layers;
    const ParticleLattice lat = fuselage_section({0, 0}, f);
    b.X = lat.x;
    b.V0 = lat.volume;
    b.layer = lat.layer;
    b.part = lat.part;
    b.spacing = lat.spacing;
    b.part_names = fuselage_part_names();
    dx = *std::min_element(lat.spacing.begin(), lat.spacing.end());
  } else {
    for (int j = 0; j < layers; ++j)
      for (int i = 0; i < 200; ++i) {
        b.X.push_back({(i + 0.5) * dx, (j + 0.5) * dx});
        b.V0.push_back(dx * dx);
      }
  }
  b.x = b.X;
  for (double v : b.V0) {
    b.rho0.push_back(mat.density);
    b.m.push_back(mat.density * v);
  }
  BodySetup cfg;
  cfg.name = shape;
  cfg.kind = BodyKind::Elastic;
  cfg.scheme = solid_scheme_from_name(scheme).value();
  cfg.dx = dx;
  cfg.h_over_dx = hdx;
  cfg.material = mat;
  setup_body(b, cfg);
  const Executor ex(1);
  const std::size_t n = b.size();
  const SolidTopology& t = b.topology;

  // Stress + hourglass acceleration at displacement u (small: linear).
  const double eps = 1e-9;
  auto stiffness = [&](const std::vector<Vec2>& u, std::vector<Vec2>& a) {
    for (std::size_t i = 0; i < n; ++i) b.x[i] = b.X[i] + eps * u[i];
    const std::vector<Mat2> F_old = b.F;
    compute_deformation_gradients(b, t, ex);
    update_stress(b, F_old, 0.0, ex);
    std::vector<Vec2> fs(n), fh(n);
    compute_stress_forces(b, t, ex, fs);
    compute_hourglass_forces(b, t, b.material.hourglass, ex, fh);
    for (std::size_t i = 0; i < n; ++i) a[i] = (fs[i] + fh[i]) / (eps * b.m[i]);
  };
  const double omega = std::sqrt(std::abs(largest_rate(n, stiffness)));
  // Viscous acceleration, every pair approaching (artificial_viscosity.h, β = 0).
  auto viscous = [&](const std::vector<Vec2>& v, std::vector<Vec2>& a) {
    for (std::size_t i = 0; i < n; ++i) {
      Vec2 s;
      for (std::uint32_t k = t.pairs.start[i]; k < t.pairs.start[i + 1]; ++k) {
        const std::uint32_t j = t.pairs.index[k];
        const Vec2 xij = b.X[i] - b.X[j], vij = v[i] - v[j];
        const double h = 0.5 * (t.h[i] + t.h[j]), r = norm(xij);
        const double pi = 0.5 * (b.rho0[i] + b.rho0[j]) * b.material.av_alpha *
                          b.material.sound_speed * h * dot(vij, xij) / (r * r + 0.01 * h * h);
        s += (-pi * viscous_pair_weight(b, t, i, k) / r) * xij;
      }
      a[i] = s / b.m[i];
    }
  };
  const double gamma = b.material.av_alpha > 0.0 ? largest_rate(n, viscous) : 0.0;

  // Back to the reference state, random speeds, 10 fluid steps of 30 µs.
  b.x = b.X;
  const std::vector<Mat2> F_old = b.F;
  compute_deformation_gradients(b, t, ex);
  update_stress(b, F_old, 0.0, ex);
  std::mt19937 gen(2);
  std::uniform_real_distribution<double> uv(-1e-3, 1e-3);
  for (Vec2& v : b.v) v = {uv(gen), uv(gen)};
  refresh_internal_forces(b, ex);
  const double dts = stable_time_step(b);
  auto vmax = [&] {
    double m = 0.0;
    for (const Vec2& v : b.v) m = std::max(m, std::isfinite(norm(v)) ? norm(v) : 1e300);
    return m;
  };
  const double v0 = vmax();
  double growth = 0.0;
  try {
    for (int s = 0; s < 10; ++s) advance_body(b, s * 3e-5, 3e-5, {}, ex);
    growth = vmax() / v0;
  } catch (const std::exception&) {
    growth = 1e300;
  }
  const double a = 0.5 * dts * omega, bv = 0.5 * dts * gamma;
  std::printf(
      "%s layers %d (%zu particles) %s h = %.2f dx alpha %.2f alpha_hg %.2f: 2/omega_max %.4e s, "
      "step %.4e s, dt omega/2 %.3f, dt gamma_max/2 %.3f (all pairs approaching), max speed "
      "after 10 x 30 us %.3g of the start: %s\n",
      shape.c_str(), layers, n, scheme.c_str(), hdx, mat.av_alpha, mat.hourglass, 2.0 / omega, dts,
      a, bv, growth, growth > 10.0 ? "DIVERGED" : "bounded");
  return 0;
}
