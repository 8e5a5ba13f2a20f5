#include "app/simulation.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

#include "app/case_builder.h"
#include "app/case_checks.h"
#include "app/checkpoint.h"
#include "app/end_time_override.h"
#include "app/recorder.h"
#include "app/setup_warnings.h"
#include "app/snapshots.h"
#include "app/stop_signal.h"
#include "core/error.h"
#include "io/progress_line.h"

namespace slamsph {
namespace {

// User + system CPU time of this process, all its threads [s].
double process_cpu_seconds() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0.0;
  auto sec = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  return sec(u.ru_utime) + sec(u.ru_stime);
}

// VTK frames at and after `frame` (<set>_<frame:05>.vtp) from an interrupted run, which the
// resumed run rewrites; removed so that none outlives the resumed run.
void remove_frames_from(const std::string& out_dir, int frame) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(out_dir + "/vtk", ec)) {
    const std::string n = e.path().filename().string();
    if (n.size() < 10 || n.substr(n.size() - 4) != ".vtp") continue;
    const std::string digits = n.substr(n.size() - 9, 5);
    if (n[n.size() - 10] != '_' || digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    if (std::stoi(digits) >= frame) std::filesystem::remove(e.path(), ec);
  }
}

}  // namespace

Simulation::Simulation(CaseConfig config, const RunOptions& options)
    : cfg_(std::move(config)),
      opt_(options),
      exec_(options.threads > 0 ? options.threads : Executor::default_threads(),
            options.adapt_threads ? Executor::Load::Adapt : Executor::Load::Fixed) {
  if (opt_.end_time) warnings_ = override_end_time(cfg_, *opt_.end_time);
  for (std::string& w : setup_warnings(cfg_)) warnings_.push_back(std::move(w));
  check_case_size(cfg_, opt_.max_particles);
  BuiltCase built = build_case(cfg_);
  check_built_case(cfg_, built.system);
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
    for (const Vec2& d : b.impulse_due) p += d;
  }
  return p;
}

double Simulation::probe_value(std::size_t k) const {
  return probes_->value(k, *stepper_, exec_);
}

int Simulation::run() {
  Recorder rec(cfg_, opt_, *stepper_, *probes_, exec_);
  CheckpointSchedule schedule{opt_.checkpoint_interval, opt_.checkpoint_interval};
  std::optional<RecorderResume> resume;
  if (!resume_from_.empty())
    resume = read_checkpoint(resume_from_, cfg_, *stepper_, rec, schedule, exec_);
  const bool checkpoints = schedule.interval > 0.0 && opt_.write_output;
  long checkpoint_step = resume_from_.empty() ? -1 : steps();  // step of the last checkpoint
  const double end = cfg_.numerics.end_time;
  // A terminal gets the line redrawn in place; a log a plain line every 10 s.
  ProgressLine progress(end, !opt_.quiet);
  if (!isatty(STDERR_FILENO)) progress.set_plain(10.0);
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_seconds();
  auto wall = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  auto checkpoint = [&] {
    rec.flush();
    write_checkpoint(opt_.out_dir, cfg_, *stepper_, rec, schedule, rec.wall_seconds(wall()));
    checkpoint_step = steps();
  };
  // CSV rows reach the disk at least every kFlushSeconds of wall time even when a step
  // takes longer than that (the writers themselves flush only when a row arrives).
  constexpr double kFlushSeconds = 2.0;
  double last_flush = 0.0;
  RunStatus status;
  std::optional<SnapshotWriter> snapshots;  // [output] snapshots (app/snapshots.h)
  try {
    if (resume) {
      if (resume->vtk) remove_frames_from(opt_.out_dir, resume->vtk->frame);
      rec.start(warnings_, &*resume);
    } else {
      rec.start(warnings_);
    }
    snapshots.emplace(cfg_, opt_.out_dir, opt_.write_output, opt_.quiet, time());
    while (time() < end * (1.0 - 1e-12)) {
      // Checkpoints are taken between steps, before the outputs due at this time.
      if (checkpoints && time() >= schedule.next - 1e-15) {
        while (schedule.next <= time() + 1e-15) schedule.next += schedule.interval;
        if (steps() != checkpoint_step) checkpoint();
      }
      if (const int sig = stop_signal()) {
        status.stopped = std::string(sig == SIGINT ? "SIGINT" : "SIGTERM") +
                         " received; stopped after the step in progress";
        status.signal = sig;
        break;
      }
      if (opt_.max_steps && steps() >= *opt_.max_steps) {
        status.stopped =
            "--max-steps " + std::to_string(*opt_.max_steps) + " reached before end_time";
        break;
      }
      rec.before_step();
      snapshots->take_due(*stepper_);
      stepper_->step();
      rec.after_step();
      progress.update(time(), steps(), last_step_limit().dt);
      if (opt_.write_output && wall() - last_flush >= kFlushSeconds) {
        rec.flush();
        last_flush = wall();
      }
    }
    // The end state, so that the run can be extended (slamsph resume --end-time).
    if (checkpoints && steps() != checkpoint_step) checkpoint();
    snapshots->take_due(*stepper_);
    rec.finish();
  } catch (const DivergenceError& e) {
    status.code = 3;
    status.failure = e.what();
    rec.after_divergence();  // keep the state the run diverged in
  } catch (const std::system_error& e) {
    // The environment refused (disk full, folder removed, permission): exit 4, and a
    // "failed" summary if it can still be written.
    status.code = 4;
    status.failure = e.what();
  }
  progress.finish();
  status.wall_seconds = wall();
  status.cpu_seconds = process_cpu_seconds() - cpu0;
  bool summary_written = false;
  if (opt_.write_output) {
    try {
      rec.flush();
    } catch (const std::system_error& e) {
      if (status.code != 4) status.code = 4, status.failure = e.what();
    }
  }
  try {
    rec.write_summary(status);
    summary_written = true;
  } catch (const std::system_error& e) {
    if (status.code != 4) status.code = 4, status.failure = e.what();
  }
  if (!opt_.quiet) {
    const double w = status.wall_seconds;
    const double ps = w > 0.0 ? double(fluid().size()) * double(steps()) / w : 0.0;
    std::fprintf(stderr,
                 "%s: fluid particles: %zu, %ld fluid steps to t = %.6g s in %.2f s (%.4g "
                 "particle-steps/s, %d thread%s)\n",
                 cfg_.name.c_str(), fluid().size(), steps(), time(), w, ps, exec_.threads(),
                 exec_.threads() == 1 ? "" : "s");
    // Where the time went (app/phase_times.h), largest first.
    std::vector<std::pair<double, const char*>> split;
    stepper_->phase_times().visit([&](const char* n, double s) { split.emplace_back(s, n); });
    split.emplace_back(stepper_->phase_times().other(w), "other");
    std::sort(split.begin(), split.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    std::string line = "time split:";
    for (const auto& [s, n] : split) {
      if (w <= 0.0 || s < 0.005 * w) continue;
      char buf[96];
      std::snprintf(buf, sizeof buf, " %s %.1f %%", n, 100.0 * s / w);
      line += buf;
    }
    std::fprintf(stderr, "%s; CPU %.2f s\n", line.c_str(), status.cpu_seconds);
    if (!status.stopped.empty())
      std::fprintf(stderr, "stopped: %s; results are incomplete\n", status.stopped.c_str());
  }
  if (status.code == 3) {
    std::fprintf(stderr, "error: run diverged: %s\n", status.failure.c_str());
    if (opt_.write_output)
      std::fprintf(stderr, "outputs written so far are kept in %s\n", opt_.out_dir.c_str());
  }
  if (status.code == 4) {
    std::fprintf(stderr, "error: %s\n", status.failure.c_str());
    if (opt_.write_output)
      std::fprintf(stderr, "the run failed; %s\n",
                   summary_written ? "summary.json says \"failed\"; outputs so far are kept"
                                   : "summary.json could not be written either");
  }
  completed_ = status.code == 0 && status.stopped.empty();
  if (status.code == 0 && status.signal) return 128 + status.signal;  // 130 SIGINT, 143 SIGTERM
  return status.code;
}

}  // namespace slamsph
