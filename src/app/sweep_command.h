// `slamsph sweep CASE --set KEY=V1,V2,... [--set ...]`: runs the cartesian product of the
// listed values (any case key, each value checked exactly as `run --set` checks it; every
// variant is parsed and built before the first run), one sub-folder per variant, then
// writes into the study folder:
//   sweep.csv, sweep.md   one row per variant: the varied values, peak force and its time,
//                         impulse, peak strain and where (body, reference position), largest
//                         keel deflection, wall time, status (app/run_metrics.h);
//   sweep_force.png/.gp   the studied body's vertical force of every variant in one plot;
//   sweep_rerun.sh        the command that reruns the study, and each variant alone.
#pragma once
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace slamsph {

struct StudyTable;

// Registers `sweep` on the command line; when it is chosen, app.parse runs it and stores
// its exit code in `exit_code` (0 every variant completed, 3 one diverged, 130/143
// interrupted). Input errors throw InputError (exit 2) before any run.
CLI::App* add_sweep_command(CLI::App& app, int& exit_code);

}  // namespace slamsph
