// slamsph command line: run | check | plot | help, parsed with CLI11 (Debian libcli11-dev):
// every subcommand has its own --help listing each option and its default, options may
// come before or after the case file, and --opt=value works as well as --opt value.
// Exit codes: 0 ok, 1 internal error, 2 bad input (nothing computed; also an output folder
// holding another run without --overwrite), 3 diverged run (outputs so far kept), 4 a file
// or folder cannot be written (path and OS reason).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include "app/checkpoint.h"
#include "app/converge_command.h"
#include "app/cost_model.h"
#include "app/output_folder.h"
#include "app/overlay_command.h"
#include "app/plot_command.h"
#include "app/run_options.h"
#include "app/simulation.h"
#include "app/stop_signal.h"
#include "app/sweep_command.h"
#include "core/error.h"
#include "core/parallel.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

namespace {

using namespace slamsph;

// What the command line asked for, filled by CLI11's callbacks.
struct Request {
  std::string case_path;
  std::string out_dir;
  RunOptions run;
  std::optional<double> dx;
  std::vector<std::string> sets;
  std::string help_topic;
  std::vector<std::string> plot_dirs;  // plot: one run, or several compared in out_dir
  std::string plot_body;
  bool no_output = false;
  bool overwrite = false;
  bool no_machine_probe = false;  // check: the calibration machine's costs, unscaled
  bool exact_threads = false;     // run, resume: Executor::Load::Fixed
};

// "--threads" default text for the help: where the number comes from and its value now.
std::string thread_default_text() {
  const int env = Executor::env_threads();
  if (env > 0) return std::to_string(env) + " (from OMP_NUM_THREADS)";
  const int aff = Executor::affinity_threads();
  if (aff > 0) return std::to_string(aff) + " (CPUs this process may run on)";
  return std::to_string(Executor::hardware_threads()) + " (hardware threads)";
}

const CLI::Validator kPositiveFinite(
    [](std::string& s) -> std::string {
      double v = 0.0;
      if (!CLI::detail::lexical_cast(s, v) || !(v > 0.0) || !std::isfinite(v))
        return "expected a finite number > 0, got '" + s + "'";
      return "";
    },
    "NUMBER > 0");

// The options `run` and `check` share: the case file and what changes it.
void add_case_options(CLI::App& sub, Request& req) {
  sub.add_option("case", req.case_path, "The case file (TOML; docs/case_format.md)")
      ->required()
      ->type_name("CASE.toml");
  sub.add_option("--set", req.sets,
                 "Override one case key, validated like the file and recorded in "
                 "case.resolved.toml, e.g. --set numerics.end_time=0.02 or "
                 "--set body[0].velocity=[0,-3] (repeatable)")
      ->type_name("KEY=VALUE")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->allow_extra_args(false);
  sub.add_option("--max-particles", req.run.max_particles,
                 "Refuse a case estimated to have more particles than this (about 1 kB of "
                 "memory each)")
      ->check(kPositiveFinite)
      ->capture_default_str()
      ->type_name("N");
  sub.add_option("--dx", req.dx,
                 "Fluid particle spacing in m; bodies keep their spacing relative to the "
                 "water (default: numerics.dx of the case)")
      ->check(kPositiveFinite)
      ->type_name("DX");
}

int run_or_check(const std::string& cmd, Request& req) {
  CaseConfig cfg = load_case(req.case_path, req.sets);
  if (req.dx) rescale_resolution(cfg, *req.dx);
  RunOptions& opt = req.run;
  opt.write_output = !req.no_output;
  opt.adapt_threads = !req.exact_threads;
  // Set-up warnings go out after the particles are built and before any time step.
  auto warn = [&](const Simulation& sim) {
    if (opt.quiet) return;
    for (const std::string& w : sim.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  };
  if (cmd == "check") {
    RunOptions check_opt = silent_options(1);
    check_opt.max_particles = opt.max_particles;
    check_opt.end_time = opt.end_time;
    Simulation sim(std::move(cfg), check_opt);
    warn(sim);
    std::printf("%s: ok (%zu fluid particles", sim.config().name.c_str(), sim.fluid().size());
    for (const auto& b : sim.bodies()) std::printf(", %s: %zu", b.name.c_str(), b.size());
    const int threads = opt.threads > 0 ? opt.threads : Executor::default_threads();
    // The constants scaled to this machine (short built-in probe runs, app/cost_model.h).
    const MachineFactors f = req.no_machine_probe ? MachineFactors{} : measure_machine_factors();
    if (req.no_machine_probe)
      std::printf(")\nmachine: not probed (--no-machine-probe): the calibration runs' costs\n");
    else
      std::printf(
          ")\nmachine: costs x%.2g (water), x%.2g (solid sub-step in lanes), x%.2g (scalar) "
          "and x%.2g (solid set-up per fluid step) of the calibration runs' (measured on "
          "built-in probe runs)\n",
          f.fluid, f.solid, f.solid_scalar, f.solid_call);
    std::printf("%s", describe_cost(predict_cost(sim, scaled({}, f)), threads).c_str());
    return 0;
  }
  opt.out_dir = req.out_dir.empty() ? "results/" + cfg.name : req.out_dir;
  opt.overwrite = req.overwrite;
  // Before any particle is built: a folder holding another run is refused (exit 2).
  if (opt.write_output) OutputFolder::check_free(opt.out_dir, opt.overwrite);
  Simulation sim(std::move(cfg), opt);
  warn(sim);
  const int code = sim.run();
  if (code == 0 && sim.completed() && opt.write_output && !sim.config().output.plot.empty()) {
    const int pc = plot_command(opt.out_dir, opt.quiet);
    if (pc != 0) std::fprintf(stderr, "warning: plotting failed (results are complete)\n");
  }
  if (opt.write_output && !opt.quiet) std::fprintf(stderr, "results in %s\n", opt.out_dir.c_str());
  return code;
}

// `slamsph resume OUT`: the case as the run resolved it, continued from its newest
// checkpoint (app/checkpoint.h) in the same folder.
int resume_run(Request& req) {
  const std::string dir = req.out_dir;
  CaseConfig cfg = load_case(dir + "/case.resolved.toml");
  RunOptions& opt = req.run;
  opt.out_dir = dir;
  opt.write_output = true;
  opt.adapt_threads = !req.exact_threads;
  const std::string checkpoint = latest_checkpoint(dir);
  Simulation sim(std::move(cfg), opt);
  sim.resume_from(checkpoint);
  if (!opt.quiet) std::fprintf(stderr, "resuming from %s\n", checkpoint.c_str());
  const int code = sim.run();
  if (code == 0 && sim.completed() && !sim.config().output.plot.empty()) {
    const int pc = plot_command(opt.out_dir, opt.quiet);
    if (pc != 0) std::fprintf(stderr, "warning: plotting failed (results are complete)\n");
  }
  if (!opt.quiet) std::fprintf(stderr, "results in %s\n", opt.out_dir.c_str());
  return code;
}

int dispatch(int argc, char** argv) {
  Request req;
  CLI::App app("slamsph " SLAMSPH_VERSION
               ": SPH solver for water entry and slamming (Wang, Yang & Yang, Appl. Sci. "
               "2023)",
               "slamsph");
  app.set_version_flag("--version", "slamsph " SLAMSPH_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 internal error, 2 bad input (the message names file, line "
      "and key; nothing is written; also an output folder holding another run without "
      "--overwrite), 3 the run diverged (outputs so far are kept), 4 a file or folder "
      "cannot be created or written (path and OS reason; summary.json says \"failed\" "
      "when it can still be written).\n"
      "'slamsph help COMMAND' or 'slamsph COMMAND --help' lists a command's options.");

  CLI::App* run = app.add_subcommand("run", "Run a case and write its results");
  add_case_options(*run, req);
  run->add_option("-o,--out", req.out_dir, "Output folder (default: results/<case name>)")
      ->type_name("DIR");
  run->add_option("-t,--threads", req.run.threads,
                  "Threads (default: OMP_NUM_THREADS, else the CPUs in this process's "
                  "affinity mask, else the hardware threads; here " +
                      thread_default_text() + ")")
      ->check(CLI::Range(1, Executor::kMaxThreads))
      ->type_name("N");
  run->add_option("--end-time", req.run.end_time,
                  "Simulated end time in s (default: numerics.end_time of the case)")
      ->check(kPositiveFinite)
      ->type_name("T");
  run->add_option("--max-steps", req.run.max_steps,
                  "Stop after N fluid steps; the run is then reported as stopped, not "
                  "completed (default: no limit)")
      ->check(CLI::Range(0L, 1000000000000000L))
      ->type_name("N");
  run->add_option("--checkpoint-interval", req.run.checkpoint_interval,
                  "Write a checkpoint every T s of simulated time, and at the end, to "
                  "OUT/checkpoints (the last two are kept; continue with 'slamsph resume "
                  "OUT'; default: none)")
      ->check(kPositiveFinite)
      ->type_name("T");
  run->add_flag("--overwrite", req.overwrite,
                "Replace the results of a previous run in the output folder (removes only the "
                "files slamsph wrote there, listed in its .slamsph_files); default: such a "
                "folder is refused");
  run->add_flag("-q,--quiet", req.run.quiet, "Print nothing but errors");
  run->add_flag("--exact-threads", req.exact_threads,
                "Use --threads threads in every loop even while other programs keep the CPUs "
                "busy (tests, timings); default: fewer then, as many as fit beside them "
                "(results are the same either way)");
  run->add_flag("--no-output", req.no_output,
                "Write no files (benchmarks); default: write everything");

  CLI::App* check = app.add_subcommand(
      "check",
      "Validate a case, build its particles and print their counts and the predicted cost "
      "(steps, sub-steps, CPU and wall time); no time step");
  add_case_options(*check, req);
  check
      ->add_option("-t,--threads", req.run.threads,
                   "Threads to predict the wall time for (default as for run: " +
                       thread_default_text() + ")")
      ->check(CLI::Range(1, Executor::kMaxThreads))
      ->type_name("N");
  check
      ->add_option("--end-time", req.run.end_time,
                   "Simulated end time in s to predict for, as run --end-time (default: "
                   "numerics.end_time of the case)")
      ->check(kPositiveFinite)
      ->type_name("T");
  check->add_flag("--no-machine-probe", req.no_machine_probe,
                  "Predict with the calibration machine's per-particle costs, without the "
                  "short built-in probe runs (0.7-0.9 s) that scale them to this machine");

  CLI::App* resume = app.add_subcommand(
      "resume",
      "Continue a run in place from its newest checkpoint (see run --checkpoint-interval)");
  resume->add_option("dir", req.out_dir, "The run's output folder")->required()->type_name("OUT");
  resume
      ->add_option("--end-time", req.run.end_time,
                   "Simulated end time in s (default: the end time of the run)")
      ->check(kPositiveFinite)
      ->type_name("T");
  resume
      ->add_option("-t,--threads", req.run.threads,
                   "Threads (results do not depend on it; default as for run: " +
                       thread_default_text() + ")")
      ->check(CLI::Range(1, Executor::kMaxThreads))
      ->type_name("N");
  resume->add_flag("-q,--quiet", req.run.quiet, "Print nothing but errors");
  resume->add_flag("--exact-threads", req.exact_threads,
                   "Use --threads threads in every loop even while the CPUs are busy (as for run)");

  CLI::App* plot = app.add_subcommand("plot", "Redraw the PNG plots of a run from its folder");
  plot->add_option("dir", req.plot_dirs,
                   "A results folder (holding case.resolved.toml); several folders: their "
                   "forces (and skin P_yy) in one plot with a table, in --out")
      ->required()
      ->type_name("DIR...");
  plot->add_option("-o,--out", req.out_dir, "Comparison folder (several DIRs only)")
      ->type_name("OUT");
  plot->add_option("--body", req.plot_body,
                   "Body compared (several DIRs; default: the first not rigid_fixed)")
      ->type_name("NAME");

  int study_code = 0;  // sweep and converge run inside app.parse and leave their exit code
  CLI::App* studies[] = {add_sweep_command(app, study_code), add_converge_command(app, study_code)};

  CLI::App* help = app.add_subcommand("help", "Show the options of a command");
  help->add_option("command", req.help_topic, "run, check or plot")->type_name("COMMAND");

  // A first word that is neither an option nor a command is a mistyped command (CLI11 would
  // call it a missing subcommand).
  if (argc > 1 && argv[1][0] != '-') {
    const std::string first = argv[1];
    if (first != "run" && first != "check" && first != "plot" && first != "help" &&
        first != "resume" && first != "sweep" && first != "converge") {
      std::fprintf(stderr,
                   "error: command line: unknown command '%s'; expected run, resume, check, plot, "
                   "sweep, converge or help\n",
                   argv[1]);
      return 2;
    }
  }
  if (argc < 2) {
    std::cerr << app.help();
    std::fprintf(stderr, "error: command line: no command given\n");
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, the CLI11 message, and where to look; bad command lines are bad input.
    std::string what = e.what();
    if (what.empty()) what = e.get_name();
    const CLI::App* sub = nullptr;
    for (const CLI::App* s : {run, resume, check, plot, help})
      if (s->parsed()) sub = s;
    std::fprintf(stderr, "error: command line: %s (see 'slamsph %s--help')\n", what.c_str(),
                 sub ? (sub->get_name() + " ").c_str() : "");
    return 2;
  }

  if (help->parsed()) {
    if (req.help_topic.empty()) {
      // app.help() would describe the selected subcommand (help itself).
      std::cout << app.get_formatter()->make_help(&app, "slamsph", CLI::AppFormatMode::Normal);
      return 0;
    }
    for (CLI::App* s : {run, resume, check, plot, studies[0], studies[1]})
      if (s->get_name() == req.help_topic) {
        std::cout << s->help("slamsph");
        return 0;
      }
    std::fprintf(stderr, "error: command line: no command '%s'; expected run, check or plot\n",
                 req.help_topic.c_str());
    return 2;
  }
  if (studies[0]->parsed() || studies[1]->parsed()) return study_code;
  if (plot->parsed() && req.plot_dirs.size() > 1)
    return overlay_command(req.plot_dirs, req.out_dir, req.plot_body, false);
  if (plot->parsed()) return plot_command(req.plot_dirs.front());
  if (resume->parsed()) return resume_run(req);
  return run_or_check(run->parsed() ? "run" : "check", req);
}

}  // namespace

int main(int argc, char** argv) {
  slamsph::install_stop_handlers();
  try {
    return dispatch(argc, argv);
  } catch (const slamsph::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const slamsph::DivergenceError& e) {
    std::fprintf(stderr, "error: run diverged: %s\n", e.what());
    return 3;
  } catch (const std::system_error& e) {
    // The environment refused (no such folder, permission, disk full): exit 4 with the path
    // and the OS reason. std::filesystem_error is a std::system_error.
    std::fprintf(stderr, "error: %s\n", e.what());
    return 4;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "internal error: %s\n", e.what());
    return 1;
  }
}
