// Several runs' force histories in one plot (`slamsph sweep`, `slamsph converge`): each
// curve is a column of a forces.csv given by its path relative to the plot's folder, so
// the written <stem>.gp can be rerun by hand in that folder.
#pragma once
#include <string>
#include <vector>

namespace slamsph {

struct OverlayCurve {
  std::string csv;    // path of the CSV relative to out_dir
  int column = 0;     // 0-based column index of the value (column 0 is the time [s])
  std::string label;  // legend text
};

// Writes <out_dir>/<stem>.gp and <stem>.png: the curves against time in ms. Return codes
// as plot_results (io/plot.h): 0 ok, 1 no gnuplot, 2 nothing to plot, 3 gnuplot failed.
int plot_overlay(const std::string& out_dir, const std::string& stem,
                 const std::vector<OverlayCurve>& curves, const std::string& title,
                 const std::string& ylabel, const std::string& gnuplot, std::string& message);

}  // namespace slamsph
