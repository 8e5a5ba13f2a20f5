// Virtual pressure, density and no-slip velocity of solid particles from their fluid
// neighbours, spec §4 (Adami, Hu & Adams 2012; paper Eqs. 12 and 14):
//   p'_s = [sum_f p_f W_sf + (g - a_s) . sum_f rho_f r_sf W_sf] / sum_f W_sf,  r_sf = r_s - r_f
//   rho'_s = EOS^-1(p'_s),   v~_s = 2 v_s - sum_f v_f W_sf / sum_f W_sf
// A solid particle without fluid neighbours is marked dry and takes no part.
#pragma once
#include <cstdint>
#include <vector>

#include "core/cell_grid.h"
#include "core/kernel.h"
#include "core/parallel.h"
#include "coupling/contact_particles.h"
#include "fluid/fluid_particles.h"
#include "fluid/tait_eos.h"

namespace slamsph {

// Which contact particles a call fills: all of them, or only those with fixed[s] != 0 (the
// entries of bodies that never move), or only the others. Each particle's state depends on
// nothing but its own entries and its fluid neighbours, so a split call gives the same bits.
enum class VirtualSubset { All, Fixed, Moving };

void compute_virtual_state(ContactParticles& c, const FluidParticles& f, const NeighbourList& cf,
                           const Kernel& kernel, const TaitEos& eos, Vec2 gravity,
                           const Executor& exec, VirtualSubset subset = VirtualSubset::All,
                           const std::vector<std::uint8_t>* fixed = nullptr);

}  // namespace slamsph
