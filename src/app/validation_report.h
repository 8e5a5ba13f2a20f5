// Comparison of a finished run with the reference numbers of docs/references.md
// (§1 cylinder entry, §2 dam break, §5 plate), chosen by the case's output.plot.
// Reads the CSVs the run wrote, so `slamsph plot DIR` can redo it.
#pragma once
#include <string>

#include "io/case_config.h"
#include "io/json_writer.h"
#include "io/plot.h"

namespace slamsph {

// Index of the body the cylinder-entry validation looks at: the first body that is not
// rigid_fixed (the tank); -1 if none.
int entry_body_index(const CaseConfig& cfg);

// Plot parameters derived from the case (entry speed and radius, dam width, ...).
PlotParams plot_params_for(const CaseConfig& cfg);

// Fills `out` and returns true if the case has a validation target and its data exist.
bool validation_report(const CaseConfig& cfg, const std::string& out_dir, JsonObject& out);

}  // namespace slamsph
