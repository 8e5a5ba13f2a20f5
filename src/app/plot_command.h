// `slamsph plot DIR`: draws the PNGs of a finished run from its CSVs and its resolved case.
#pragma once
#include <string>

namespace slamsph {

// Returns 0 on success, 2 if DIR is not a results folder, else the plot_results code.
// `quiet` prints only errors.
int plot_command(const std::string& out_dir, bool quiet = false);

}  // namespace slamsph
