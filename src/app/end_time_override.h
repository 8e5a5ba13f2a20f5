// `--end-time T` of run, resume and the studies (RunOptions::end_time, applied by
// Simulation): the run ends at T instead of the case's numerics.end_time. Times the case
// lists within the run that the shorter run never reaches (output.snapshots after T) are
// dropped, each drop reported as a warning of the run (printed before any computation,
// kept in summary.json), and with no snapshot left output.skin_profile and
// output.snapshot_view too (the case check requires snapshots for them), so that
// case.resolved.toml stays a valid case that `slamsph plot` and `resume` read back. Before this, a
// run with an --end-time before a listed snapshot completed and then failed (exit 2) when the plot
// step re-read its own case.resolved.toml.
#pragma once
#include <string>
#include <vector>

#include "io/case_config.h"

namespace slamsph {

// Sets cfg.numerics.end_time = end_time; returns the warnings (empty if nothing dropped).
std::vector<std::string> override_end_time(CaseConfig& cfg, double end_time);

}  // namespace slamsph
