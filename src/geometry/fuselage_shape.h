// Plain description of a stiffened fuselage cross-section (paper §4.2–4.4, spec §7): a skin
// ring with optional stringers, floor and columns. Filled by the case parser, turned into
// particles by geometry/fuselage_section.h. Lengths in m, angles in degrees.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace slamsph {

// Part ids of a fuselage section (ParticleLattice::part) and their names (output tables).
enum class FuselagePart : std::uint32_t { Skin = 0, Stringers = 1, Floor = 2, Columns = 3 };
inline const std::vector<std::string>& fuselage_part_names() {
  static const std::vector<std::string> names{"skin", "stringers", "floor", "columns"};
  return names;
}

struct FuselageStringers {
  int count = 0;                  // evenly spaced around the ring (0: none)
  std::string section = "I";      // "I" (web between two flanges) or "L" (web on one flange)
  double height = 0.0;            // from the inner skin face to the stringer's inner edge [m]
  double web_thickness = 0.0;     // [m]
  double flange_width = 0.0;      // [m]
  double flange_thickness = 0.0;  // [m]
  double offset_deg = 0.0;        // angle of the first stringer's web, from +x, CCW [deg]
};

struct FuselageFloor {
  bool present = false;
  double height = 0.0;     // y of the floor's mid-plane relative to the ring centre [m]
  double thickness = 0.0;  // [m]
  double dx = 0.0;         // particle spacing of floor and columns (0: the skin's) [m]
};

struct FuselageColumns {
  std::vector<double> x;  // column centre lines relative to the ring centre [m]
  double width = 0.0;     // [m]
};

struct FuselageShape {
  double diameter = 0.0;        // outer skin diameter [m]
  double skin_thickness = 0.0;  // [m]
  int skin_layers = 0;          // particle layers through the skin (spacing = thickness/layers)
  FuselageStringers stringers;
  FuselageFloor floor;
  FuselageColumns columns;

  double skin_spacing() const { return skin_thickness / skin_layers; }
  double floor_spacing() const { return floor.dx > 0.0 ? floor.dx : skin_spacing(); }
};

}  // namespace slamsph
