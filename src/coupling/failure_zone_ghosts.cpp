#include "coupling/failure_zone_ghosts.h"

#include <algorithm>
#include <cmath>

#include "core/cell_grid.h"
#include "solid/eulerian_failed_interaction.h"
#include "solid/solid_body.h"

namespace slamsph {

std::vector<std::uint8_t> failure_zone(const SolidBody& body) {
  const std::vector<double>* failed = failed_flags(body);
  if (failed == nullptr || failed->size() != body.size()) return {};
  // By reference position: the zone is a function of the failed flags alone, also after the
  // crack has opened.
  std::vector<Vec2> Xf;
  for (std::size_t i = 0; i < body.size(); ++i)
    if ((*failed)[i] > 0.5) Xf.push_back(body.X[i]);
  if (Xf.empty()) return {};
  const double zone = 2.0 * body.kernel.support();
  CellGrid near_failed;
  near_failed.build(Xf, zone);
  std::vector<std::uint8_t> in(body.size(), 0);
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vec2 Xi = body.X[i];
    bool near = false;
    near_failed.for_each_candidate(
        Xi, [&](std::uint32_t k) { near = near || norm2(Xf[k] - Xi) < zone * zone; });
    in[i] = near ? 1 : 0;
  }
  return in;
}

GhostDepths ghost_depths(double d, double support, double ghost_spacing) {
  GhostDepths g;
  g.layers = static_cast<int>(std::ceil(support / d - 1e-9));
  g.cell = std::max(1, static_cast<int>(std::floor(ghost_spacing / d + 1e-9)));
  return g;
}

// The reference plan's cells (coupling/ghost_layers.cpp): from the back face (present + 1/2)
// d in cells of m layers until K d is covered.
double GhostDepths::depth(int present, int j) const {
  const int needed = (layers - present + cell - 1) / cell;
  return (j < needed ? present : 0) + 0.5 + (j + 0.5) * cell;
}

double GhostDepths::weight(int present, int j) const {
  const int needed = (layers - present + cell - 1) / cell;
  return j < needed ? static_cast<double>(cell) : 0.0;
}

std::vector<int> layers_behind_now(const SolidBody& body, std::span<const Vec2> normals,
                                   std::span<const std::uint8_t> zone, double support) {
  std::vector<int> present(body.size(), 0);
  if (zone.empty()) return present;
  double dmax = body.dx;
  for (double d : body.spacing) dmax = std::max(dmax, d);
  CellGrid grid;
  grid.build(body.x, dmax);
  const std::vector<double>* failed = failed_flags(body);
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vec2 n = normals[i];
    if (!zone[i] || norm2(n) == 0.0 || (failed != nullptr && (*failed)[i] > 0.5)) continue;
    const double d = body.spacing.size() == body.size() ? body.spacing[i] : body.dx;
    const int K = ghost_depths(d, support, 0.0).layers;
    auto occupied = [&](Vec2 p) {
      bool found = false;
      grid.for_each_candidate(p, [&](std::uint32_t j) {
        if (j != i && norm2(body.x[j] - p) < 0.5625 * d * d) found = true;  // within 0.75 d
      });
      return found;
    };
    int k = 0;
    while (k < K && occupied(body.x[i] - (k + 1) * d * n)) ++k;
    present[i] = k;
  }
  return present;
}

}  // namespace slamsph
