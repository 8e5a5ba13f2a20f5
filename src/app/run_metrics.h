// The numbers a study compares between runs, read back from a finished run's folder
// (case.resolved.toml, summary.json, forces.csv, probes.csv), so that `slamsph sweep`,
// `slamsph converge` and `slamsph plot DIR1 DIR2 ...` can use any run folder:
//   peak force: the largest |F| of the studied body's total fluid force in forces.csv and
//     its time (as summary.json's peak); the y component at that time is reported too;
//   impulse: the trapezoid integral of Fy over the whole record [N s/m];
//   peak strain: the largest value of the body's first body_max_strain probe and the
//     reference position of the particle that carried it;
//   keel deflection: the largest |value| of its first keel_deflection probe (signed);
//   wall time and status from summary.json.
// A metric whose data is absent is NaN (written "n/a").
#pragma once
#include <string>

namespace slamsph {

struct RunMetrics {
  std::string dir;
  std::string body;    // the studied body
  std::string status;  // summary.json "status" ("unknown" without a summary)
  double wall_seconds = 0.0;
  double peak_force = 0.0;    // max |F| [N/m]
  double peak_force_y = 0.0;  // Fy at that time [N/m]
  double peak_time = 0.0;     // [s]
  double impulse_y = 0.0;     // [N s/m]
  double peak_strain = 0.0;   // [-]
  double peak_strain_time = 0.0;
  double peak_strain_x = 0.0, peak_strain_y = 0.0;  // reference position of the particle [m]
  double keel_deflection = 0.0;                     // signed value of the largest |.| [m]
};

// The body a study looks at: `body` if not empty (InputError if the case has none of that
// name), else the first body that is not rigid_fixed (else the first body).
std::string studied_body(const std::string& dir, const std::string& body);

// Reads the metrics of the run in `dir` for `body` (see studied_body). Throws InputError
// when `dir` is not a results folder.
RunMetrics read_run_metrics(const std::string& dir, const std::string& body = "");

// Formats a metric for tables: "n/a" for NaN, else %.5g.
std::string metric_text(double v);

}  // namespace slamsph
