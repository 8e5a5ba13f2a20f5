#include "app/sweep_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <memory>

#include "app/stop_signal.h"
#include "app/study_runs.h"
#include "core/error.h"
#include "core/parallel.h"
#include "io/case_file.h"

namespace slamsph {

namespace {

struct SweepRequest {
  StudyOptions opt;
  std::vector<std::string> sets;
};

// The study's own command line, for sweep_rerun.sh and sweep.md.
std::string sweep_command_line(const SweepRequest& r) {
  std::string c = "slamsph sweep " + shell_quote(r.opt.case_path);
  for (const std::string& s : r.sets) c += " --set " + shell_quote(s);
  c += " --out " + shell_quote(r.opt.out_dir);
  if (!r.opt.body.empty()) c += " --body " + shell_quote(r.opt.body);
  if (r.opt.end_time) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", *r.opt.end_time);
    c += std::string(" --end-time ") + buf;
  }
  if (r.opt.threads > 0) c += " --threads " + std::to_string(r.opt.threads);
  return c + " --overwrite";
}

int run_sweep(SweepRequest& r) {
  if (r.sets.empty())
    throw InputError("command line: sweep needs at least one --set KEY=V1,V2,...");
  // Keys and their values; the variants are their cartesian product, the first key
  // varying slowest.
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> values;
  for (const std::string& s : r.sets) {
    auto [k, v] = split_study_set(s);
    for (const std::string& known : keys)
      if (known == k) throw InputError("command line: --set " + k + " given twice");
    keys.push_back(k);
    values.push_back(v);
  }
  std::size_t n = 1;
  for (const auto& v : values) n *= v.size();
  if (n > 1000)
    throw InputError("command line: the sweep has " + std::to_string(n) +
                     " variants; at most 1000");
  std::vector<StudyVariant> variants;
  for (std::size_t i = 0; i < n; ++i) {
    StudyVariant v;
    std::size_t rest = i;
    std::vector<std::size_t> pick(keys.size());
    for (std::size_t k = keys.size(); k-- > 0;) {
      pick[k] = rest % values[k].size();
      rest /= values[k].size();
    }
    for (std::size_t k = 0; k < keys.size(); ++k) {
      v.overrides.push_back(keys[k] + "=" + values[k][pick[k]]);
      v.values.push_back(values[k][pick[k]]);
    }
    // Only the varied keys name the folder (a key with one value is the same for all).
    std::vector<std::string> named;
    for (std::size_t k = 0; k < keys.size(); ++k)
      if (values[k].size() > 1) named.push_back(v.overrides[k]);
    v.label = study_label(i, named);
    variants.push_back(v);
  }
  if (r.opt.out_dir.empty())
    r.opt.out_dir = "results/" + load_case(r.opt.case_path).name + "_sweep";
  if (!r.opt.quiet) std::fprintf(stderr, "sweep: checking %zu variants\n", variants.size());
  validate_study(r.opt, variants);
  const std::string command = sweep_command_line(r);
  write_study_rerun(r.opt, "sweep_rerun.sh", command, variants);
  const std::vector<RunMetrics> metrics = run_study(r.opt, variants);
  const std::string plot = write_study_tables(r.opt, "sweep", "Sweep of " + r.opt.case_path, keys,
                                              variants, metrics, command);
  if (!r.opt.quiet)
    std::fprintf(stderr, "sweep: %s; wrote %s/sweep.csv, sweep.md\n", plot.c_str(),
                 r.opt.out_dir.c_str());
  return study_exit_code(metrics);
}

}  // namespace

CLI::App* add_sweep_command(CLI::App& app, int& exit_code) {
  auto req = std::make_shared<SweepRequest>();
  CLI::App* sub = app.add_subcommand(
      "sweep",
      "Run a case for every combination of the listed values and tabulate peak force, "
      "impulse, peak strain, keel deflection (sweep.csv, sweep.md, sweep_force.png)");
  sub->add_option("case", req->opt.case_path, "The case file (TOML; docs/case_format.md)")
      ->required()
      ->type_name("CASE.toml");
  sub->add_option("--set", req->sets,
                  "A case key and its values, e.g. --set body[1].shape.layers=2,3,6 (values "
                  "checked like run --set; a single value applies to every variant; "
                  "repeatable: the variants are the cartesian product)")
      ->type_name("KEY=V1,V2,...")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->allow_extra_args(false);
  sub->add_option("-o,--out", req->opt.out_dir,
                  "Study folder (default: results/<case name>_sweep); variant runs go to "
                  "sub-folders")
      ->type_name("DIR");
  add_study_options(*sub, req->opt, "tabulated", "variant");
  sub->callback([req, &exit_code] { exit_code = run_sweep(*req); });
  return sub;
}

}  // namespace slamsph
