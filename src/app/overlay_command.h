// `slamsph plot DIR1 DIR2 ... --out OUT`: several finished runs compared in one folder —
// the studied body's vertical force of each run in one plot (OUT/overlay_force.png), a
// table of their metrics (OUT/overlay.csv, overlay.md; app/run_metrics.h) and, when every
// run has a skin profile (`[output] skin_profile`), P_yy against the angle of each run at
// their last common snapshot in one plot (OUT/overlay_skin_pyy.png; the paper's Fig. 25).
// The .gp scripts name the runs' CSVs by paths relative to OUT.
#pragma once
#include <string>
#include <vector>

namespace slamsph {

// Returns 0, or 2 when a folder is not a results folder or OUT cannot be used.
int overlay_command(const std::vector<std::string>& dirs, const std::string& out,
                    const std::string& body, bool quiet);

}  // namespace slamsph
