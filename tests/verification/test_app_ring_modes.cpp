// Free dry ring, plane strain: the ovalling modes n = 2 and 3 (issue 10 item 6) against
// thin-ring theory (inextensional modes with tangential inertia; Soedel, "Vibrations of
// Shells and Plates", 3rd ed., §5.2; Blevins, "Formulas for Natural Frequency and Mode
// Shape", table 9-1 case 1):
//   f_n = n(n² − 1)/(2π R²) · sqrt(D / (ρ h (n² + 1))),   D = E h³ / (12 (1 − ν²))
// (plane strain: the ring is the cross-section of an infinitely long shell, so D is the
// plate rigidity), R the mid-surface radius, h the thickness. Thin-ring theory neglects
// shear and rotary inertia: its error grows like (h/R)² n² (h/R = 0.05 here: the exact
// plane-strain values computed with CalculiX, scripts/calculix/ring_modes.py, are 0.2 %
// (n = 2) and 0.5 % (n = 3) below it; tests/verification/data/ccx_ring_modes.csv).
//
// The ring is the `ring` shape of the case files (geometry/polar_lattice.h, radially
// aligned layers) in aluminium (the paper's skin, §4.2: 2700 kg/m³, 67.5 GPa, ν 0.34),
// 3 mm thick, R/h = 20 (the paper's R/h is 100; a thinner ring costs (R/h)³ more per
// period at the same layer count: scripts/validate_ring_modes.sh runs both).
// The mode is excited by its velocity field (Kirchhoff kinematics through the thickness):
//   v_r = V cos nθ,  v_θ(z) = −(V/n) sin nθ + z (n − 1/n) (V/R) sin nθ
// and its frequency is measured from the zero crossings of the mid-surface radial
// displacement projected on cos nθ (the projection filters every other n).
// SLAMSPH_RING_{R_OVER_H,LAYERS,MODE,HOURGLASS,PERIODS} run DISABLED_OneRun by hand
// (the full table: scripts/validate_ring_modes.sh).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/parallel.h"
#include "geometry/polar_lattice.h"
#include "solid/body_dynamics.h"
#include "solid/body_setup.h"

using namespace slamsph;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kE = 67.5e9, kNu = 0.34, kRho = 2700.0, kH = 0.003;

double thin_ring_frequency(int n, double R, double h, double E = kE) {
  const double D = E * h * h * h / (12.0 * (1.0 - kNu * kNu));
  return n * (n * n - 1.0) / (2.0 * kPi * R * R) * std::sqrt(D / (kRho * h * (n * n + 1.0)));
}

struct RingModeResult {
  double f = 0.0;       // measured [Hz]
  double f_thin = 0.0;  // thin-ring theory [Hz]
  int crossings = 0;
  std::size_t particles = 0;
  double zigzag_ratio = 0.0;  // largest E_hg / strain energy over the run
  double seconds = 0.0;
};

RingModeResult run_ring_mode(double r_over_h, int layers, int n, double hourglass, double periods,
                             double youngs_modulus = kE) {
  const double R = r_over_h * kH, dx = kH / layers;
  const ParticleLattice lat = ring({0.0, 0.0}, R - 0.5 * kH, R + 0.5 * kH, layers);
  SolidBody b;
  b.X = lat.x;
  b.x = lat.x;
  b.layer = lat.layer;
  for (std::size_t i = 0; i < lat.size(); ++i) {
    b.V0.push_back(lat.volume[i]);
    b.rho0.push_back(kRho);
    b.m.push_back(kRho * lat.volume[i]);
  }
  ElasticMaterialInput mat;
  mat.name = "aluminium";
  mat.density = kRho;
  mat.youngs_modulus = youngs_modulus;
  mat.poisson_ratio = kNu;
  mat.hourglass = hourglass;  // av_alpha 1, av_beta 0: the case-file defaults
  BodySetup cfg;
  cfg.name = "ring";
  cfg.dx = dx;
  cfg.h_over_dx = 1.3;
  cfg.gravity = false;
  cfg.material = mat;
  setup_body(b, cfg);
  const Executor exec(1);

  RingModeResult r;
  r.particles = b.size();
  r.f_thin = thin_ring_frequency(n, R, kH);
  const double omega_ref = 2.0 * kPi * r.f_thin;
  const double amplitude = 0.1 * kH;  // displacement amplitude: linear, A/h = 0.1
  const double V = amplitude * omega_ref;
  std::vector<double> cos_n(b.size()), weight(b.size());
  double norm = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double th = std::atan2(b.X[i].y, b.X[i].x), rad = std::hypot(b.X[i].x, b.X[i].y);
    const double z = rad - R, c = std::cos(n * th), s = std::sin(n * th);
    const double vr = V * c, vt = -(V / n) * s + z * (n - 1.0 / n) * (V / R) * s;
    b.v[i] = {vr * std::cos(th) - vt * std::sin(th), vr * std::sin(th) + vt * std::cos(th)};
    cos_n[i] = c;
    weight[i] = b.m[i];
    norm += b.m[i] * c * c;
  }
  refresh_internal_forces(b, exec);  // the viscous force of the initial velocity
  auto modal = [&] {
    double s = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const Vec2 u = b.x[i] - b.X[i];
      const double th = std::atan2(b.X[i].y, b.X[i].x);
      s += weight[i] * cos_n[i] * (u.x * std::cos(th) + u.y * std::sin(th));
    }
    return s / norm;
  };
  // a(t) = A sin ωt: zero at t = 0 and at every half period.
  const double T_ref = 1.0 / r.f_thin, dt = T_ref / 200.0;
  const int wanted = static_cast<int>(std::lround(2.0 * periods));
  double t = 0.0, prev = 0.0, last = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  while (r.crossings < wanted && t < 2.0 * periods * T_ref) {
    advance_body(b, t, dt, {0.0, 0.0}, exec);
    t += dt;
    const double a = modal();
    if (t > 0.25 * T_ref && ((prev > 0.0) != (a > 0.0))) {
      ++r.crossings;
      last = t - dt * a / (a - prev);
    }
    prev = a;
    const BodyEnergies e = body_energies(b);
    if (e.strain > 0.0) r.zigzag_ratio = std::max(r.zigzag_ratio, e.hourglass / e.strain);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.f = r.crossings > 0 ? 0.5 * r.crossings / last : 0.0;
  return r;
}

void print(const char* tag, double r_over_h, int layers, int n, double hg,
           const RingModeResult& r) {
  std::printf(
      "[ring %s] R/h %g layers %d n %d hourglass %g: particles %zu, f %.3f Hz, thin ring %.3f Hz "
      "(%+.2f %%), %d crossings, E_hg/E_strain %.3g, %.1f s\n",
      tag, r_over_h, layers, n, hg, r.particles, r.f, r.f_thin, 100.0 * (r.f / r.f_thin - 1.0),
      r.crossings, r.zigzag_ratio, r.seconds);
}

// The exact plane-strain frequency from CalculiX (tests/verification/data/ccx_ring_modes.csv).
double ccx_frequency(int r_over_h, int n) {
  std::ifstream in(SLAMSPH_SOURCE_DIR "/tests/verification/data/ccx_ring_modes.csv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'r') continue;
    std::istringstream row(line);
    std::string a, b, c;
    std::getline(row, a, ',');
    std::getline(row, b, ',');
    std::getline(row, c, ',');
    if (std::stoi(a) == r_over_h && std::stoi(b) == n) return std::stod(c);
  }
  ADD_FAILURE() << "no CalculiX reference for R/h " << r_over_h << ", n " << n;
  return 0.0;
}

}  // namespace

// CI: R/h = 20, 2 layers (the paper's thinnest skin), one period each. The table at 2–12
// layers is scripts/validate_ring_modes.sh (docs/validation.md §5). 3 % is what the paper's
// 2-layer skin needs (issue 10); a modulus 10 % off moves f by 4.9 % and fails.
TEST(RingModes, TwoLayerRingOvallingN2AndN3) {
  for (int n : {2, 3}) {
    const RingModeResult r = run_ring_mode(20.0, 2, n, 0.1, 1.0);
    print("ci", 20.0, 2, n, 0.1, r);
    const double f_ccx = ccx_frequency(20, n);
    std::printf("  CalculiX %.3f Hz: %+.2f %%\n", f_ccx, 100.0 * (r.f / f_ccx - 1.0));
    EXPECT_EQ(r.crossings, 2);
    EXPECT_NEAR(r.f / f_ccx, 1.0, 0.03) << "n = " << n;
  }
}

// The hourglass control stiffens the non-affine bending field of a 2-layer skin: measured
// +0.8 % in f at α = 0.1 (n = 2); it may not exceed the bound sqrt(1 + α) − 1 = 4.9 %
// (docs/model.md §3), and must be there (a control that is not applied gives 0).
TEST(RingModes, HourglassControlStiffensTwoLayerRingSlightly) {
  const RingModeResult on = run_ring_mode(20.0, 2, 2, 0.1, 1.0);
  const RingModeResult off = run_ring_mode(20.0, 2, 2, 0.0, 1.0);
  const double stiffening = on.f / off.f - 1.0;
  std::printf("[ring] hourglass 0.1: %.3f Hz, off: %.3f Hz, stiffening %+.2f %%\n", on.f, off.f,
              100.0 * stiffening);
  EXPECT_GT(stiffening, 0.003);
  EXPECT_LT(stiffening, 0.02);
  EXPECT_GT(on.zigzag_ratio, 0.0);
  EXPECT_LT(on.zigzag_ratio, 0.05);
}

// Opt-in single run for the validation script: prints one line.
TEST(RingModes, DISABLED_OneRun) {
  auto env = [](const char* k, double d) {
    const char* v = std::getenv(k);
    return v ? std::atof(v) : d;
  };
  const double r_over_h = env("SLAMSPH_RING_R_OVER_H", 20.0);
  const int layers = static_cast<int>(env("SLAMSPH_RING_LAYERS", 2));
  const int n = static_cast<int>(env("SLAMSPH_RING_MODE", 2));
  const double hg = env("SLAMSPH_RING_HOURGLASS", 0.1);
  const double periods = env("SLAMSPH_RING_PERIODS", 3.0);
  const RingModeResult r = run_ring_mode(r_over_h, layers, n, hg, periods);
  print("run", r_over_h, layers, n, hg, r);
  std::printf("csv,%g,%d,%d,%g,%zu,%.6f,%.6f,%d,%.4g,%.2f\n", r_over_h, layers, n, hg, r.particles,
              r.f, r.f_thin, r.crossings, r.zigzag_ratio, r.seconds);
}
