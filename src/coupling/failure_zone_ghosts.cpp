#include "coupling/failure_zone_ghosts.h"

#include <algorithm>
#include <cmath>

#include "coupling/ghost_layers.h"
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

std::vector<int> layers_behind_now(const SolidBody& body, const CellGrid& grid,
                                   std::span<const Vec2> normals,
                                   std::span<const std::uint8_t> zone, double support) {
  std::vector<int> present(body.size(), 0);
  if (zone.empty()) return present;
  const std::vector<double>* failed = failed_flags(body);
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Vec2 n = normals[i];
    if (!zone[i] || norm2(n) == 0.0 || (failed != nullptr && (*failed)[i] > 0.5)) continue;
    const double d = body.spacing.size() == body.size() ? body.spacing[i] : body.dx;
    present[i] = layers_behind(grid, body.x, body.x[i], n, d, ghost_depths(d, support, 0.0).layers);
  }
  return present;
}

}  // namespace slamsph
