#include "coupling/interaction_lists.h"

#include <algorithm>
#include <limits>

namespace slamsph {

double InteractionLists::fluid_displacement2(const FluidParticles& f, const Executor& exec,
                                             double known) const {
  if (known >= 0.0) return known;
  return exec.max_of(
      f.size(), [&](std::size_t i) { return norm2(f.x[i] - fluid_ref_[i]); }, 0.0,
      Executor::kMinParallelCheap);
}

bool InteractionLists::fluid_within_skin(const FluidParticles& f, const Executor& exec,
                                         double fluid_d2) const {
  return fluid_ref_.size() == f.size() &&
         fluid_displacement2(f, exec, fluid_d2) < 0.25 * skin_ * skin_;
}

bool InteractionLists::update(FluidParticles& f, const ContactParticles& c, const Executor& exec,
                              bool force, double fluid_d2) {
  if (!force && fluid_ref_.size() == f.size() && contact_ref_.size() == c.size()) {
    const double lim2 = 0.25 * skin_ * skin_;
    const double df = fluid_displacement2(f, exec, fluid_d2);
    const double dc = exec.max_of(
        c.size(), [&](std::size_t i) { return norm2(c.x[i] - contact_ref_[i]); }, 0.0,
        Executor::kMinParallelCheap);
    if (df < lim2 && dc < lim2) return false;
  }
  // Reorder the fluid into cell order so neighbours are close in memory. The grid then holds
  // the same cells with the points renumbered, which is what binning them again would give.
  fluid_grid_.build(f.x, cell_size());
  f.permute(fluid_grid_.cell_order(), reorder_scratch_, exec);
  fluid_grid_.renumber_in_cell_order();
  build(f.x, c.x, exec, true);
  ++rebuilds_;
  return true;
}

double InteractionLists::cell_size() const {
  return std::max(support_ff_ + skin_, support_fc_ + skin_);
}

void InteractionLists::build(const std::vector<Vec2>& xf, const std::vector<Vec2>& xc,
                             const Executor& exec, bool fluid_grid_ready) {
  const double r_ff = support_ff_ + skin_;
  const double r_fc = support_fc_ + skin_;
  const double cell = cell_size();
  if (!fluid_grid_ready) fluid_grid_.build(xf, cell);
  build_banded_pairs(xf, fluid_grid_, r_ff, exec, ff_);
  // Contact particles that have not moved since the last build (a tank's walls, a fixed
  // body: most of the contact set of a tank case) are binned as before: the same grid.
  const bool contact_moved =
      !contact_grid_built_ || xc.size() != contact_ref_.size() ||
      !std::equal(xc.begin(), xc.end(), contact_ref_.begin(),
                  [](const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; });
  if (contact_moved) contact_grid_.build(xc, cell);
  contact_grid_built_ = true;
  build_neighbour_list(xf, xc, contact_grid_, r_fc, false, exec, fc_);
  build_neighbour_list(xc, xf, fluid_grid_, r_fc, false, exec, cf_);
  // The two lists hold the same pairs (the same radius, the same squared distance; the 3x3
  // search of cells no smaller than the radius finds every one from either side).
  // Split by pairs: only the wetted contact particles have any (a tank's floor and the
  // gate's wetted face; in equal shares of the contact set one thread took 5x the other's
  // time on bench/elastic_gate_peer.toml); the split then follows the measured times.
  cf_in_fc_.resize(cf_.index.size());
  exec.for_each_weighted(cf_.size(), cf_.start.data(), [&](std::size_t s) {
    for (std::uint32_t m = cf_.start[s]; m < cf_.start[s + 1]; ++m) {
      const std::uint32_t i = cf_.index[m];
      std::uint32_t k = fc_.start[i];
      while (k < fc_.start[i + 1] && fc_.index[k] != s) ++k;
      // Not found (it cannot be, see above): the reaction evaluates that pair itself.
      cf_in_fc_[m] = k < fc_.start[i + 1] ? k : std::numeric_limits<std::uint32_t>::max();
    }
  });
  fluid_ref_ = xf;
  contact_ref_ = xc;
}

void InteractionLists::restore(std::vector<Vec2> fluid_ref, std::vector<Vec2> contact_ref,
                               long rebuilds, const Executor& exec) {
  build(fluid_ref, contact_ref, exec, false);
  rebuilds_ = rebuilds;
}

}  // namespace slamsph
