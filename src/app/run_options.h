// Command-line options of `slamsph run`.
#pragma once
#include <optional>
#include <string>

namespace slamsph {

struct RunOptions {
  std::string out_dir = "results";
  int threads = 0;                   // 0 = Executor::default_threads()
  std::optional<double> end_time;    // overrides numerics.end_time
  std::optional<long> max_steps;     // stop after this many fluid steps
  std::optional<double> dx;          // fluid spacing override (bodies scale with it)
  bool quiet = false;                // no progress line, no banner
  bool write_output = true;          // false: no VTK/CSV (benchmarks)
  bool overwrite = false;            // replace a previous run in out_dir (app/output_folder.h)
  double checkpoint_interval = 0.0;  // [s] simulated time between checkpoints; 0 = none
  double max_particles = 1e7;        // refuse a case estimated above this (app/case_checks.h)
  // false: every loop uses `threads` threads even while other programs keep the CPUs busy
  // (core/parallel.h, Executor::Load); results are the same either way.
  bool adapt_threads = true;
};

// Options for driving a Simulation from code (tests, benchmarks): silent, no files.
inline RunOptions silent_options(int threads) {
  RunOptions o;
  o.threads = threads;
  o.quiet = true;
  o.write_output = false;
  o.adapt_threads = false;  // a test that asks for 2 threads gets 2
  return o;
}

}  // namespace slamsph
