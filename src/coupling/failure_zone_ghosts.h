// Ghost layers around a failure, planned in the current configuration (docs/model.md §4
// "Ghosts around a failure"; spec §5: water meets the faces a crack exposes).
//
// The reference plan (coupling/ghost_layers.h) counts, once, the body layers behind each
// surface particle along its reference normal and fills the rest of the water kernel's
// support with ghosts. Near failed particles the surface is no longer the reference one:
// their normals are the current colour gradient (coupling/surface_normals.h), and a crack
// face of a skin has its normal along the skin, where the skin itself fills the support.
// Keeping the reference ghosts there would put them inside the intact skin beside the crack
// (an over-filled support at the crack mouth that pushes water out at p > 0 and pulls it in
// at p < 0). So every intact particle of the failure zone gets a fixed number of ghost
// *slots* instead of its reference ghosts, enough for a particle with nothing behind it,
// ceil(K / m) with K = ceil(support / d) and m the ghost cell depth in layers (as in the
// reference plan). At each gather the layers behind the particle are counted along its
// current normal among the body's current positions (a particle within 0.75 d of
// x − k d n, k = 1, 2, ...) and the slots fill the missing depths exactly as the reference
// plan would; the slots not needed get zero volume (they exert nothing: every contact term
// carries V_s) and sit where they would be with nothing behind, so they move smoothly.
//
// The number of slots depends only on the zone, i.e. on the (sticky, checkpointed) failed
// flags and the reference positions, so a resumed run re-plans the same layout; the depths
// and weights are recomputed from the state at every gather. Failed particles get no slots
// and keep no reference ghosts: they are debris, compression only (solid/materials), not a
// wall (ContactParticles::debris).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/cell_grid.h"
#include "core/vec.h"

namespace slamsph {

struct SolidBody;

// 1 for the particles whose reference position lies within two kernel supports of a failed
// particle's (the failed and switched particles and the neighbours they had); empty if no
// particle of the body has failed or its law cannot fail.
std::vector<std::uint8_t> failure_zone(const SolidBody& body);

// For every particle with zone[i], not failed and with a non-zero normals[i]: the body layers
// behind it along normals[i] in the current configuration (body.x, binned in `grid` with cells
// of at least 0.75 of the coarsest spacing; coupling/ghost_layers.h layers_behind), at most the
// K of `support`; 0 elsewhere.
std::vector<int> layers_behind_now(const SolidBody& body, const CellGrid& grid,
                                   std::span<const Vec2> normals,
                                   std::span<const std::uint8_t> zone, double support);

}  // namespace slamsph
