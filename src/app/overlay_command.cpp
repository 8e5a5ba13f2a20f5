#include "app/overlay_command.h"

#include <cstdio>
#include <filesystem>

#include "app/study_runs.h"
#include "core/error.h"
#include "io/plot.h"

namespace slamsph {

namespace fs = std::filesystem;

int overlay_command(const std::vector<std::string>& dirs, const std::string& out,
                    const std::string& body, bool quiet) {
  if (out.empty())
    throw InputError("command line: plot with several folders needs --out DIR for the comparison");
  fs::create_directories(out);
  const fs::path base = fs::absolute(out);
  StudyOptions opt;
  opt.out_dir = out;
  opt.body = body;
  opt.case_path = "(several runs)";
  std::vector<StudyVariant> variants;
  std::vector<RunMetrics> metrics;
  for (const std::string& d : dirs) {
    StudyVariant v;
    // The run as seen from OUT, so that the tables and scripts work from there.
    v.label = fs::relative(fs::absolute(d), base).lexically_normal().string();
    v.values = {d};
    metrics.push_back(read_run_metrics(d, body));
    variants.push_back(v);
  }
  std::string command = "slamsph plot";
  for (const std::string& d : dirs) command += " " + shell_quote(d);
  command += " --out " + shell_quote(out);
  if (!body.empty()) command += " --body " + shell_quote(body);
  write_study_rerun(opt, "overlay_rerun.sh", command, {});
  const std::string msg =
      write_study_tables(opt, "overlay", "Runs compared", {"run"}, variants, metrics, command);
  if (!quiet)
    std::fprintf(stderr, "plot: %s; wrote %s/overlay.csv, overlay.md\n", msg.c_str(), out.c_str());

  // Skin P_yy: the last snapshot index every run has.
  int common = 99;
  for (const std::string& d : dirs) {
    int last = 0;
    for (int k = 1; k <= 99; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "skin_pyy_%02d.csv", k);
      if (fs::exists(fs::path(d) / "snapshots" / name)) last = k;
    }
    common = std::min(common, last);
  }
  if (common > 0) {
    char name[32];
    std::snprintf(name, sizeof name, "skin_pyy_%02d.csv", common);
    std::string s = gnuplot_preamble("overlay_skin_pyy.png", 1100, 650);
    s += "set title " +
         gnuplot_quote("P_yy along the skin's mid-surface, snapshot " + std::to_string(common)) +
         "\nset xlabel 'angle from the keel, anticlockwise [deg]'\nset ylabel 'P_yy [Pa]'\n"
         "set xrange [0:360]\nset xtics 45\nset key below box opaque\nplot ";
    for (std::size_t k = 0; k < dirs.size(); ++k) {
      const std::string rel = (fs::path(variants[k].label) / "snapshots" / name).string();
      s += (k ? ", \\\n     " : "") + gnuplot_quote(rel) +
           " skip 1 using 1:2 with linespoints pt 7 ps 0.4 lw 1.5 title " + gnuplot_quote(dirs[k]);
    }
    s += "\n";
    std::string m;
    const int rc = run_gnuplot_script(out, "overlay_skin_pyy", s, "gnuplot", m);
    if (!quiet)
      std::fprintf(stderr, "plot: %s\n", rc == 0 ? "wrote overlay_skin_pyy.png" : m.c_str());
  }
  return 0;
}

}  // namespace slamsph
