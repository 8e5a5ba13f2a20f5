// Where a run's wall time goes (issue 13 item 5): the fluid step's phases timed with a
// steady clock around each operator group of FsiStepper::step(), summed over the steps this
// process took. summary.json writes them as "time_split_s" (with the rest of the wall time,
// output and set-up, as "other"); the cost model (app/cost_model.h) is calibrated from them
// (bench/calibrate_cost.py).
//
// On two threads the water's pair pass, and the virtual state of the fixed walls' contact
// entries, may run beside small bodies' sub-steps (app/fsi_stepper.h); their time then
// counts in solid_substeps, the wall time both took.
//
// A handful of clock reads per fluid step (~25 ns each) against steps of 0.1 ms to 1 s:
// the timing does not measurably change what it times.
#pragma once
#include <chrono>

namespace slamsph {

struct PhaseTimes {
  double step_limit = 0.0;         // choose_time_step: the fluid and solid step limits
  double fluid_integration = 0.0;  // the fluid's kick-drift-kick updates and the EOS
  double solid_substeps = 0.0;     // every body's sub-steps (dual time stepping) or step
  double neighbour_lists = 0.0;    // the interaction lists (their rebuilds included)
  double fluid_rates = 0.0;        // the GSPH water–water rates
  double contact = 0.0;            // body state to contact particles, virtual state,
                                   // contact rates both ways, leaks, forces to bodies
  double checks_and_zone = 0.0;    // divergence checks and the absorbing zone
  double total() const {
    return step_limit + fluid_integration + solid_substeps + neighbour_lists + fluid_rates +
           contact + checks_and_zone;
  }
  // The rest of a wall time `wall` (set-up, output, progress): summary.json's "other".
  double other(double wall) const { return wall - total(); }
  // f(name, seconds) for each phase, in the order above.
  template <class F>
  void visit(F&& f) const {
    f("step_limit", step_limit);
    f("fluid_integration", fluid_integration);
    f("solid_substeps", solid_substeps);
    f("neighbour_lists", neighbour_lists);
    f("fluid_rates", fluid_rates);
    f("contact", contact);
    f("checks_and_zone", checks_and_zone);
  }
};

// Adds the seconds since the last lap to one phase per call: lap(times.x) after the work of x.
class PhaseClock {
 public:
  PhaseClock() : last_(std::chrono::steady_clock::now()) {}
  void lap(double& phase) {
    const auto now = std::chrono::steady_clock::now();
    phase += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  std::chrono::steady_clock::time_point last_;
};

}  // namespace slamsph
