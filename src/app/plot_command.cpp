#include "app/plot_command.h"

#include <cstdio>
#include <filesystem>

#include "app/validation_report.h"
#include "core/error.h"
#include "io/case_file.h"
#include "io/plot.h"

namespace slamsph {

int plot_command(const std::string& out_dir, bool quiet) {
  const std::string resolved = out_dir + "/case.resolved.toml";
  if (!std::filesystem::exists(resolved))
    throw InputError(out_dir + ": not a results folder (no case.resolved.toml)");
  const CaseConfig cfg = load_case(resolved);
  if (cfg.output.plot.empty()) {
    if (!quiet)
      std::fprintf(stderr, "%s: the case has no output.plot; nothing to draw\n", out_dir.c_str());
    return 0;
  }
  std::string message;
  const int code = plot_results(out_dir, cfg.output.plot, plot_params_for(cfg), message);
  if (code != 0 || !quiet)
    std::fprintf(stderr, "%s%s\n", code == 0 ? "" : "plot: ", message.c_str());
  return code;
}

}  // namespace slamsph
