#include "coupling/interaction_lists.h"

#include <algorithm>

namespace slamsph {

bool InteractionLists::update(FluidParticles& f, const ContactParticles& c, const Executor& exec,
                              bool force) {
  if (!force && fluid_ref_.size() == f.size() && contact_ref_.size() == c.size()) {
    const double lim2 = 0.25 * skin_ * skin_;
    const double df = exec.max_of(
        f.size(), [&](std::size_t i) { return norm2(f.x[i] - fluid_ref_[i]); }, 0.0);
    const double dc = exec.max_of(
        c.size(), [&](std::size_t i) { return norm2(c.x[i] - contact_ref_[i]); }, 0.0);
    if (df < lim2 && dc < lim2) return false;
  }
  const double r_ff = support_ff_ + skin_;
  const double r_fc = support_fc_ + skin_;
  const double cell = std::max(r_ff, r_fc);
  // Reorder the fluid into cell order so neighbours are close in memory.
  fluid_grid_.build(f.x, cell);
  f.permute(fluid_grid_.cell_order());
  fluid_grid_.build(f.x, cell);
  build_banded_pairs(f.x, fluid_grid_, r_ff, exec, ff_);
  contact_grid_.build(c.x, cell);
  build_neighbour_list(f.x, c.x, contact_grid_, r_fc, false, exec, fc_);
  build_neighbour_list(c.x, f.x, fluid_grid_, r_fc, false, exec, cf_);
  fluid_ref_ = f.x;
  contact_ref_ = c.x;
  ++rebuilds_;
  return true;
}

}  // namespace slamsph
