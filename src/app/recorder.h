// The recorder: everything a run writes and remembers about its own history — the output
// folder (case.resolved.toml, forces.csv, probes.csv, bodies.csv, energy.csv, momentum.csv,
// the VTK series, summary.json), when the next probe row and VTK frame are due, and the peak force
// and impulse of each body. It reads the stepper's state and never changes it.
//
// Per step the driver calls before_step() (probe rows and VTK frames due at the current
// time), then FsiStepper::step(), then after_step() (forces.csv row, peak, impulse by the
// trapezoid rule over the step, failure.csv rows of the particles that failed in the step).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/failure_log.h"
#include "app/fsi_stepper.h"
#include "app/part_peaks.h"
#include "app/probes.h"
#include "app/run_options.h"
#include "io/case_config.h"
#include "io/vtk_writer.h"

namespace slamsph {

class CsvWriter;
class Executor;
class OutputFolder;

// A CSV file's state at a checkpoint: its name in the output folder, size and row count.
struct CsvResume {
  std::string name;
  std::uintmax_t bytes = 0;
  std::size_t rows = 0;
};

// Where a resumed run continues its output files (app/checkpoint.h).
struct RecorderResume {
  std::vector<CsvResume> csv;
  std::optional<VtkSeries::State> vtk;
  std::vector<std::string> case_overrides;  // --set notes of the run's case.resolved.toml
};

struct RunStatus {
  bool running = false;  // the summary written at the start: status "running"
  int code = 0;          // 0 completed or stopped, 3 diverged, 4 failed (environment error)
  std::string failure;   // divergence message, or the path and OS reason of the failure
  std::string stopped;   // why a run with code 0 ended before end_time (--max-steps), else ""
  int signal = 0;        // SIGINT/SIGTERM that stopped the run, else 0
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;  // user + system CPU time of all threads over wall_seconds
};

class Recorder {
 public:
  Recorder(const CaseConfig& cfg, const RunOptions& opt, const FsiStepper& stepper,
           const ProbeSet& probes, const Executor& exec);
  ~Recorder();

  // Creates the output folder and files (if output is on) and records the initial loads;
  // with `resume`, continues the files of a checkpointed run instead. In order: the
  // folder is opened (a previous run refused unless RunOptions::overwrite, app/output_folder.h),
  // the manifest lists the files about to be written, summary.json says "running", then
  // case.resolved.toml and the series files. `warnings` go into every summary.json.
  void start(std::vector<std::string> warnings, const RecorderResume* resume = nullptr);
  void before_step();
  void after_step();
  // The final probe and bodies rows and the last VTK frame of a completed run.
  void finish();
  // The state the run diverged in, as a VTK frame (unless that frame was just written).
  void after_divergence();
  // Flushes every file and brings the manifest up to date. Throws std::system_error (the
  // first failure) after trying every file.
  void flush();
  // summary.json, whole (temporary file and rename): status "running", "completed",
  // "stopped", "interrupted", "diverged" or "failed" (RunStatus).
  void write_summary(const RunStatus& status) const;

  // Checkpoint access (app/checkpoint.h). Call flush() first: the sizes are the files' now.
  std::vector<CsvResume> csv_state() const;
  std::optional<VtkSeries::State> vtk_state() const;
  template <class Self, class F>
  static void visit_state(Self& s, F&& f) {
    f("next_vtk_time", s.next_vtk_);
    f("next_probe_time", s.next_probe_);
    f("vtk_interval", s.vtk_dt_);
    f("probe_interval", s.probe_dt_);
    f("frame_step", s.frame_step_);
    f("peak_force", s.peak_);
    f("peak_magnitude", s.peak_mag_);
    f("peak_time", s.peak_time_);
    f("impulse", s.impulse_);
    f("wall_seconds_before", s.wall_before_);
    f("first_failure", s.failure_log_.first);
    f("part_peaks", s.part_peaks_.state);
    f("energy_initial", s.energy0_);
    f("energy_largest_term", s.energy_scale_);
    f("energy_max_residual", s.energy_max_residual_);
    f("energy_last_residual", s.energy_last_residual_);
    f("momentum_initial", s.momentum0_);
    f("momentum_largest_term", s.momentum_scale_);
    f("momentum_max_residual", s.momentum_max_residual_);
    f("momentum_last_residual", s.momentum_last_residual_);
  }
  // Wall time of the segments before this one (resumed runs) plus `segment`.
  double wall_seconds(double segment) const { return wall_before_ + segment; }

 private:
  void record_loads(double dt_prev);
  void record_probes();
  void record_bodies();
  void record_energy();
  void record_momentum();
  void write_frame();

  const CaseConfig& cfg_;
  const RunOptions& opt_;
  const FsiStepper& st_;
  const ProbeSet& probes_;
  const Executor& exec_;
  std::unique_ptr<OutputFolder> folder_;
  std::vector<std::string> warnings_;  // set-up warnings, for summary.json
  std::unique_ptr<VtkSeries> vtk_;
  std::unique_ptr<CsvWriter> forces_, probes_csv_, bodies_csv_, energy_csv_, momentum_csv_;
  FailureLog failure_log_;                  // failed particles (app/failure_log.h)
  PartPeaks part_peaks_;                    // peak strain per part (app/part_peaks.h)
  std::unique_ptr<CsvWriter> failure_csv_;  // failure.csv, when a law can fail

  double vtk_dt_ = 0.0, probe_dt_ = 0.0;
  double next_vtk_ = 0.0, next_probe_ = 0.0;
  long frame_step_ = -1;              // step count at the last VTK frame
  std::vector<BodyLoad> prev_loads_;  // loads at the start of the current step
  std::vector<Vec2> peak_, impulse_;  // per body [N/m], [N s/m]
  std::vector<double> peak_mag_, peak_time_;
  double wall_before_ = 0.0;  // [s] wall time of earlier segments of a resumed run
  // Energy balance (energy.csv): the state at t = 0 (fluid potential, fluid total, then per
  // elastic or rigid_free body its kinetic + strain + hourglass and its potential), the
  // largest |term| written, the largest |residual| and the last residual [J/m].
  std::vector<double> energy0_;
  double energy_scale_ = 0.0, energy_max_residual_ = 0.0, energy_last_residual_ = 0.0;
  // Momentum balance (momentum.csv): the water's momentum at t = 0, the largest |term|
  // written, the largest |residual| per component and the last residual [N s/m].
  Vec2 momentum0_;
  double momentum_scale_ = 0.0;
  Vec2 momentum_max_residual_, momentum_last_residual_;
};

}  // namespace slamsph
