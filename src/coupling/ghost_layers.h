// Ghost layers behind thin bodies (spec §4, "thin structures").
//
// The GSPH pair force of a fluid particle against a boundary only balances a uniform
// pressure when the boundary fills the particle's kernel support: with a skin thinner
// than the support, sum_j V_j grad W_ij over fluid and skin no longer vanishes and the
// pressure pushes the fluid *into* the skin, which then leaks. Thick bodies (the tank's
// 4 wall layers, a disc) fill the support; for every surface particle of a body that does
// not, we add ghost contact particles at x_s - k d n_s (k = k_present+1 .. K, d the body
// spacing, n_s the current outward normal, K = ceil(support/d)), carrying the parent's
// velocity, acceleration and volume. A ghost acts only on fluid on its parent's side
// (ContactParticles::faces), so a skin wetted on both sides gets a full support from
// each side, and its forces are returned to the parent (momentum stays exact).
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/cell_grid.h"
#include "core/vec.h"

namespace slamsph {

// How the missing depths behind a particle of spacing d are filled, for a kernel support
// `support` and ghost cells `ghost_spacing` deep (0: one layer per cell): K = ceil(support /
// d) layers, cells of m = max(1, floor(ghost_spacing / d)) layers from the back face. The
// rule of plan_ghost_layers, shared with the re-plan around failures
// (coupling/failure_zone_ghosts.h).
struct GhostDepths {
  int layers = 0;  // K
  int cell = 1;    // m
  // Cells needed with `present` body layers behind the particle; enough for none: slots().
  int cells(int present) const { return (layers - present + cell - 1) / cell; }
  int slots() const { return cells(0); }
  // Cell j: depth in d and volume weight. A cell not needed (j >= cells(present)) has weight
  // 0 and the depth it would have with nothing behind.
  double depth(int present, int j) const {
    return (j < cells(present) ? present : 0) + 0.5 + (j + 0.5) * cell;
  }
  double weight(int present, int j) const {
    return j < cells(present) ? static_cast<double>(cell) : 0.0;
  }
};
GhostDepths ghost_depths(double d, double support, double ghost_spacing);

// Body layers behind x along -n at spacing d: k = 1, 2, ... while a point of `pts` (binned in
// `grid`, cells >= 0.75 d) lies within 0.75 d of x - k d n (tolerant of offset ring layers);
// at most K.
int layers_behind(const CellGrid& grid, std::span<const Vec2> pts, Vec2 x, Vec2 n, double d, int K);

struct GhostSpec {
  std::uint32_t parent = 0;  // particle index in the body
  double depth = 0.0;        // in the parent's spacing d_i: the ghost sits at x - depth d_i n
  double weight = 1.0;       // ghost volume / parent volume (the body layers it stands for)
};

// From the reference configuration: for each particle i with a non-zero normal and its own
// spacing d_i, count the body layers present behind it (a body particle within 0.75 d_i of
// X - k d_i N for k = 1, 2, ...), and fill the missing depths from (present + 1/2) d_i to
// (K + 1/2) d_i, K = ceil(support / d_i), with ghost cells m layers deep, m = max(1,
// floor(ghost_spacing / d_i)): ghosts at depths present + 1/2 + (j + 1/2) m, weight m. With
// m = 1 this is one ghost per missing layer k = present+1 .. K. The contact layout asks for
// cells half a water spacing deep (docs/model.md §4, "Bodies finer than the water"): the
// ghosts only complete the water kernel's support, and at that depth they do it as well as
// one ghost per body layer (tests/unit/test_coupling_spacing_ratio.cpp: residual 0.015 vs
// 0.014 at r = 8) with 5 ghosts per surface particle instead of 20.
// Per-particle spacings (a body of parts, e.g. a fuselage's 1.5 mm skin and 5 mm floor):
// each part is probed and filled at its own layer spacing; probing a coarse part at the
// finest spacing would miss its own layers and put ghosts inside it.
std::vector<GhostSpec> plan_ghost_layers(const std::vector<Vec2>& X,
                                         const std::vector<Vec2>& normals,
                                         std::span<const double> spacing, double support,
                                         double ghost_spacing = 0.0);
// One spacing d for every particle.
std::vector<GhostSpec> plan_ghost_layers(const std::vector<Vec2>& X,
                                         const std::vector<Vec2>& normals, double d, double support,
                                         double ghost_spacing = 0.0);

}  // namespace slamsph
