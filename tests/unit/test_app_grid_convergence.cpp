// Observed order and GCI (app/grid_convergence.h) against values worked by hand and the
// published example of Celik et al. (2008, J. Fluids Eng. 130 078001, Table 1, phi_1).
#include <gtest/gtest.h>

#include <cmath>

#include "app/grid_convergence.h"

namespace slamsph {
namespace {

// f = 1 + h^2 on h = 1, 2, 4: eps21 = 3, eps32 = 12, p = ln 4 / ln 2 = 2, extrapolated 1,
// GCI_fine = 1.25 * |2 - 5|/2 / (2^2 - 1) = 0.625.
TEST(AppGridConvergence, ConstantRatioByHand) {
  const GridConvergence g = grid_convergence(1, 2, 4, 2, 5, 17);
  EXPECT_EQ(g.kind, ConvergenceKind::Monotone);
  EXPECT_NEAR(g.ratio, 0.25, 1e-15);
  EXPECT_NEAR(g.order, 2.0, 1e-12);
  EXPECT_NEAR(g.extrapolated, 1.0, 1e-12);
  EXPECT_NEAR(g.gci_fine, 0.625, 1e-12);
}

// Unequal ratios (r21 = 1.5, r32 = 2): the fixed point must recover p = 2 of f = 1 + h^2
// exactly; the plain ln(eps32/eps21)/ln r21 would give ln(6.75/1.25)/ln 1.5 = 4.16.
TEST(AppGridConvergence, UnequalRatiosRecoverTheOrder) {
  const GridConvergence g = grid_convergence(1, 1.5, 3, 2, 3.25, 10);
  EXPECT_EQ(g.kind, ConvergenceKind::Monotone);
  EXPECT_NEAR(g.order, 2.0, 1e-9);
  EXPECT_NEAR(g.extrapolated, 1.0, 1e-9);
}

// Celik et al. 2008, Table 1, phi_1: N = 18000, 8000, 4500 cells (2D, h = N^-1/2),
// phi = 6.063, 5.972, 5.863 → p = 1.53, phi_ext = 6.1685, GCI_fine = 2.17 %.
TEST(AppGridConvergence, CelikPublishedExample) {
  const double h1 = 1 / std::sqrt(18000.0), h2 = 1 / std::sqrt(8000.0), h3 = 1 / std::sqrt(4500.0);
  const GridConvergence g = grid_convergence(h1, h2, h3, 6.063, 5.972, 5.863);
  EXPECT_EQ(g.kind, ConvergenceKind::Monotone);
  EXPECT_NEAR(g.order, 1.53, 0.005);
  EXPECT_NEAR(g.extrapolated, 6.1685, 0.0005);
  EXPECT_NEAR(g.gci_fine, 0.0217, 0.0002);
}

// f = 2, 1, 3: R = (1 - 2)/(3 - 1) = -0.5, oscillatory; band = 0.5 (3 - 1)/2 = 0.5; no
// order, no GCI.
TEST(AppGridConvergence, OscillatoryHasBandNoOrder) {
  const GridConvergence g = grid_convergence(1, 2, 4, 2, 1, 3);
  EXPECT_EQ(g.kind, ConvergenceKind::Oscillatory);
  EXPECT_NEAR(g.ratio, -0.5, 1e-15);
  EXPECT_NEAR(g.band, 0.5, 1e-15);
  EXPECT_TRUE(std::isnan(g.order));
  EXPECT_TRUE(std::isnan(g.gci_fine));
}

TEST(AppGridConvergence, DivergentAndExact) {
  const GridConvergence d = grid_convergence(1, 2, 4, 10, 5, 4);  // R = -5/-1 = 5
  EXPECT_EQ(d.kind, ConvergenceKind::Divergent);
  EXPECT_TRUE(std::isnan(d.gci_fine));
  const GridConvergence e = grid_convergence(1, 2, 4, 3, 3, 3);
  EXPECT_EQ(e.kind, ConvergenceKind::Exact);
  EXPECT_EQ(e.gci_fine, 0.0);
  EXPECT_THROW(grid_convergence(2, 1, 4, 1, 2, 3), std::invalid_argument);
}

}  // namespace
}  // namespace slamsph
