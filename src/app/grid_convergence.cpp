#include "app/grid_convergence.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace slamsph {

const char* convergence_kind_name(ConvergenceKind k) {
  switch (k) {
    case ConvergenceKind::Monotone:
      return "monotone";
    case ConvergenceKind::Oscillatory:
      return "oscillatory";
    case ConvergenceKind::Divergent:
      return "divergent";
    case ConvergenceKind::Exact:
      return "converged";
    case ConvergenceKind::Undefined:
      break;
  }
  return "undefined";
}

GridConvergence grid_convergence(double h1, double h2, double h3, double f1, double f2, double f3,
                                 double safety) {
  if (!(h1 > 0.0) || !(h2 > h1) || !(h3 > h2))
    throw std::invalid_argument("grid_convergence: need 0 < h1 < h2 < h3");
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  GridConvergence g;
  g.ratio = g.order = g.extrapolated = g.gci_fine = g.band = nan;
  if (!std::isfinite(f1) || !std::isfinite(f2) || !std::isfinite(f3)) {
    g.note = "a solution is missing or not finite";
    return g;
  }
  const double e21 = f2 - f1, e32 = f3 - f2;
  if (e21 == 0.0 && e32 == 0.0) {
    g.kind = ConvergenceKind::Exact;
    g.ratio = 0.0;
    g.gci_fine = 0.0;
    g.extrapolated = f1;
    return g;
  }
  if (e32 == 0.0) {
    g.kind = ConvergenceKind::Divergent;
    g.note = "the two coarse grids agree exactly but the fine grid differs";
    return g;
  }
  g.ratio = e21 / e32;
  if (g.ratio < 0.0) {
    g.kind = ConvergenceKind::Oscillatory;
    const double lo = std::fmin(f1, std::fmin(f2, f3)), hi = std::fmax(f1, std::fmax(f2, f3));
    if (f1 != 0.0) g.band = 0.5 * (hi - lo) / std::abs(f1);
    g.note = "oscillatory: no observed order or GCI; band = half range of the three values";
    return g;
  }
  if (g.ratio >= 1.0) {
    g.kind = ConvergenceKind::Divergent;
    g.note = "the change does not shrink with refinement";
    return g;
  }
  if (e21 == 0.0) {  // the two finest agree exactly: converged on the fine pair
    g.kind = ConvergenceKind::Exact;
    g.gci_fine = 0.0;
    g.extrapolated = f1;
    return g;
  }
  g.kind = ConvergenceKind::Monotone;
  const double r21 = h2 / h1, r32 = h3 / h2;
  const double s = 1.0;  // sign(eps32/eps21) = +1 for monotone convergence
  const double lr = std::log(std::abs(e32 / e21));
  // Fixed-point iteration (Celik et al. 2008, eq. 3); q = 0 when r21 = r32, converges in a
  // few iterations otherwise.
  double p = lr / std::log(r21);
  for (int it = 0; it < 200; ++it) {
    const double q = std::log((std::pow(r21, p) - s) / (std::pow(r32, p) - s));
    const double next = std::abs(lr + q) / std::log(r21);
    if (!std::isfinite(next)) break;
    const bool done = std::abs(next - p) < 1e-12 * std::fmax(1.0, std::abs(p));
    p = next;
    if (done) break;
  }
  g.order = p;
  const double rp = std::pow(r21, p);
  g.extrapolated = (rp * f1 - f2) / (rp - 1.0);
  if (f1 != 0.0) g.gci_fine = safety * std::abs((f1 - f2) / f1) / (rp - 1.0);
  return g;
}

}  // namespace slamsph
