// Result plots with gnuplot: for each plot a script <name>.gp is written into the output
// folder next to the data and run there (gnuplot, terminal pngcairo), producing
// <name>.png. The .gp files reference the CSVs by relative name, so they can be edited and
// rerun by hand (`cd out && gnuplot slamming_force.gp`).
//
// Kinds (output.plot in the case file):
//  "cylinder_entry": forces.csv column "<body> Fy [N/m]" (p.body, or p.column) and the
//      body's path in bodies.csv ("<body> com_y [m]", "<body> vel_y [m/s]") with the still
//      surface p.surface_y: the series Cs = F/(ρ V(t)² R) against s(t)/D, t0 the geometric
//      contact time (io/entry_series.h; without a path: constant p.velocity from
//      p.t_contact) → slamming_cs.csv, slamming_force.png (F against t − t0 with each
//      theory's force at the actual V(t), s(t)), slamming_coefficient.png (Cs against s/D)
//      and entry_velocity.png (V against t − t0); references: Campbell–Weynberg (3D fit),
//      von Kármán, Wagner and modified Logvinovich with the exact circle (2D;
//      reference_curves.h). Needs p.radius.
//  "dam_break": probes.csv column "surge_front [m]" (or p.column; else the first column
//      whose name contains "front" with unit [m]) → surge_front.png,
//      Z = (x − p.wall_x)/a against T = t sqrt(2g/a) with the Martin & Moyce and
//      Koshizuka & Oka points. Needs p.dam_width.
//  "plate": tip-displacement columns of bodies.csv, else probes.csv: p.column if set,
//      else headers containing "tip" with unit [m], else pairs "<name>_x [m]" and
//      "<name>_y [m]" (a body_displacement probe) → plate_tip.png in mm, with A sin(ωt) if
//      p.plate_omega and p.plate_amplitude are set.
//  "gate": tip-displacement columns as for "plate" → gate_tip.png in mm with the
//      Antoci et al. (2007) experimental peaks marked.
//  "structure": forces.csv column "<body> Fy [N/m]" (p.body, or p.column) → slamming_force.png
//      (kN/m against ms) and, from probes.csv, structure_response.png: one panel per unit —
//      displacements [m] in mm, strains [-], stresses [Pa] in MPa — with the leak count and a
//      body_max_strain probe's reference position (_X, _Y) left out (fuselage studies).
// The first CSV column is the time [s].
//
// Return codes: 0 success; 1 gnuplot not found; 2 missing file, column or parameter;
// 3 gnuplot failed. `message` says what was written (with peak and error metrics) or
// what went wrong.
#pragma once
#include <limits>
#include <string>
#include <vector>

namespace slamsph {

struct PlotParams {
  std::string column;       // override the column looked up by a kind ("" = default)
  std::string body;         // cylinder_entry: body whose force is plotted
  double density = 1000.0;  // cylinder_entry: fluid density ρ [kg/m^3]
  double velocity = 0.0;    // cylinder_entry: entry speed V [m/s]
  double radius = 0.0;      // cylinder_entry: R [m]
  double t_contact = 0.0;   // cylinder_entry: contact time if there is no body path [s]
  // cylinder_entry: still free-surface level [m]; with bodies.csv, s(t) from the body's path.
  double surface_y = std::numeric_limits<double>::quiet_NaN();
  double dam_width = 0.0;           // dam_break: initial column width a [m]
  double gravity = 9.81;            // dam_break: |g| [m/s^2]
  double wall_x = 0.0;              // dam_break: x of the wall the column rests against [m]
  double plate_omega = 0.0;         // plate: reference angular frequency [rad/s] (0 = none)
  double plate_amplitude = 0.0;     // plate: reference tip amplitude [m]
  std::string gnuplot = "gnuplot";  // executable name (searched in PATH) or path
  std::string note;  // second title line of every plot (an incomplete run), "" = none
};

int plot_results(const std::string& out_dir, const std::string& kind, const PlotParams& p,
                 std::string& message);

// Generic: the given columns of <out_dir>/<csv_name> (all but the first if empty) against
// the first column, into <out_dir>/<png_name> (script <png stem>.gp). Same return codes.
int plot_csv_columns(const std::string& out_dir, const std::string& csv_name,
                     const std::vector<std::string>& columns, const std::string& png_name,
                     const std::string& gnuplot, std::string& message);

// Building blocks for other plots (io/overlay_plot.h, app/snapshots.h): the common script
// head (pngcairo, CSV separator, grid) for <png>; a gnuplot single-quoted string; writing
// <out_dir>/<stem>.gp and running gnuplot in out_dir (gnuplot resolved by find_gnuplot),
// with the return codes above (<stem>.png must appear).
std::string gnuplot_preamble(const std::string& png, int width = 1000, int height = 700);
std::string gnuplot_quote(const std::string& s);
int run_gnuplot_script(const std::string& out_dir, const std::string& stem,
                       const std::string& script, const std::string& gnuplot, std::string& message);

// Full path of the gnuplot executable (name searched in PATH), or "" if not found.
std::string find_gnuplot(const std::string& name = "gnuplot");

}  // namespace slamsph
