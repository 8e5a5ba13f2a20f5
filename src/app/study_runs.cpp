#include "app/study_runs.h"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "app/output_folder.h"
#include "app/plot_command.h"
#include "app/run_options.h"
#include "app/simulation.h"
#include "app/stop_signal.h"
#include "core/error.h"
#include "core/parallel.h"
#include "io/case_file.h"
#include "io/case_resolution.h"
#include "io/csv_writer.h"
#include "io/overlay_plot.h"

namespace slamsph {

std::pair<std::string, std::vector<std::string>> split_study_set(const std::string& set) {
  const std::size_t eq = set.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("command line: --set " + set +
                     ": expected KEY=V1,V2,... (a case key and one or more values)");
  const std::string key = set.substr(0, eq);
  std::vector<std::string> values;
  std::string cur;
  int depth = 0;
  char quote = 0;
  for (std::size_t i = eq + 1; i < set.size(); ++i) {
    const char c = set[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    } else if (c == ',' && depth == 0) {
      values.push_back(cur);
      cur.clear();
      continue;
    }
    cur += c;
  }
  values.push_back(cur);
  for (const std::string& v : values)
    if (v.find_first_not_of(" \t") == std::string::npos)
      throw InputError("command line: --set " + set + ": empty value in the list");
  return {key, values};
}

std::string study_label(std::size_t index, const std::vector<std::string>& overrides) {
  char num[16];
  std::snprintf(num, sizeof num, "%02zu", index + 1);
  std::string s = num;
  for (const std::string& o : overrides) {
    s += "_";
    for (const char c : o) {
      const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '-' || c == '_' || c == '=';
      s += ok ? c : '-';
    }
  }
  if (s.size() > 120) s.resize(120);
  return s;
}

CaseConfig study_case(const StudyOptions& opt, const StudyVariant& v) {
  CaseConfig cfg = load_case(opt.case_path, v.overrides);
  if (v.dx) rescale_resolution(cfg, *v.dx);
  const BodyConfig* body = nullptr;
  for (const BodyConfig& b : cfg.bodies)
    if ((opt.body.empty() && b.kind != "rigid_fixed") || b.name == opt.body) {
      body = &b;
      break;
    }
  if (!opt.body.empty() && !body)
    throw InputError(opt.case_path + ": --body " + opt.body + ": the case has no such body");
  if (body && body->kind == "elastic") {
    bool strain = false, keel = false;
    for (const ProbeConfig& p : cfg.output.probes) {
      strain = strain || (p.kind == "body_max_strain" && p.body == body->name);
      keel = keel || (p.kind == "keel_deflection" && p.body == body->name);
    }
    // Probe names must not clash with the case's own (io/case_parse.cpp checks the file).
    auto free_name = [&](std::string n) {
      for (bool clash = true; clash;) {
        clash = false;
        for (const ProbeConfig& p : cfg.output.probes)
          if (p.name.rfind(n, 0) == 0) clash = true;
        if (clash) n += "_";
      }
      return n;
    };
    const std::string name = body->name;
    if (!strain) {
      ProbeConfig p;
      p.name = free_name("study_max_strain");
      p.kind = "body_max_strain";
      p.body = name;
      cfg.output.probes.push_back(p);
    }
    if (!keel) {
      ProbeConfig p;
      p.name = free_name("study_keel");
      p.kind = "keel_deflection";
      p.body = name;
      cfg.output.probes.push_back(p);
    }
  }
  return cfg;
}

void validate_study(const StudyOptions& opt, const std::vector<StudyVariant>& variants) {
  for (const StudyVariant& v : variants) {
    try {
      RunOptions check = silent_options(1);
      check.max_particles = opt.max_particles;
      check.end_time = opt.end_time;  // applied by Simulation (app/end_time_override.h)
      Simulation sim(study_case(opt, v), check);
      OutputFolder::check_free(opt.out_dir + "/" + v.label, opt.overwrite);
    } catch (const InputError& e) {
      throw InputError("variant " + v.label + ": " + e.what());
    }
  }
}

std::vector<RunMetrics> run_study(const StudyOptions& opt,
                                  const std::vector<StudyVariant>& variants) {
  std::vector<RunMetrics> out;
  for (std::size_t k = 0; k < variants.size(); ++k) {
    const StudyVariant& v = variants[k];
    RunOptions ro;
    ro.threads = opt.threads;
    ro.quiet = opt.quiet;
    ro.max_particles = opt.max_particles;
    ro.end_time = opt.end_time;
    ro.overwrite = opt.overwrite;
    ro.out_dir = opt.out_dir + "/" + v.label;
    if (!opt.quiet) std::fprintf(stderr, "[%zu/%zu] %s\n", k + 1, variants.size(), v.label.c_str());
    Simulation sim(study_case(opt, v), ro);
    const int code = sim.run();
    if (code == 0 && sim.completed() && !sim.config().output.plot.empty())
      plot_command(ro.out_dir, true);
    out.push_back(read_run_metrics(ro.out_dir, opt.body));
    if (stop_signal()) break;
  }
  return out;
}

std::string shell_quote(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789_-+=./,:@") == std::string::npos)
    return s;
  std::string r = "'";
  for (const char c : s) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return r + "'";
}

void write_study_rerun(const StudyOptions& opt, const std::string& name, const std::string& command,
                       const std::vector<StudyVariant>& variants) {
  std::filesystem::create_directories(opt.out_dir);
  const std::string path = opt.out_dir + "/" + name;
  std::ofstream f(path);
  f << "#!/bin/sh\n# Written by slamsph: reruns this study (from the folder it was started "
       "in), replacing its runs (--overwrite).\n"
    << command
    << "\n\n# Each variant alone (the study adds its strain and keel probes to the "
       "case; each folder's case.resolved.toml has the case exactly as run):\n";
  for (const StudyVariant& v : variants) {
    std::string line = "# slamsph run " + shell_quote(opt.case_path);
    for (const std::string& o : v.overrides) line += " --set " + shell_quote(o);
    if (v.dx) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", *v.dx);
      line += std::string(" --dx ") + buf;
    }
    if (opt.end_time) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", *opt.end_time);
      line += std::string(" --end-time ") + buf;
    }
    line += " --out " + shell_quote(opt.out_dir + "/" + v.label) + " --overwrite";
    f << line << "\n";
  }
  f.close();
  if (!f)
    throw std::system_error(errno ? errno : EIO, std::generic_category(), "cannot write " + path);
  std::filesystem::permissions(path, std::filesystem::perms::owner_exec,
                               std::filesystem::perm_options::add);
}

}  // namespace slamsph

namespace slamsph {

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string r = "\"";
  for (const char c : s) r += c == '"' ? std::string("\"\"") : std::string(1, c);
  return r + "\"";
}

// Full precision for the CSV (the .md rounds to 5 digits).
std::string csv_number(double v) {
  if (std::isnan(v)) return "n/a";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string where_text(const RunMetrics& m) {
  if (std::isnan(m.peak_strain_x)) return "n/a";
  return m.body + " (" + metric_text(m.peak_strain_x) + ", " + metric_text(m.peak_strain_y) + ")";
}

}  // namespace

std::string write_study_tables(const StudyOptions& opt, const std::string& stem,
                               const std::string& title, const std::vector<std::string>& keys,
                               const std::vector<StudyVariant>& variants,
                               const std::vector<RunMetrics>& metrics, const std::string& command) {
  const std::string csv_path = opt.out_dir + "/" + stem + ".csv";
  std::ofstream csv(csv_path);
  csv << "variant";
  for (const std::string& k : keys) csv << "," << csv_field(k);
  csv << ",peak_force [N/m],peak_force_y [N/m],peak_time [s],impulse_y [N s/m],peak_strain "
         "[-],peak_strain_time [s],peak_strain_body,peak_strain_X [m],peak_strain_Y "
         "[m],keel_deflection [m],wall_time [s],status\n";
  std::ofstream md(opt.out_dir + "/" + stem + ".md");
  md << "# " << title << "\n\nCase `" << opt.case_path << "`, studied body `"
     << (metrics.empty() ? opt.body : metrics.front().body) << "`. Rerun: `" << command
     << "` (also in " << stem << "_rerun.sh).\n\n";
  md << "| variant |";
  for (const std::string& k : keys) md << " " << k << " |";
  md << " peak F [N/m] | t peak [s] | impulse Fy [N s/m] | peak strain [-] | at (body, X, Y "
        "[m]) | t strain [s] | max keel defl. [m] | wall [s] | status |\n|---|";
  for (std::size_t k = 0; k < keys.size(); ++k) md << "---|";
  md << "---|---|---|---|---|---|---|---|---|\n";
  std::vector<OverlayCurve> curves;
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    const RunMetrics& m = metrics[i];
    const StudyVariant& v = variants[i];
    csv << csv_field(v.label);
    for (const std::string& val : v.values) csv << "," << csv_field(val);
    for (double x : {m.peak_force, m.peak_force_y, m.peak_time, m.impulse_y, m.peak_strain,
                     m.peak_strain_time})
      csv << "," << csv_number(x);
    csv << "," << (std::isnan(m.peak_strain) ? "n/a" : m.body);
    for (double x : {m.peak_strain_x, m.peak_strain_y, m.keel_deflection, m.wall_seconds})
      csv << "," << csv_number(x);
    csv << "," << m.status << "\n";
    md << "| " << v.label << " |";
    for (const std::string& val : v.values) md << " `" << val << "` |";
    md << " " << metric_text(m.peak_force) << " | " << metric_text(m.peak_time) << " | "
       << metric_text(m.impulse_y) << " | " << metric_text(m.peak_strain) << " | " << where_text(m)
       << " | " << metric_text(m.peak_strain_time) << " | " << metric_text(m.keel_deflection)
       << " | " << metric_text(m.wall_seconds) << " | " << m.status << " |\n";
    const std::string forces = v.label + "/forces.csv";
    if (std::filesystem::exists(opt.out_dir + "/" + forces)) {
      const CsvTable t = read_csv(opt.out_dir + "/" + forces);
      const int col = t.find(m.body + " Fy [N/m]");
      std::string label;
      for (std::size_t k = 0; k < keys.size() && k < v.values.size(); ++k) {
        bool varied = false;  // keys with one value are the same for every curve
        for (const StudyVariant& w : variants) varied = varied || w.values[k] != v.values[k];
        if (varied || keys.size() == 1)
          label += (label.empty() ? "" : ", ") + keys[k] + "=" + v.values[k];
      }
      if (col > 0) curves.push_back({forces, col, label.empty() ? v.label : label});
    }
  }
  md << "\nPeak force: largest |F| of the body's fluid force (forces.csv, every fluid step); "
        "impulse: trapezoid integral of Fy over the record; peak strain: the largest "
        "equivalent Green-Lagrange strain of the body over the probe rows, at the reference "
        "position of the particle carrying it; keel deflection: signed value of the largest "
        "|keel_deflection| (docs/studies.md). n/a: the run has no such data.\n";
  if (variants.size() > metrics.size())
    md << "\nStopped after " << metrics.size() << " of " << variants.size()
       << " variants (interrupted).\n";
  csv.close();
  md.close();
  if (!csv || !md)
    throw std::system_error(errno ? errno : EIO, std::generic_category(),
                            "cannot write " + csv_path + " or its .md");
  std::string message;
  if (curves.empty()) return "no force history to overlay";
  plot_overlay(opt.out_dir, stem + "_force", curves, title + ": vertical force on the body",
               "Fy [N/m]", "gnuplot", message);
  return message;
}

}  // namespace slamsph

namespace slamsph {

void add_study_options(CLI::App& sub, StudyOptions& opt, const std::string& use,
                       const std::string& run) {
  sub.add_option("--body", opt.body,
                 "Body whose force, strain and keel are " + use +
                     " (default: the first body that is not rigid_fixed)")
      ->type_name("NAME");
  sub.add_option("-t,--threads", opt.threads, "Threads per run (default as for run)")
      ->check(CLI::Range(1, Executor::kMaxThreads))
      ->type_name("N");
  sub.add_option("--end-time", opt.end_time,
                 "Simulated end time of every " + run + " in s (default: the case's)")
      ->check(CLI::PositiveNumber)
      ->type_name("T");
  sub.add_flag("--overwrite", opt.overwrite,
               "Replace earlier runs in the variants' folders (default: refuse them, exit 2)");
  sub.add_flag("-q,--quiet", opt.quiet, "Print nothing but errors");
}

int study_exit_code(const std::vector<RunMetrics>& metrics) {
  if (const int sig = stop_signal()) return 128 + sig;
  for (const RunMetrics& m : metrics)
    if (m.status == "diverged") return 3;
  return 0;
}

}  // namespace slamsph
