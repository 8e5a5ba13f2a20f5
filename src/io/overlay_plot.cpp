#include "io/overlay_plot.h"

#include "io/plot.h"

namespace slamsph {

int plot_overlay(const std::string& out_dir, const std::string& stem,
                 const std::vector<OverlayCurve>& curves, const std::string& title,
                 const std::string& ylabel, const std::string& gnuplot, std::string& message) {
  if (curves.empty()) {
    message = "plot: no curve to overlay";
    return 2;
  }
  std::string s = gnuplot_preamble(stem + ".png", 1100, 700);
  s += "set title " + gnuplot_quote(title) + "\n";
  s += "set xlabel 'time [ms]'\nset ylabel " + gnuplot_quote(ylabel) + "\n";
  s += "set autoscale xfix\nset key below box opaque\n";
  s += "plot ";
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const OverlayCurve& c = curves[k];
    if (k) s += ", \\\n     ";
    s += gnuplot_quote(c.csv) + " skip 1 using ($1*1e3):(column(" + std::to_string(c.column + 1) +
         ")) with lines lw 2 lc " + std::to_string(k + 1) + " title " + gnuplot_quote(c.label);
  }
  s += "\n";
  const int rc = run_gnuplot_script(out_dir, stem, s, gnuplot, message);
  if (rc == 0) message = "wrote " + stem + ".png";
  return rc;
}

}  // namespace slamsph
