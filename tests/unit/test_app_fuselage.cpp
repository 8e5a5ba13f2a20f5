#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdlib>

#include "core/parallel.h"
#include "geometry/fuselage_section.h"
#include "geometry/polar_lattice.h"
#include "solid/body_dynamics.h"
#include "test_solid_lattices.h"

namespace slamsph {
namespace {

FuselageShape shipped_shape(int layers = 2) {
  FuselageShape f;
  f.diameter = 0.6;
  f.skin_thickness = 0.003;
  f.skin_layers = layers;
  f.stringers = {30, "I", 0.024, 0.003, 0.015, 0.003, 0.0};
  f.floor = {true, -0.09, 0.01, 0.0025};
  f.columns = {{-0.12, 0.12}, 0.01};
  return f;
}

ElasticMaterialInput aluminium() {
  ElasticMaterialInput m;
  m.name = "al";
  m.density = 2700.0;
  m.youngs_modulus = 67.5e9;
  m.poisson_ratio = 0.34;
  return m;
}

SolidBody body_of(const ParticleLattice& lat, const ElasticMaterialInput& mat) {
  SolidBody b;
  b.X = lat.x;
  b.x = lat.x;
  b.V0 = lat.volume;
  double finest = 1e9;
  for (double d : lat.spacing) finest = std::min(finest, d);
  if (finest == 0.0) finest = 0.005;
  for (double v : lat.volume) {
    b.rho0.push_back(mat.density);
    b.m.push_back(mat.density * v);
  }
  b.layer = lat.layer;
  b.part = lat.part;
  b.spacing = lat.spacing;
  for (double& d : b.spacing) if (d == 0.0) d = finest;
  b.part_names = fuselage_part_names();
  BodySetup cfg = testing::with_spacing({}, finest);
  cfg.kind = BodyKind::Elastic;
  cfg.material = mat;
  setup_body(b, cfg);
  return b;
}

TEST(FuselageDebug, Gmax) {
  for (int L : {2, 3, 6}) {
    FuselageShape f = shipped_shape(L);
    f.stringers.count = 0; f.columns.x.clear(); f.floor.present = false;
    SolidBody b = body_of(fuselage_section({0, 0}, f), aluminium());
    double g = 0; for (auto v : b.topology.grad0) g = std::max(g, norm(v));
    std::printf("skin %d layers: max|g|d = %g\n", L, g * b.dx);
    f = shipped_shape(L);
    b = body_of(fuselage_section({0, 0}, f), aluminium());
    g = 0; for (auto v : b.topology.grad0) g = std::max(g, norm(v));
    std::printf("full %d layers: max|g|d = %g\n", L, g * b.dx);
  }
  for (double R : {0.1}) {
    ParticleLattice lat = disc({0,0}, R, 0.005);
    SolidBody b = body_of(lat, aluminium());
    double g = 0; for (auto v : b.topology.grad0) g = std::max(g, norm(v));
    std::printf("disc: max|g|d = %g\n", g * 0.005);
  }
}

TEST(FuselageDebug, Setup) {
  FuselageShape f = shipped_shape(std::getenv("L") ? std::atoi(std::getenv("L")) : 2);
  if (std::getenv("NOSTR")) f.stringers.count = 0;
  const ParticleLattice lat = fuselage_section({0, 0}, f);
  SolidBody b = body_of(lat, aluminium());
  int bad = 0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Mat2& B = b.topology.B[i];
    const bool ok = std::isfinite(B.xx + B.xy + B.yx + B.yy) && std::isfinite(b.f_int[i].x + b.f_int[i].y);
    if (!ok && bad++ < 10) {
      std::printf("bad %zu part %u at (%g, %g) B %g %g %g %g f %g %g\n", i, b.part[i], b.X[i].x,
                  b.X[i].y, B.xx, B.xy, B.yx, B.yy, b.f_int[i].x, b.f_int[i].y);
    }
  }
  EXPECT_EQ(bad, 0);
  const double dts = stable_time_step(b);
  {
    // worst |g| d per particle
    const auto& t = b.topology;
    std::vector<std::pair<double, std::size_t>> worst;
    for (std::size_t i = 0; i < b.size(); ++i) {
      double g = 0;
      for (auto k = t.pairs.start[i]; k < t.pairs.start[i + 1]; ++k) {
        g = std::max(g, norm(t.grad0[k]) * b.spacing[i]);
        g = std::max(g, norm(t.grad0[t.pair_reverse[k]]) * b.spacing[i]);
      }
      worst.push_back({g, i});
    }
    std::sort(worst.rbegin(), worst.rend());
    for (int q = 0; q < 8; ++q) {
      auto i = worst[q].second;
      std::printf("worst |g|d %g at %zu part %u (%g %g) set:", worst[q].first, i, b.part[i], b.X[i].x, b.X[i].y);
      for (auto k = t.fpm_sets.start[i]; k < t.fpm_sets.start[i + 1]; ++k) { auto j = t.fpm_sets.index[k]; std::printf(" %u[p%u r=%.2f]", j, b.part[j], norm(b.X[j]-b.X[i])/b.spacing[i]); }
      std::printf("\n");
    }
    std::printf("i=3405: V0/df2 %g\n", b.V0[3405]/ (b.spacing[3405]*b.spacing[3405]));
  }
  std::printf("n %zu dts %g\n", b.size(), dts);
  for (auto& v : b.v) v = {0.0, std::getenv("V") ? -5.0 : 0.0};
  for (int s = 0; s < 200; ++s) {
    advance_body(b, 0, std::getenv("DT") ? std::atof(std::getenv("DT")) : 3e-5, {0, std::getenv("G") ? -9.81 : 0.0}, Executor(1));
    double vmax = 0; for (auto& v: b.v) v += Vec2{0.0, 5.0};
    std::size_t im = 0;
    for (std::size_t i = 0; i < b.size(); ++i)
      if (!(norm(b.v[i]) <= vmax)) { vmax = norm(b.v[i]); im = i; }
    if (s % 20 == 0 || !std::isfinite(vmax)) std::printf("step %d vmax %g at %zu part %u (%g %g)\n", s, vmax, im, b.part[im], b.X[im].x, b.X[im].y);
    for (auto& v: b.v) v -= Vec2{0.0, 5.0};
    if (!std::isfinite(vmax) || s > 100) break;
  }
}

}  // namespace
}  // namespace slamsph
