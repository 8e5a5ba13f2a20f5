#include "coupling/surface_normals.h"

#include <cmath>

#include "core/cell_grid.h"
#include "core/parallel.h"
#include "solid/solid_body.h"

namespace slamsph {

std::vector<Vec2> reference_surface_normals(const std::vector<Vec2>& X,
                                            const std::vector<double>& V0, const Kernel& kernel) {
  std::vector<Vec2> n(X.size());
  if (X.empty()) return n;
  CellGrid grid;
  grid.build(X, kernel.support());
  NeighbourList nl;
  Executor serial(1);
  build_neighbour_list(X, X, grid, kernel.support(), true, serial, nl);
  for (std::size_t i = 0; i < X.size(); ++i) {
    Vec2 g;
    for (std::uint32_t k = nl.start[i]; k < nl.start[i + 1]; ++k) {
      const std::uint32_t j = nl.index[k];
      const Vec2 d = X[i] - X[j];
      g += (V0[j] * kernel.dw_over_r(std::sqrt(norm2(d)))) * d;
    }
    // sum V_j grad W has magnitude ~1/(2h) at a flat surface and ~0 inside.
    const double mag = norm(g);
    n[i] = mag * kernel.h() > 0.15 ? (-1.0 / mag) * g : Vec2{};
  }
  return n;
}

void update_normals_near_failure(const SolidBody& body, const CellGrid& all,
                                 std::span<const std::uint8_t> zone, std::span<Vec2> normals) {
  if (zone.empty()) return;
  const Kernel& kernel = body.kernel;
  const double r = kernel.support();
  for (std::size_t i = 0; i < body.size(); ++i) {
    if (!zone[i]) continue;
    const Vec2 xi = body.x[i];
    Vec2 g;
    all.for_each_candidate(xi, [&](std::uint32_t j) {
      const Vec2 d = xi - body.x[j];
      const double d2 = norm2(d);
      if (j == i || !(d2 < r * r)) return;
      g += (body.volume(j) * kernel.dw_over_r(std::sqrt(d2))) * d;
    });
    const double mag = norm(g);
    normals[i] = mag * kernel.h() > 0.15 ? (-1.0 / mag) * g : Vec2{};
  }
}

}  // namespace slamsph
