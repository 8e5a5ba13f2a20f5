// The Tait fluid's internal energy (fluid/fluid_energy.h) against the first law it comes
// from: e(ρ) = ∫_{ρ0}^{ρ} p/ρ'² dρ', checked by Simpson quadrature of the pressure the
// solver uses (TaitEos::pressure), by its derivative de/dρ = p/ρ², and by the acoustic
// limit c0² (ρ/ρ0 − 1)²/2. Breaking it on purpose (dropping the 1/r − 1 term, or the
// factor 1/(γ−1)) fails all three.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid/fluid_energy.h"

using namespace slamsph;

namespace {

double simpson(const TaitEos& eos, double a, double b) {
  const int n = 2000;
  const double h = (b - a) / n;
  auto f = [&](double r) { return eos.pressure(r) / (r * r); };
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

}  // namespace

TEST(FluidEnergy, TaitInternalEnergyIsTheWorkOfCompression) {
  for (const double gamma : {7.0, 1.0 + 1e-9, 3.0}) {
    const TaitEos eos{1000.0, 30.0, gamma};
    EXPECT_EQ(tait_specific_internal_energy(eos, 1000.0), 0.0);
    for (const double rho : {950.0, 990.0, 1003.0, 1050.0, 1200.0}) {
      SCOPED_TRACE(rho);
      const double e = tait_specific_internal_energy(eos, rho);
      EXPECT_NEAR(e, simpson(eos, 1000.0, rho), 1e-9 * std::abs(e) + 1e-12);
      EXPECT_GE(e, 0.0);  // compressed or stretched, the fluid stores energy
      const double d = 1e-4;
      const double de = (tait_specific_internal_energy(eos, rho + d) -
                         tait_specific_internal_energy(eos, rho - d)) /
                        (2 * d);
      EXPECT_NEAR(de, eos.pressure(rho) / (rho * rho), 1e-6 * std::abs(de) + 1e-9);
    }
  }
  // Acoustic limit, where the closed form would cancel: no loss of precision.
  const TaitEos eos{1000.0, 30.0, 7.0};
  const double d = 1e-6;
  EXPECT_NEAR(tait_specific_internal_energy(eos, 1000.0 * (1 + d)), 0.5 * 900.0 * d * d,
              1e-4 * 0.5 * 900.0 * d * d);
}

TEST(FluidEnergy, SumsKineticPotentialAndInternal) {
  FluidParticles f;
  f.resize(2);
  f.x = {{0.0, 1.0}, {2.0, -0.5}};
  f.v = {{3.0, 4.0}, {0.0, 0.0}};
  f.m = {2.0, 4.0};
  f.rho = {1000.0, 1010.0};
  const TaitEos eos{1000.0, 30.0, 7.0};
  const FluidEnergies e = fluid_energies(f, eos, {0.0, -9.81});
  EXPECT_DOUBLE_EQ(e.kinetic, 25.0);
  EXPECT_DOUBLE_EQ(e.potential, 2.0 * 9.81 * 1.0 + 4.0 * 9.81 * -0.5);
  EXPECT_DOUBLE_EQ(e.internal, 4.0 * tait_specific_internal_energy(eos, 1010.0));
}
