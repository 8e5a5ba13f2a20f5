#include "app/simulation.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>

#include "app/case_builder.h"
#include "app/recorder.h"
#include "app/setup_warnings.h"
#include "core/error.h"
#include "io/progress_line.h"

namespace slamsph {

Simulation::Simulation(CaseConfig config, const RunOptions& options)
    : cfg_(std::move(config)),
      opt_(options),
      exec_(options.threads > 0 ? options.threads : Executor::default_threads()) {
  if (opt_.end_time) cfg_.numerics.end_time = *opt_.end_time;
  warnings_ = setup_warnings(cfg_);
  BuiltCase built = build_case(cfg_);
  stepper_ = std::make_unique<FsiStepper>(built.params, std::move(built.system), exec_);
  probes_ = std::make_unique<ProbeSet>(cfg_.output.probes, bodies(), cfg_.numerics.dx);
}

Simulation::~Simulation() = default;

Vec2 Simulation::total_momentum() const {
  Vec2 p;
  const FluidParticles& f = fluid();
  for (std::size_t i = 0; i < f.size(); ++i) p += f.m[i] * f.v[i];
  for (const SolidBody& b : bodies()) {
    if (b.kind == BodyKind::RigidFixed || b.kind == BodyKind::RigidPrescribed) continue;
    if (b.kind == BodyKind::RigidFree) {
      p += b.rigid.mass * b.rigid.vel;
      continue;
    }
    for (std::size_t i = 0; i < b.size(); ++i) p += b.m[i] * b.v[i];
  }
  return p;
}

double Simulation::probe_value(std::size_t k) const {
  return probes_->value(k, *stepper_, exec_);
}

int Simulation::run() {
  Recorder rec(cfg_, opt_, *stepper_, *probes_, exec_);
  rec.start();
  const double end = cfg_.numerics.end_time;
  const bool show_progress = !opt_.quiet && isatty(STDERR_FILENO);
  ProgressLine progress(end, show_progress);
  const auto t0 = std::chrono::steady_clock::now();
  RunStatus status;
  try {
    while (time() < end * (1.0 - 1e-12)) {
      if (opt_.max_steps && steps() >= *opt_.max_steps) break;
      rec.before_step();
      stepper_->step();
      rec.after_step();
      progress.update(time(), steps(), last_step_limit().dt);
    }
    rec.finish();
  } catch (const DivergenceError& e) {
    status.code = 3;
    status.failure = e.what();
    rec.after_divergence();  // keep the state the run diverged in
  }
  progress.finish();
  status.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  rec.flush();
  rec.write_summary(status, warnings_);
  if (!opt_.quiet) {
    const double wall = status.wall_seconds;
    const double ps = wall > 0.0 ? double(fluid().size()) * double(steps()) / wall : 0.0;
    std::fprintf(stderr,
                 "%s: fluid particles: %zu, %ld fluid steps to t = %.6g s in %.2f s (%.4g "
                 "particle-steps/s, %d threads)\n",
                 cfg_.name.c_str(), fluid().size(), steps(), time(), wall, ps, exec_.threads());
  }
  if (status.code != 0) {
    std::fprintf(stderr, "error: run diverged: %s\n", status.failure.c_str());
    if (opt_.write_output)
      std::fprintf(stderr, "outputs written so far are kept in %s\n", opt_.out_dir.c_str());
  }
  return status.code;
}

}  // namespace slamsph
