// What `slamsph sweep` and `slamsph converge` share: splitting "KEY=V1,V2,..." into values,
// validating every variant before any runs, running the variants one after another into
// sub-folders of the study folder, and writing the command file that reruns the study.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "app/run_metrics.h"
#include "io/case_config.h"

namespace CLI {
class App;
}

namespace slamsph {

// One run of a study.
struct StudyVariant {
  std::string label;                   // sub-folder name (file-safe)
  std::vector<std::string> overrides;  // "KEY=VALUE" applied to the case, like run --set
  std::vector<std::string> values;     // the varied values, in the order of the varied keys
  std::optional<double> dx;            // fluid spacing (bodies scale with it), if changed
};

struct StudyOptions {
  std::string case_path;
  std::string out_dir;
  std::string body;  // studied body ("" = first body that is not rigid_fixed)
  int threads = 0;
  std::optional<double> end_time;
  double max_particles = 1e7;
  bool quiet = false;
  bool overwrite = false;  // replace earlier runs in the variants' folders (app/output_folder.h)
};

// "KEY=V1,V2,..." → KEY and the values; commas inside [...], {...} or quotes do not split
// ("body[0].velocity=[0,-3],[0,-5]" has two values). Throws InputError naming the option
// for a missing '=', an empty key or an empty value.
std::pair<std::string, std::vector<std::string>> split_study_set(const std::string& set);

// A file-safe folder name from "KEY=VALUE" pairs (characters other than letters, digits,
// '.', '-', '_' and '=' become '-'), prefixed by the variant's number.
std::string study_label(std::size_t index, const std::vector<std::string>& overrides);

// The case of one variant, as run: parsed with the overrides (every check of run --set),
// rescaled to the variant's dx, with a body_max_strain and a keel_deflection probe added
// for an elastic studied body that has none (named study_max_strain, study_keel), so that
// the study tables have them; case.resolved.toml records them.
CaseConfig study_case(const StudyOptions& opt, const StudyVariant& v);

// Parses and builds every variant's particles (all checks of `slamsph check`) and checks
// that its folder holds no earlier run unless opt.overwrite, before any run; the first bad
// variant throws InputError with its label.
void validate_study(const StudyOptions& opt, const std::vector<StudyVariant>& variants);

// Runs the variants into opt.out_dir/<label> and reads their metrics back (run_metrics.h).
// A diverged variant is recorded (status "diverged") and the study goes on; Ctrl-C or
// SIGTERM stops the study after the run in progress (the returned list is then shorter).
std::vector<RunMetrics> run_study(const StudyOptions& opt,
                                  const std::vector<StudyVariant>& variants);

// Writes <out_dir>/<name>: a shell script that reruns the study with `command` and, commented,
// each variant alone (`slamsph run CASE --set ... --out DIR`).
void write_study_rerun(const StudyOptions& opt, const std::string& name, const std::string& command,
                       const std::vector<StudyVariant>& variants);

// The options every study command takes: --body, --threads, --end-time, --overwrite and
// --quiet. `use` says what the study does with the body ("tabulated", "compared") and `run`
// what one run is called in the help ("variant", "run").
void add_study_options(CLI::App& sub, StudyOptions& opt, const std::string& use,
                       const std::string& run);

// A study's exit code: 128 + the signal that stopped it, else 3 if a run diverged, else 0.
int study_exit_code(const std::vector<RunMetrics>& metrics);

// A POSIX-shell-quoted word (for command files).
std::string shell_quote(const std::string& s);

}  // namespace slamsph

namespace slamsph {

// Writes <out_dir>/<stem>.csv and <stem>.md: one row per run, the `keys` columns holding
// each variant's values, then the metrics; the .md also gives `command` and a note per
// missing metric. Returns the overlay plot's message (the force of every run in
// <stem>_force.png), or the reason it was not drawn.
std::string write_study_tables(const StudyOptions& opt, const std::string& stem,
                               const std::string& title, const std::vector<std::string>& keys,
                               const std::vector<StudyVariant>& variants,
                               const std::vector<RunMetrics>& metrics, const std::string& command);

}  // namespace slamsph
