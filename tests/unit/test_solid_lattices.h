// Small particle lattices and body setup for the solid tests (the geometry domain provides
// the real builders; the tests build their own so they link only slamsph_solid).
#pragma once
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/vec.h"
#include "solid/body_dynamics.h"
#include "solid/body_setup.h"
#include "solid/solid_body.h"

namespace slamsph::testing {

// nx × ny particles centred in dx cells starting at `origin`.
inline std::vector<Vec2> box_lattice(int nx, int ny, double dx, Vec2 origin = {}) {
  std::vector<Vec2> X;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) X.push_back(origin + Vec2{(i + 0.5) * dx, (j + 0.5) * dx});
  return X;
}

// Concentric layers of a ring (inner radius r_in, `layers` layers of thickness dx), each
// layer with round(2π r / dx) particles: near-uniform arc spacing, not aligned radially.
inline std::vector<Vec2> ring_lattice(double r_in, int layers, double dx,
                                      std::vector<double>* V0 = nullptr) {
  std::vector<Vec2> X;
  for (int l = 0; l < layers; ++l) {
    const double r = r_in + (l + 0.5) * dx;
    const int n = static_cast<int>(std::lround(2.0 * std::numbers::pi * r / dx));
    const double phase = 0.37 * l;
    for (int k = 0; k < n; ++k) {
      const double t = phase + 2.0 * std::numbers::pi * k / n;
      X.push_back({r * std::cos(t), r * std::sin(t)});
      if (V0) V0->push_back(2.0 * std::numbers::pi * r * dx / n);
    }
  }
  return X;
}

// Box lattice with every particle moved by up to ±amp·dx in each direction.
inline std::vector<Vec2> perturbed_lattice(int nx, int ny, double dx, double amp, unsigned seed) {
  std::vector<Vec2> X = box_lattice(nx, ny, dx);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-amp * dx, amp * dx);
  for (Vec2& p : X) p += Vec2{u(gen), u(gen)};
  return X;
}

inline ElasticMaterialInput plate_material(double hourglass = 0.0, double av_alpha = 1.0) {
  ElasticMaterialInput m;
  m.name = "rubber";
  m.density = 1000.0;
  m.youngs_modulus = 2.0e6;
  m.poisson_ratio = 0.3975;
  m.av_alpha = av_alpha;
  m.av_beta = 0.0;
  m.hourglass = hourglass;
  return m;
}

// Spacing dx, h = 1.3 dx, solid CFL 0.5.
inline BodySetup with_spacing(BodySetup cfg, double dx) {
  cfg.name = cfg.name.empty() ? "test" : cfg.name;
  cfg.dx = dx;
  cfg.h_over_dx = 1.3;
  cfg.solid_cfl = 0.5;
  return cfg;
}

// An elastic body on positions X (volumes V0 or dx² each) set up through setup_body.
inline SolidBody make_body(const std::vector<Vec2>& X, double dx, const std::string& scheme,
                           const ElasticMaterialInput& mat, BodySetup cfg = {},
                           const std::vector<double>& V0 = {}) {
  SolidBody b;
  b.X = X;
  b.x = X;
  for (std::size_t i = 0; i < X.size(); ++i) {
    const double v = V0.empty() ? dx * dx : V0[i];
    b.V0.push_back(v);
    b.rho0.push_back(mat.density);
    b.m.push_back(mat.density * v);
  }
  cfg = with_spacing(cfg, dx);
  cfg.kind = BodyKind::Elastic;
  cfg.scheme = solid_scheme_from_name(scheme).value();
  cfg.material = mat;
  setup_body(b, cfg);
  return b;
}

}  // namespace slamsph::testing
