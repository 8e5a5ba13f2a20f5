// Tension bar (spec §3 tensile instability): a free rubber bar (0.2 × 0.02 m, ρ 1000,
// E 2 MPa, ν 0.3975) is given the linear velocity field v_x = v0 (X − X_c)/(L/2), so it is
// pulled to a few per cent mean strain, released by its own elasticity, and rings
// (tension–compression) for three longitudinal periods 2L/c. A total-Lagrangian scheme
// must show no particle clustering or numerical fracture: the minimum distance between
// any two particles stays above 0.8 dx (a compressive strain of ε changes it by ~ε dx),
// and the bar stays in one piece (largest gap between neighbours bounded).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "../unit/test_solid_lattices.h"
#include "core/cell_grid.h"
#include "core/parallel.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

struct BarResult {
  double max_strain = 0.0;    // largest mean strain (length change / L)
  double min_distance = 1e9;  // smallest particle distance over the run [dx]
  double max_pair_gap = 0.0;  // largest distance between reference neighbours [dx]
  double seconds = 0.0;
};

BarResult run_bar(const char* scheme, int layers, double v0) {
  const double L = 0.2, H = 0.02, dx = H / layers;
  const int nx = static_cast<int>(std::lround(L / dx));
  BodySetup cfg;
  cfg.gravity = false;
  SolidBody b = make_body(box_lattice(nx, layers, dx), dx, scheme, plate_material(0.1), cfg);
  for (std::size_t i = 0; i < b.size(); ++i) b.v[i] = {v0 * (b.X[i].x - L / 2) / (L / 2), 0.0};
  const Executor exec(1);
  const double c_bar = std::sqrt(2e6 / (1000.0 * (1 - 0.3975 * 0.3975)));
  const double t_end = 3.0 * 2.0 * L / c_bar;
  const double dt = stable_time_step(b) * 4;
  BarResult r;
  const auto t0 = std::chrono::steady_clock::now();
  CellGrid grid;
  for (double t = 0.0; t < t_end; t += dt) {
    advance_body(b, t, dt, {}, exec);
    double xmin = 1e9, xmax = -1e9;
    for (const Vec2& p : b.x) {
      xmin = std::min(xmin, p.x);
      xmax = std::max(xmax, p.x);
    }
    r.max_strain = std::max(r.max_strain, (xmax - xmin) / ((nx - 1) * dx) - 1.0);
    grid.build(b.x, dx);
    for (std::size_t i = 0; i < b.size(); ++i)
      grid.for_each_candidate(b.x[i], [&](std::uint32_t j) {
        if (j != i) r.min_distance = std::min(r.min_distance, norm(b.x[j] - b.x[i]) / dx);
      });
    for (std::size_t i = 0; i < b.size(); ++i)
      for (std::uint32_t k = b.topology.pairs.start[i]; k < b.topology.pairs.start[i + 1]; ++k) {
        const std::uint32_t j = b.topology.pairs.index[k];
        if (norm(b.X[j] - b.X[i]) < 1.01 * dx)
          r.max_pair_gap = std::max(r.max_pair_gap, norm(b.x[j] - b.x[i]) / dx);
      }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "[bar] %-7s layers %d v0 %.2f: max mean strain %.2f %%, min distance %.3f dx, "
      "max neighbour gap %.3f dx, %.1f s\n",
      scheme, layers, v0, 100 * r.max_strain, r.min_distance, r.max_pair_gap, r.seconds);
  return r;
}

}  // namespace

TEST(SolidTensionBar, TlSfpmNoClustering) {
  const BarResult r = run_bar("tl_sfpm", 8, 5.0);
  EXPECT_GT(r.max_strain, 0.04);  // it was really pulled a few per cent
  EXPECT_GT(r.min_distance, 0.8);
  EXPECT_LT(r.max_pair_gap, 1.2);
}

TEST(SolidTensionBar, TlSphNoClustering) {
  const BarResult r = run_bar("tlsph", 8, 5.0);
  EXPECT_GT(r.max_strain, 0.04);
  EXPECT_GT(r.min_distance, 0.8);
  EXPECT_LT(r.max_pair_gap, 1.2);
}
