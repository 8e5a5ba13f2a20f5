// Verlet neighbour lists for everything the fluid touches (spec §1): fluid–fluid,
// fluid→solid and solid→fluid, built from cell-linked lists with a skin. They are
// rebuilt when any fluid or contact particle has moved more than half the skin since
// the last build, which keeps every pair inside the kernel support in the lists.
// On each rebuild the fluid particles are reordered into cell order for memory locality.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/cell_grid.h"
#include "core/parallel.h"
#include "coupling/contact_particles.h"
#include "fluid/fluid_particles.h"

namespace slamsph {

class InteractionLists {
 public:
  // support_ff: fluid kernel support; support_fc: contact kernel support; skin [m].
  InteractionLists(double support_ff, double support_fc, double skin)
      : support_ff_(support_ff), support_fc_(support_fc), skin_(skin) {}

  // Rebuilds if needed (or if `force`); returns true if it rebuilt. May permute `f`.
  // fluid_d2: max |x_i - fluid_reference()[i]|² over the fluid as a sweep that moved the
  // particles already found it (the drift, app/fsi_stepper.cpp; a maximum is exact in any
  // order), or negative to have it computed here; only used while the sizes agree.
  bool update(FluidParticles& f, const ContactParticles& c, const Executor& exec,
              bool force = false, double fluid_d2 = -1.0);

  // False if the next update() rebuilds because of the fluid (a fluid particle has moved
  // half the skin, or the fluid changed size): update() may still rebuild for the contact
  // particles. While true, ff() holds for the fluid's current positions whatever the
  // contact does, up to such a rebuild (app/fsi_stepper.h: the water's pair pass beside
  // the bodies' sub-steps).
  // fluid_d2 as for update().
  bool fluid_within_skin(const FluidParticles& f, const Executor& exec,
                         double fluid_d2 = -1.0) const;

  const BandedPairs& ff() const { return ff_; }  // fluid–fluid, each pair once
  const NeighbourList& fc() const { return fc_; }
  const NeighbourList& cf() const { return cf_; }
  // For entry m of cf (contact s, fluid i): the entry of fc (fluid i, contact s) holding the
  // same pair, so the reaction can reuse the pair force computed for the fluid
  // (coupling/contact_rates.h ContactPairForces).
  const std::vector<std::uint32_t>& cf_in_fc() const { return cf_in_fc_; }
  long rebuilds() const { return rebuilds_; }
  // Fluid grid of the last build; a query radius up to cell_size() - skin is safe, since
  // no particle has moved more than skin/2 since.
  const CellGrid& fluid_grid() const { return fluid_grid_; }

  // Positions at the last build (checkpoints): rebuilding from them reproduces the lists
  // of the last build exactly (same grids, same pair order), without reordering the fluid,
  // which was already put in cell order by that build.
  const std::vector<Vec2>& fluid_reference() const { return fluid_ref_; }
  const std::vector<Vec2>& contact_reference() const { return contact_ref_; }
  void restore(std::vector<Vec2> fluid_ref, std::vector<Vec2> contact_ref, long rebuilds,
               const Executor& exec);

 private:
  double cell_size() const;
  // max |x_i - x_i at the last build|^2 over the fluid (sizes equal): `known` if not
  // negative, else computed.
  double fluid_displacement2(const FluidParticles& f, const Executor& exec, double known) const;
  // Grids and lists from fluid positions xf (already in cell order) and contact xc; with
  // fluid_grid_ready the fluid grid already bins xf.
  void build(const std::vector<Vec2>& xf, const std::vector<Vec2>& xc, const Executor& exec,
             bool fluid_grid_ready);

  double support_ff_, support_fc_, skin_;
  CellGrid fluid_grid_, contact_grid_;
  BandedPairs ff_;
  NeighbourList fc_, cf_;
  std::vector<std::uint32_t> cf_in_fc_;
  std::vector<Vec2> fluid_ref_, contact_ref_;  // positions at the last build
  bool contact_grid_built_ = false;            // contact_grid_ bins contact_ref_
  std::vector<std::byte> reorder_scratch_;     // the fluid reorder's copies (FluidParticles)
  long rebuilds_ = 0;
};

}  // namespace slamsph
