// Point measurements of a run (the [[output.probe]] tables of a case): pressure at a point
// (Shepard kernel average), surge front, water height at x, largest fluid speed, pressure
// on a body surface and displacement of a body point. A body probe follows the body
// particle nearest to its start position (reference configuration).
//
// Structural probes (docs/case_format.md, "Structural probes"):
//   body_strain        equivalent (von Mises) Green–Lagrange strain at the particle [-]
//   body_stress        von Mises stress and P_yy (first Piola–Kirchhoff, yy) there [Pa]
//   body_max_strain    the body's largest equivalent strain and the reference position
//                      (X, Y) of the particle that carries it
//   keel_deflection    upward displacement of the body's lowest particle (reference
//                      configuration; ties: nearest the centre of mass in x) relative to
//                      the body's centre of mass: (y_k - y_c) - (Y_k - Y_c) [m]; > 0 when
//                      the bottom is pushed in
//   ovalisation        change of the vertical diameter (topmost minus lowest particle, in
//                      y) and of the horizontal one (rightmost minus leftmost, in x) [m]
//   shortening         reference minus current distance between the particles nearest
//                      `position` and `to` (a column's shortening, > 0 when shorter) [m]
//   midspan_deflection displacement of the particle nearest `at` relative to the chord
//                      between the particles nearest `position` and `to` (linearly
//                      interpolated at its projection), along the chord's left normal
//                      (+y for a chord drawn in +x) [m]
#pragma once
#include <string>
#include <vector>

#include "app/fsi_stepper.h"
#include "io/case_config.h"

namespace slamsph {

class Executor;

// Number of probes.csv columns a probe kind writes.
std::size_t headers_of_kind(const std::string& kind);

class ProbeSet {
 public:
  // dx: the fluid spacing (half of it is a particle's extent for fronts and heights).
  ProbeSet(std::vector<ProbeConfig> probes, const std::vector<SolidBody>& bodies, double dx);

  // Column headers with units ("name [Pa]"); some kinds give several columns.
  std::vector<std::string> headers() const;
  // Current values, one per header.
  std::vector<double> row(const FsiStepper& st, const Executor& exec) const;
  // First column of probe k.
  double value(std::size_t k, const FsiStepper& st, const Executor& exec) const;

 private:
  // The particles a body probe follows (indices into its body; unused ones 0).
  struct Attached {
    std::size_t body = 0, particle = 0;
    std::size_t to = 0, at = 0;                            // shortening, midspan_deflection
    std::size_t top = 0, bottom = 0, left = 0, right = 0;  // ovalisation, keel (bottom)
    Vec2 com0;                                             // reference centre of mass
  };
  std::vector<ProbeConfig> probes_;
  std::vector<Attached> attached_;  // per probe (body probes only)
  double dx_;
};

}  // namespace slamsph
