// Checkpoint and restart (issue 8, item 5). A checkpoint holds the whole state a
// continuation needs to be bit-identical to an uninterrupted run: every persistent field
// of the fluid, the contact set and each body (core/field_registry.h, by name), the body
// scalars (rigid motion, energy accumulators, law update counter), the stepper's counters
// and body loads, the neighbour lists' reference positions (the lists are rebuilt from
// them exactly, app/../coupling/interaction_lists.h), and the recorder's state (next output
// times, peak and impulse, CSV sizes and row counts, the VTK series index). Reference data
// (lattices, topology, layout, kernels) is rebuilt from the case by the case builder,
// which is deterministic.
//
// Files: OUT/checkpoints/checkpoint_<fluid step>.bin, binary (io/checkpoint_file.h),
// written via a temporary file and a rename; the last two are kept. A checkpoint is
// refused (InputError, exit 2) if it comes from another code version or another case:
// the header carries SLAMSPH_VERSION and a hash of the resolved case with its end time
// left out (resume may extend the end time).
#pragma once
#include <cstdint>
#include <string>

#include "app/fsi_stepper.h"
#include "app/recorder.h"
#include "io/case_config.h"

namespace slamsph {

class Executor;

// When the run writes checkpoints (stored in them, so a resumed run keeps the schedule).
struct CheckpointSchedule {
  double interval = 0.0;  // [s] simulated time; 0 = no checkpoints
  double next = 0.0;      // [s]
};

// Hash of resolved_case_toml(cfg) with numerics.end_time zeroed.
std::uint64_t case_hash(const CaseConfig& cfg);

// Writes a checkpoint of the current state into out_dir/checkpoints and deletes all but the
// newest two; `wall_seconds` is the run's wall time so far. Returns the file's path.
std::string write_checkpoint(const std::string& out_dir, const CaseConfig& cfg,
                             const FsiStepper& stepper, const Recorder& recorder,
                             const CheckpointSchedule& schedule, double wall_seconds);

// The newest checkpoint in out_dir/checkpoints; InputError if there is none.
std::string latest_checkpoint(const std::string& out_dir);

// Restores a state written by write_checkpoint into a stepper and recorder freshly built
// from the same case. InputError (naming the file) for another version, another case or a
// damaged file. Returns where the recorder continues its files.
RecorderResume read_checkpoint(const std::string& path, const CaseConfig& cfg, FsiStepper& stepper,
                               Recorder& recorder, CheckpointSchedule& schedule,
                               const Executor& exec);

}  // namespace slamsph
