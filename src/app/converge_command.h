// `slamsph converge CASE --dx-factors 1,0.5,0.25` (the fluid spacing times each factor,
// bodies keeping their spacing relative to the water) or `--set KEY=V1,V2,V3` with KEY a
// resolution key (ending in "layers": grid size ∝ 1/value; ending in "dx": ∝ value; the
// first multi-valued --set; further multi-valued --sets with as many values change with
// it, e.g. a ring's layers and the body spacing):
// runs each resolution, then writes into the study folder
//   converge.csv, converge.md   each metric per resolution (app/run_metrics.h) and, for
//                               every three consecutive resolutions, the observed order,
//                               the Richardson extrapolation and the GCI with Fs = 1.25
//                               (app/grid_convergence.h; oscillatory and divergent cases
//                               are named and get no order or GCI);
//   converge_force.png/.gp      the force histories of all resolutions in one plot;
//   converge_rerun.sh           the command that reruns the study, and each run alone.
#pragma once

namespace CLI {
class App;
}

namespace slamsph {

// Registers `converge`; when chosen, app.parse runs it and stores its exit code.
CLI::App* add_converge_command(CLI::App& app, int& exit_code);

}  // namespace slamsph
