#include "app/plot_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "app/output_folder.h"
#include "app/validation_report.h"
#include "core/error.h"
#include "io/case_file.h"
#include "io/plot.h"

namespace slamsph {

namespace {

// The "status" of the run's summary.json ("completed", "stopped", "diverged", ...), or
// "unknown" when there is no summary (a run killed before it wrote one).
std::string run_status(const std::string& out_dir) {
  std::ifstream in(out_dir + "/summary.json");
  if (!in) return "unknown (no summary.json)";
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string s = ss.str();
  const std::string key = "\"status\": \"";
  const std::size_t at = s.find(key);
  if (at == std::string::npos) return "unknown";
  const std::size_t b = at + key.size();
  return s.substr(b, s.find('"', b) - b);
}

}  // namespace

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
  // Plots of a run that did not reach its end time must not pass for the case's result:
  // the status is said in every plot's title and in the message.
  const std::string status = run_status(out_dir);
  PlotParams params = plot_params_for(cfg);
  if (status != "completed") {
    params.note = "INCOMPLETE RUN (" + status + "), not the case's result";
    if (!quiet)
      std::fprintf(stderr,
                   "warning: %s: the run is %s, not completed; the plots show an incomplete run\n",
                   out_dir.c_str(), status.c_str());
  }
  // The plots are the run's files too (--overwrite removes them with the rest).
  std::optional<OutputFolder> folder;
  if (OutputFolder::holds_run(out_dir)) folder.emplace(out_dir, OutputFolder::Mode::Continue);
  std::string message;
  const int code = plot_results(out_dir, cfg.output.plot, params, message);
  if (folder) folder->record();
  if (status != "completed" && code == 0) message += " [INCOMPLETE RUN: " + status + "]";
  if (code != 0 || !quiet)
    std::fprintf(stderr, "%s%s\n", code == 0 ? "" : "plot: ", message.c_str());
  return code;
}

}  // namespace slamsph
