// slamsph command line: run | check | plot. Exit codes: 0 ok, 1 internal error,
// 2 bad input (nothing computed), 3 diverged run (outputs so far kept).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "app/plot_command.h"
#include "app/run_options.h"
#include "app/simulation.h"
#include "core/error.h"
#include "io/case_file.h"
#include "io/case_resolution.h"

namespace {

const char* kUsage =
    "usage:\n"
    "  slamsph run CASE.toml [--out DIR] [--threads N] [--end-time T] [--max-steps N]\n            "
    "    [--dx DX] [--quiet] [--no-output]\n"
    "  slamsph check CASE.toml      validate a case file and print its particle counts\n"
    "  slamsph plot DIR             (re)draw the PNG plots of a finished run in DIR\n"
    "  slamsph --version | --help\n";

double parse_number(const std::string& flag, const char* s) {
  char* end = nullptr;
  const double v = std::strtod(s, &end);
  if (end == s || *end != '\0')
    throw slamsph::InputError("command line: " + flag + ": expected a number, got '" + s + "'");
  return v;
}

int run_command(int argc, char** argv) {
  using namespace slamsph;
  if (argc < 3) throw InputError(std::string("missing CASE.toml\n") + kUsage);
  const std::string cmd = argv[1];
  const std::string path = argv[2];
  RunOptions opt;
  for (int k = 3; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> const char* {
      if (k + 1 >= argc) throw InputError("command line: " + a + ": expected a value");
      return argv[++k];
    };
    if (a == "--out")
      opt.out_dir = value();
    else if (a == "--threads") {
      const double n = parse_number(a, value());
      if (!(n >= 1 && n <= 1024) || n != std::floor(n))
        throw InputError("command line: --threads: expected a whole number from 1 to 1024");
      opt.threads = static_cast<int>(n);
    } else if (a == "--end-time") {
      opt.end_time = parse_number(a, value());
      if (!(*opt.end_time > 0.0) || !std::isfinite(*opt.end_time))
        throw InputError("command line: --end-time: expected a finite time > 0 s");
    } else if (a == "--max-steps") {
      const double n = parse_number(a, value());
      if (!(n >= 0 && n <= 1e15) || n != std::floor(n))
        throw InputError("command line: --max-steps: expected a whole number >= 0");
      opt.max_steps = static_cast<long>(n);
    } else if (a == "--dx") {
      opt.dx = parse_number(a, value());
      if (!(*opt.dx > 0.0) || !std::isfinite(*opt.dx))
        throw InputError("command line: --dx: expected a positive length in m");
    } else if (a == "--quiet")
      opt.quiet = true;
    else if (a == "--no-output")
      opt.write_output = false;
    else
      throw InputError("command line: unknown option '" + a + "'\n" + kUsage);
  }
  if (cmd == "plot") return plot_command(path);
  CaseConfig cfg = load_case(path);
  if (opt.dx) rescale_resolution(cfg, *opt.dx);
  // Set-up warnings go out after the particles are built and before any time step.
  auto warn = [](const Simulation& sim) {
    for (const std::string& w : sim.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  };
  if (cmd == "check") {
    Simulation sim(std::move(cfg), silent_options(1));
    warn(sim);
    std::printf("%s: ok (%zu fluid particles", sim.config().name.c_str(), sim.fluid().size());
    for (const auto& b : sim.bodies()) std::printf(", %s: %zu", b.name.c_str(), b.size());
    std::printf(")\n");
    return 0;
  }
  if (opt.out_dir.empty()) opt.out_dir = "results";
  Simulation sim(std::move(cfg), opt);
  warn(sim);
  const int code = sim.run();
  if (code == 0 && opt.write_output && !sim.config().output.plot.empty()) {
    const int pc = plot_command(opt.out_dir);
    if (pc != 0) std::fprintf(stderr, "warning: plotting failed (results are complete)\n");
  }
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::printf("slamsph %s\n", SLAMSPH_VERSION);
    return 0;
  }
  const std::string cmd = argv[1];
  if (cmd != "run" && cmd != "check" && cmd != "plot") {
    std::fprintf(stderr, "error: unknown command '%s'\n%s", argv[1], kUsage);
    return 2;
  }
  try {
    return run_command(argc, argv);
  } catch (const slamsph::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const slamsph::DivergenceError& e) {
    std::fprintf(stderr, "error: run diverged: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "internal error: %s\n", e.what());
    return 1;
  }
}
