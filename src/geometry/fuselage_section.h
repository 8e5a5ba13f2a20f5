// Particles of a stiffened fuselage cross-section (paper §4.2–4.4, spec §7) as one lattice
// whose particles carry a part id (FuselagePart) and their own spacing; the solid bonds the
// parts into one elastic body (solid/solid_topology.h).
//
// - Skin: the thin-ring polar grid of geometry/polar_lattice.h (`skin_layers` layers of
//   spacing d = thickness/layers, all layers radially aligned), with the common count n a
//   multiple of the stringer count so that every stringer sits on the grid the same way.
// - Stringers: further rows of the same polar grid inside the skin (same angular step, rows
//   of depth d at r_in − (q+½)d), so skin and stringer form one regular 4-neighbour grid
//   (a misaligned junction made session 3's face-laid lattice unstable). Widths are whole
//   numbers of arc steps measured on the inner skin face; "I": foot flange, web, inner
//   flange, all centred on the stringer angle; "L": web on a foot flange that extends to
//   one side — counter-clockwise on the right half (x ≥ centre), clockwise on the left, so
//   the section stays mirror-symmetric about the vertical centre line (offset_deg = 0).
//   Flanges and webs are slightly tapered (arc spacing ∝ r).
// - Floor: a Cartesian lattice of spacing d_f (floor.dx) symmetric about the centre line,
//   rows of cells [j d_f, (j+1) d_f]; the last cell of each row is stretched or shrunk to
//   end exactly on the inner skin face (length in [½, 3/2) d_f), so the floor spans skin
//   to skin and the volumes sum to the row lengths.
// - Columns: the floor's lattice continued downwards below the floor (edges on the floor's
//   cell boundaries), each particle column ending on the inner skin face like the floor rows.
// Volumes: skin and stringer particles are exact annulus sectors; floor and column cells
// are rectangles (the curved end slivers of the floor and column ends, below 1e-3 of their
// area at the shipped sizes, are not represented).
//
// Input errors throw FuselageShapeError naming the shape key (e.g. "stringers.height").
#pragma once
#include <stdexcept>
#include <string>

#include "core/vec.h"
#include "geometry/fuselage_shape.h"
#include "geometry/particle_lattice.h"

namespace slamsph {

struct FuselageShapeError : std::invalid_argument {
  FuselageShapeError(std::string k, const std::string& what)
      : std::invalid_argument(what), key(std::move(k)) {}
  std::string key;  // relative to the shape table, e.g. "floor.height"
};

// Number of particles per skin layer (a multiple of the stringer count).
long fuselage_skin_count(const FuselageShape& s);

ParticleLattice fuselage_section(Vec2 centre, const FuselageShape& s);

}  // namespace slamsph
