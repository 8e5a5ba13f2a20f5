// Observed order of convergence and the Grid Convergence Index (GCI) of three solutions
// of one quantity on refined grids (Roache 1994; the procedure of Celik et al. 2008,
// J. Fluids Eng. 130, 078001, which allows a refinement ratio that differs between the two
// grid pairs). Used by `slamsph converge` (app/converge_command.h).
//
// With h1 < h2 < h3 (1 = finest), f1, f2, f3 the solutions, eps21 = f2 - f1,
// eps32 = f3 - f2, r21 = h2/h1, r32 = h3/h2 and R = eps21/eps32:
//   0 < R < 1   monotone convergence: p from the fixed point of
//               p = |ln|eps32/eps21| + q(p)| / ln r21, q(p) = ln((r21^p - s)/(r32^p - s)),
//               s = sign(eps32/eps21); extrapolated f = (r21^p f1 - f2)/(r21^p - 1);
//               GCI_fine = Fs |(f1 - f2)/f1| / (r21^p - 1), Fs = 1.25 (three grids).
//   R < 0       oscillatory convergence: no Richardson extrapolation exists (the error is
//               not a single power of h); p and GCI are not reported, the uncertainty is the
//               half range of the three solutions, 0.5 (max - min)/|f1| (Stern et al. 2001).
//   R >= 1      divergence (the change grows with refinement): nothing is reported.
//   eps21 = eps32 = 0  converged to round-off: GCI 0.
#pragma once
#include <string>

namespace slamsph {

enum class ConvergenceKind { Monotone, Oscillatory, Divergent, Exact, Undefined };

const char* convergence_kind_name(ConvergenceKind k);

struct GridConvergence {
  ConvergenceKind kind = ConvergenceKind::Undefined;
  double ratio = 0.0;         // R = eps21/eps32 (NaN when eps32 = 0)
  double order = 0.0;         // observed p (monotone only, else NaN)
  double extrapolated = 0.0;  // Richardson-extrapolated value (monotone only, else NaN)
  double gci_fine = 0.0;      // GCI of the finest grid, relative to |f1| (monotone/exact)
  double band = 0.0;          // oscillatory: half range relative to |f1|; else NaN
  std::string note;           // why a value is missing (one short sentence)
};

// h: grid sizes (any positive measure proportional to the spacing), h1 the finest;
// f: the solutions on those grids. safety: Fs (1.25 for three grids, Roache).
// Throws std::invalid_argument unless 0 < h1 < h2 < h3.
GridConvergence grid_convergence(double h1, double h2, double h3, double f1, double f2, double f3,
                                 double safety = 1.25);

}  // namespace slamsph
