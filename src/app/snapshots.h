// Field snapshots of a run at the times the case lists (`[output] snapshots`), for the
// paper's figures (Figs. 7, 10, 11, 13, 15, 16, 18, 19, 21, 22, 24 and 25; docs/studies.md):
//
//  snapshots/snapshot_NN.csv/.gp/.png  the particles at the first fluid step at or after
//      the NN-th time: the water coloured by pressure and the elastic bodies by equivalent
//      (von Mises) Green–Lagrange strain, each with its own colour bar; rigid bodies grey;
//      axes in metres (equal scales), the actual and the requested time in the title. The
//      view is `output.snapshot_view`, else the elastic bodies' bounding box at that time
//      widened by half its size on each side (clipped to the domain).
//  snapshots/skin_pyy_NN.csv, skin_pyy.png/.gp  with `output.skin_profile`: the first
//      Piola–Kirchhoff stress P_yy of the skin's mid-surface particles (a ring, or the part
//      "skin" of a fuselage, r_out = diameter/2) against the angle
//      θ, at every snapshot time in one plot (the paper's Fig. 25). Mid-surface: the
//      particles whose reference radius lies within half a layer of (r_in + r_out)/2 — the
//      middle layer for an odd layer count, the two middle layers (averaged at each angle of
//      the aligned polar lattice) for an even one. θ is measured at the ring's centre in the
//      reference configuration from the keel (lowest point, θ = 0), anticlockwise (+x side
//      first: θ = 90° at the +x side, 180° at the top), in degrees.
//
// PNGs need gnuplot; without it the CSV and .gp are written and one warning is printed.
#pragma once
#include <string>
#include <vector>

#include "app/fsi_stepper.h"
#include "io/case_config.h"

namespace slamsph {

class SnapshotWriter {
 public:
  // Snapshots at or after `start_time` are due (a resumed run skips earlier ones).
  SnapshotWriter(const CaseConfig& cfg, std::string out_dir, bool write_output, bool quiet,
                 double start_time);

  // Writes every snapshot whose time has been reached by the stepper's current time.
  void take_due(const FsiStepper& st);

 private:
  void write(const FsiStepper& st, std::size_t index);
  void write_skin_profile(const FsiStepper& st, std::size_t index);

  const CaseConfig& cfg_;
  std::string dir_;  // <out_dir>/snapshots
  bool enabled_, quiet_;
  std::size_t next_ = 0;                 // index of the next due snapshot
  std::vector<std::size_t> skin_taken_;  // snapshot indices with a skin profile written
  bool warned_ = false;
  std::vector<double> taken_at_;  // actual time of each snapshot (requested until taken)
};

}  // namespace slamsph
