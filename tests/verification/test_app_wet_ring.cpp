// A ring half immersed in water, vibrating in its n = 2 ovalling mode (issue 10 item 6 and
// issue 9: "suction ... verified by a plate (or ring) vibrating in water against its
// added-mass frequency, which the clamp at 0 gets wrong on every outward stroke").
//
// Set-up: a free elastic ring, mid radius R = 0.1 m, h = 10 mm (2 layers), centred on the
// still free surface y = 0 of water 0.4 m deep in an open tank 0.8 m wide; the ring's
// inside is dry. Its density ρ_s = ρ a²/(4 R h) (2756 kg/m³, aluminium's) makes it float
// exactly half immersed (a = R + h/2, the wetted face), so with gravity the water starts at
// hydrostatic rest around a ring in equilibrium. The n = 2 mode is excited by its velocity
// field. Without gravity the water is at zero pressure and every outward stroke of the
// wetted half needs suction.
//
// Reference: potential flow, high-frequency free surface φ = 0 on y = 0 (exact without
// gravity; with gravity the correction is O(g/(ω² a)) ≈ 2 %). Inextensional ring modes
// u_r = q_n g_n(θ) of the family symmetric about the vertical axis (heave sin θ, cos 2θ,
// sin 3θ, cos 4θ, ...) with ring mass M_n = π ρ_s h R (1 + 1/n²) and stiffness
// K_n = π D (n² − 1)² / R³ (thin ring); the water outside r = a in the lower half plane has
//   φ = Σ_k c_k (a/r)^k sin kψ   (ψ the angle below the surface, so φ = 0 on it),
//   A_mn = ρ a² (π/2) Σ_k β_k(g_m) β_k(g_n) / k,
// β_k the sine coefficients of g on ψ ∈ (0, π) (derivation: kinetic energy ½ρ∮φ ∂φ/∂n).
// Heave alone gives ρπa²/2, the known high-frequency added mass of a half-immersed circle.
// The wet frequency is the lowest non-zero root of det(K − ω²(M + A)) (Rayleigh–Ritz over
// 8 modes; heave is free, so the ovalling mode drags the ring up and down, which raises
// the frequency by 10 % over the uncoupled estimate). The tank is not in the reference:
// a 1.2 m × 0.6 m tank changes the measured frequency by < 0.1 %.
//
// SLAMSPH_WET_RING_{DX,C0,HALF_WIDTH,DEPTH,PERIODS,CAVITATION,WATER,GRAVITY,RHO_S,AMPLITUDE}
// run DISABLED_OneRun by hand (scripts/validate_wet_ring.sh).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "app/simulation.h"
#include "io/case_file.h"

using namespace slamsph;

namespace {

constexpr double kPi = std::numbers::pi;
// Ring: mid radius, thickness, 2 layers; a soft solid so that the wet frequency is low.
constexpr double kR = 0.1, kH = 0.01, kE = 2.5e7, kNu = 0.34;
constexpr double kRhoF = 1000.0;

struct WetRingParams {
  double dx = 0.01;               // water spacing [m] (the ring has dx = h/2 = 5 mm)
  double c0 = 80.0;               // [m/s]
  double half_width = 0.4;        // tank inner half-width [m]
  double depth = 0.4;             // water depth below the ring centre [m]
  double periods = 2.0;           // periods of the wet mode measured
  double cavitation = -101325.0;  // fluid.cavitation_pressure [Pa]
  bool water = true;
  bool gravity = false;
  double g = 9.81;                     // [m/s^2] when gravity is on
  double rho_s = 1000.0;               // ring density [kg/m^3] (tests use floating_density())
  double amplitude = 0.1;              // initial mode amplitude / h
  bool hydrostatic_correction = true;  // fluid.hydrostatic_correction
};

// Water below y = 0 outside the ring: one block per column of cells where the column passes
// under the ring's dry inside (its top stops below the inner circle), one block each side
// elsewhere. Overlap removal (½(dx_f + dx_b)) clears the ring's own band.
std::string wet_ring_case(const WetRingParams& p) {
  std::ostringstream s;
  const double r_in = kR - 0.5 * kH, r_out = kR + 0.5 * kH, dx = p.dx;
  const double W = p.half_width, Dp = p.depth;
  s << "schema_version = 1\nname = \"wet_ring\"\n[numerics]\ndx = " << dx
    << "\nh_over_dx = 1.38\nend_time = 10.0\ngravity = [0.0, " << (p.gravity ? -p.g : 0.0) << "]\n"
    << "[numerics.domain]\nmin = [" << -W - 0.1 << ", " << -Dp - 0.1 << "]\nmax = [" << W + 0.1
    << ", " << r_out + 0.1 << "]\n[fluid]\ndensity = " << kRhoF << "\nsound_speed = " << p.c0
    << "\ncavitation_pressure = " << p.cavitation
    << "\nhydrostatic_correction = " << (p.hydrostatic_correction ? "true" : "false") << "\n";
  if (p.water) {
    const long nx = std::lround(2.0 * W / dx);
    const long ny_full = std::lround(Dp / dx);
    auto block = [&](double x0, double x1, long ny) {
      if (ny <= 0) return;
      s << "[[fluid.block]]\nmin = [" << x0 << ", " << -Dp << "]\nmax = [" << x1 << ", "
        << -Dp + ny * dx << "]\nsurface = 0.0\n";
    };
    long i = 0;
    while (i < nx) {
      const double xc = -W + (i + 0.5) * dx;
      if (std::abs(xc) >= r_in) {  // a run of full columns
        long j = i;
        while (j < nx && std::abs(-W + (j + 0.5) * dx) >= r_in) ++j;
        block(-W + i * dx, -W + j * dx, ny_full);
        i = j;
      } else {  // under the dry inside: particle centres below the inner circle only
        const double top = -std::sqrt(r_in * r_in - xc * xc);
        block(-W + i * dx, -W + (i + 1) * dx, static_cast<long>(std::floor((top + Dp) / dx + 0.5)));
        ++i;
      }
    }
    s << "[[body]]\nname = \"tank\"\nkind = \"rigid_fixed\"\ndensity = 1000.0\n"
      << "[body.shape]\ntype = \"tank\"\nmin = [" << -W << ", " << -Dp << "]\nmax = [" << W << ", "
      << r_out + 0.05 << "]\n";
  }
  s << "[materials.soft]\ndensity = " << p.rho_s << "\nyoungs_modulus = " << kE
    << "\npoisson_ratio = " << kNu << "\n"
    << "[[body]]\nname = \"ring\"\nkind = \"elastic\"\nmaterial = \"soft\"\ndx = " << 0.5 * kH
    << "\ngravity = " << (p.gravity ? "true" : "false")
    << "\n[body.shape]\ntype = \"ring\"\ncentre = [0.0, 0.0]\ninner_radius = " << r_in
    << "\nouter_radius = " << r_out << "\nlayers = 2\n";
  return s.str();
}

// Ring density at which it floats half immersed: 2π R h ρ_s = ρ π a²/2.
double floating_density() {
  const double a = kR + 0.5 * kH;
  return kRhoF * a * a / (4.0 * kR * kH);
}

double dry_frequency(int n, double rho_s) {  // thin ring, plane strain
  const double D = kE * kH * kH * kH / (12.0 * (1.0 - kNu * kNu));
  return n * (n * n - 1.0) / (2.0 * kPi * kR * kR) * std::sqrt(D / (rho_s * kH * (n * n + 1.0)));
}

// --- Rayleigh–Ritz reference (see the header comment) ---------------------------------
// Basis: n = 1 (heave, sin), 2 (cos), 3 (sin), ... in ψ, the angle below the surface.
// Sine coefficient k of g_n on (0, π): sin nψ → δ_kn; cos nψ → (4/π) k/(k² − n²) for k + n odd.
double sine_coefficient(int n, int k) {
  if (n % 2 == 1) return n == k ? 1.0 : 0.0;
  if ((k + n) % 2 == 0) return 0.0;
  return 4.0 / kPi * k / (static_cast<double>(k) * k - static_cast<double>(n) * n);
}

double added_mass(int m, int n) {
  const double a = kR + 0.5 * kH;
  double s = 0.0;
  for (int k = 1; k < 20001; ++k) s += sine_coefficient(m, k) * sine_coefficient(n, k) / k;
  return kRhoF * a * a * 0.5 * kPi * s;
}

// Lowest non-zero ω² of K x = ω² (M + A) x over basis n = 1..N (Cholesky of M + A, then
// cyclic Jacobi on L⁻¹ K L⁻ᵀ), its mode x and the ring's velocity u that excites it alone
// from water at rest: starting the flow is an impulse, (M + A) x = M u, and since
// (M + A) x = K x / ω², u_n ∝ (K_n / M_n) x_n (no heave: K_1 = 0). Both scaled to x_2 = 1.
struct RitzMode {
  double omega2 = 0.0;
  std::vector<double> x, u;  // coefficients of n = 1..N
};

RitzMode wet_mode(int N, bool with_fluid, double rho_s) {
  const double D = kE * kH * kH * kH / (12.0 * (1.0 - kNu * kNu));
  std::vector<double> Mt(N * N, 0.0), K(N * N, 0.0);
  for (int i = 0; i < N; ++i) {
    const int n = i + 1;
    Mt[i * N + i] = kPi * rho_s * kH * kR * (1.0 + 1.0 / (n * n));
    K[i * N + i] = kPi * D * (n * n - 1.0) * (n * n - 1.0) / (kR * kR * kR);
    if (with_fluid)
      for (int j = 0; j < N; ++j) Mt[i * N + j] += added_mass(n, j + 1);
  }
  std::vector<double> L(N * N, 0.0);  // Cholesky
  for (int i = 0; i < N; ++i)
    for (int j = 0; j <= i; ++j) {
      double s = Mt[i * N + j];
      for (int k = 0; k < j; ++k) s -= L[i * N + k] * L[j * N + k];
      L[i * N + j] = (i == j) ? std::sqrt(s) : s / L[j * N + j];
    }
  // C = L⁻¹ K L⁻ᵀ: solve L Y = K, then L Cᵀ = Yᵀ.
  auto lower_solve = [&](std::vector<double> B) {  // columns of B
    for (int c = 0; c < N; ++c)
      for (int i = 0; i < N; ++i) {
        double s = B[i * N + c];
        for (int k = 0; k < i; ++k) s -= L[i * N + k] * B[k * N + c];
        B[i * N + c] = s / L[i * N + i];
      }
    return B;
  };
  std::vector<double> Y = lower_solve(K), Yt(N * N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) Yt[i * N + j] = Y[j * N + i];
  std::vector<double> C = lower_solve(Yt), V(N * N, 0.0);
  for (int i = 0; i < N; ++i) V[i * N + i] = 1.0;
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0;
    for (int p = 0; p < N; ++p)
      for (int q = p + 1; q < N; ++q) off += C[p * N + q] * C[p * N + q];
    if (off < 1e-30) break;
    for (int p = 0; p < N; ++p)
      for (int q = p + 1; q < N; ++q) {
        if (std::abs(C[p * N + q]) < 1e-300) continue;
        const double th = 0.5 * std::atan2(2.0 * C[p * N + q], C[q * N + q] - C[p * N + p]);
        const double c = std::cos(th), s = std::sin(th);
        for (int k = 0; k < N; ++k) {  // columns p, q (and of the eigenvectors)
          const double a = C[k * N + p], b = C[k * N + q];
          C[k * N + p] = c * a - s * b;
          C[k * N + q] = s * a + c * b;
          const double va = V[k * N + p], vb = V[k * N + q];
          V[k * N + p] = c * va - s * vb;
          V[k * N + q] = s * va + c * vb;
        }
        for (int k = 0; k < N; ++k) {  // rows p, q
          const double a = C[p * N + k], b = C[q * N + k];
          C[p * N + k] = c * a - s * b;
          C[q * N + k] = s * a + c * b;
        }
      }
  }
  RitzMode m;
  m.omega2 = 1e300;
  int which = -1;
  const double scale = K[1 * N + 1] / Mt[1 * N + 1];
  for (int i = 0; i < N; ++i)
    if (C[i * N + i] > 1e-6 * scale && C[i * N + i] < m.omega2) {
      m.omega2 = C[i * N + i];
      which = i;
    }
  // x = L⁻ᵀ y, y the eigenvector of C.
  m.x.assign(N, 0.0);
  for (int i = N - 1; i >= 0; --i) {
    double t = V[i * N + which];
    for (int k = i + 1; k < N; ++k) t -= L[k * N + i] * m.x[k];
    m.x[i] = t / L[i * N + i];
  }
  const double x2 = m.x[1];
  m.u.assign(N, 0.0);
  for (int i = 0; i < N; ++i) {
    m.x[i] /= x2;
    const int n = i + 1;
    const double ring_mass = kPi * rho_s * kH * kR * (1.0 + 1.0 / (n * n));
    const double ring_mass2 = kPi * rho_s * kH * kR * 1.25;
    m.u[i] = (K[i * N + i] / ring_mass) / (K[N + 1] / ring_mass2) * m.x[i];
  }
  (void)which;
  return m;
}

double wet_omega2(int N, bool with_fluid, double rho_s) {
  return wet_mode(N, with_fluid, rho_s).omega2;
}

struct WetRingResult {
  double f = 0.0;          // measured [Hz]
  int crossings = 0;       // extrema found (alternating)
  double amplitude = 0.0;  // |first extremum| of the mode [m]
  std::size_t fluid = 0, ring = 0;
  long steps = 0, substeps = 0, leaked = 0;
  double max_wall_speed = 0.0, seconds = 0.0;
};

// Excites the wet n = 2 mode (cos 2θ amplitude A = amplitude · h; θ from the horizontal, so
// the keel and the waterline move) and measures the frequency of the projection of u_r
// (rigid translation removed) on cos 2θ.
WetRingResult run_wet_ring(const WetRingParams& p) {
  Simulation sim(parse_case_string(wet_ring_case(p), "wet_ring.toml"), silent_options(1));
  const std::size_t k = sim.bodies().size() - 1;
  SolidBody& b = sim.bodies()[k];
  const double f_dry = dry_frequency(2, p.rho_s);
  const double f_guess = std::sqrt(wet_omega2(8, p.water, p.rho_s)) / (2 * kPi);
  const double V = p.amplitude * kH * 2.0 * kPi * f_dry;
  // Initial ring velocity: the combination of inextensional modes n = 1..8 that excites the
  // Ritz wet mode alone (RitzMode::u; without water the dry n = 2 mode), scaled so that its
  // cos 2θ part has amplitude V; Kirchhoff kinematics through the thickness.
  const RitzMode mode = wet_mode(8, p.water, p.rho_s);
  std::vector<double> c2(b.size()), th(b.size());
  double norm_c2 = 0.0, mass = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    th[i] = std::atan2(b.X[i].y, b.X[i].x);
    const double r = std::hypot(b.X[i].x, b.X[i].y), z = r - kR;
    double ur = 0.0, dur = 0.0, ut = 0.0;  // u_r, du_r/dθ, u_θ on the mid-surface
    for (int k = 0; k < 8; ++k) {
      const int n = k + 1;
      const double cn = std::cos(n * th[i]), sn = std::sin(n * th[i]), q = mode.u[k];
      if (n % 2 == 1) {  // sin nψ = −sin nθ (ψ = −θ below the surface)
        ur -= q * sn;
        dur -= q * n * cn;
        ut -= q * cn / n;
      } else {  // cos nψ = cos nθ
        ur += q * cn;
        dur -= q * n * sn;
        ut -= q * sn / n;
      }
    }
    const double vr = V * ur, vt = V * (ut - z * (dur - ut) / kR);
    b.v[i] = {vr * std::cos(th[i]) - vt * std::sin(th[i]),
              vr * std::sin(th[i]) + vt * std::cos(th[i])};
    c2[i] = std::cos(2 * th[i]);
    norm_c2 += b.m[i] * c2[i] * c2[i];
    mass += b.m[i];
  }
  auto modal = [&] {
    Vec2 mean;
    for (std::size_t i = 0; i < b.size(); ++i) mean += b.m[i] * (b.x[i] - b.X[i]);
    mean = mean / mass;
    double s = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const Vec2 u = b.x[i] - b.X[i] - mean;
      s += b.m[i] * c2[i] * (u.x * std::cos(th[i]) + u.y * std::sin(th[i]));
    }
    return s / norm_c2;
  };
  WetRingResult r;
  r.fluid = sim.fluid().size();
  r.ring = b.size();
  // Frequency from the times of alternating extrema (parabolic vertex of three samples): a
  // static offset of the mode (the hydrostatic load of a run with gravity) does not bias it.
  // Extrema closer than T/4 to the previous one are noise: the more extreme one is kept.
  const double T = 1.0 / f_guess;
  const int wanted = static_cast<int>(std::lround(2.0 * p.periods)) + 1;
  std::vector<double> ts, as, ext_t, ext_a;
  std::vector<int> ext_sign;
  const auto t0 = std::chrono::steady_clock::now();
  ts.push_back(0.0);
  as.push_back(modal());
  while (static_cast<int>(ext_t.size()) < wanted && sim.time() < 3.0 * p.periods * T) {
    sim.step();
    ts.push_back(sim.time());
    as.push_back(modal());
    for (const Vec2& v : b.v) r.max_wall_speed = std::max(r.max_wall_speed, norm(v));
    const std::size_t k = as.size() - 1;
    if (k < 2) continue;
    const double d1 = as[k - 1] - as[k - 2], d2 = as[k] - as[k - 1];
    if (d1 * d2 >= 0.0) continue;
    const int sign = d1 > 0.0 ? 1 : -1;
    const double t1 = ts[k - 2], t2 = ts[k - 1], t3 = ts[k];
    const double s12 = d1 / (t2 - t1), s23 = d2 / (t3 - t2);  // slopes at the mid-points
    const double te = 0.5 * (t1 + t2) + (0.5 * (t3 - t1)) * s12 / (s12 - s23);
    if (!ext_t.empty() && (ext_sign.back() == sign || te - ext_t.back() < 0.25 * T)) {
      if (ext_sign.back() == sign && sign * (as[k - 1] - ext_a.back()) > 0.0) {
        ext_t.back() = te;
        ext_a.back() = as[k - 1];
      }
      continue;
    }
    ext_t.push_back(te);
    ext_a.push_back(as[k - 1]);
    ext_sign.push_back(sign);
  }
  r.crossings = static_cast<int>(ext_t.size());
  if (r.crossings >= 3) r.f = 0.5 * (r.crossings - 1) / (ext_t.back() - ext_t.front());
  r.amplitude = ext_a.empty() ? 0.0 : std::abs(ext_a.front());
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.steps = sim.steps();
  r.substeps = sim.solid_substeps();
  r.leaked = sim.leaked_particles();
  return r;
}

void print(const char* tag, const WetRingParams& p, const WetRingResult& r) {
  std::printf(
      "[wet ring %s] dx %g c0 %g tank %gx%g water %d g %d rho_s %g p_cav %g: fluid %zu, ring %zu, "
      "f %.4f Hz (dry %.4f, Ritz %.4f), amplitude %.3g m, "
      "%d crossings, %ld steps, %ld solid sub-steps, leaked %ld, max wall speed %.4f m/s, %.1f s\n",
      tag, p.dx, p.c0, 2 * p.half_width, p.depth, p.water, p.gravity, p.rho_s, p.cavitation,
      r.fluid, r.ring, r.f, dry_frequency(2, p.rho_s),
      std::sqrt(wet_omega2(8, true, p.rho_s)) / (2 * kPi), r.amplitude, r.crossings, r.steps,
      r.substeps, r.leaked, r.max_wall_speed, r.seconds);
}

}  // namespace

TEST(WetRing, RitzReferenceLimits) {
  // Heave alone: the high-frequency added mass of a half-immersed circle, ρπa²/2.
  const double a = kR + 0.5 * kH;
  EXPECT_NEAR(added_mass(1, 1), kRhoF * kPi * a * a / 2, 1e-9);
  // Without water the lowest non-zero root is the dry n = 2 frequency.
  EXPECT_NEAR(std::sqrt(wet_omega2(8, false, 1000.0)) / (2 * kPi), dry_frequency(2, 1000.0), 1e-9);
  // The Ritz value has converged in the number of modes.
  const double f6 = std::sqrt(wet_omega2(6, true, 1000.0)),
               f8 = std::sqrt(wet_omega2(8, true, 1000.0));
  EXPECT_NEAR(f6 / f8, 1.0, 2e-3);
  const RitzMode m = wet_mode(8, true, 1000.0);
  std::printf("wet mode x:");
  for (double v : m.x) std::printf(" %.4f", v);
  std::printf("; excitation u:");
  for (double v : m.u) std::printf(" %.4f", v);
  std::printf("\n");
  EXPECT_EQ(m.u[0], 0.0);  // no heave in the excitation
  EXPECT_DOUBLE_EQ(m.u[1], 1.0);
  std::printf("dry %.4f Hz, wet (Ritz, 8 modes) %.4f Hz, 6 modes %.4f Hz; A22 %.4f kg/m\n",
              dry_frequency(2, 1000.0), f8 / (2 * kPi), f6 / (2 * kPi), added_mass(2, 2));
}

// Floating ring, water at hydrostatic rest. With suction (the default cavitation pressure)
// the wet frequency follows potential flow; with the old clamp p* ≥ 0 the water near the
// surface, where the hydrostatic pressure is below the dynamic suction, lets go of the
// ring on every outward stroke, and the frequency rises towards the dry one.
// Measured (docs/validation.md §5): suction −0.3 %, clamp +6.2 % against Ritz at water dx
// 10 mm; at 5 mm suction +2.1 %, clamp +1.3 %: with hydrostatic water the clamp only loses
// the suction of a near-surface layer, whose effect shrinks with dx. The decisive check of
// the clamp is the zero-pressure test below.
TEST(WetRing, FloatingRingFollowsAddedMassOnlyWithSuction) {
  WetRingParams p;
  p.gravity = true;
  p.rho_s = floating_density();
  const double f_ritz = std::sqrt(wet_omega2(8, true, p.rho_s)) / (2 * kPi);
  const WetRingResult suction = run_wet_ring(p);
  print("ci", p, suction);
  p.cavitation = 0.0;
  const WetRingResult clamp = run_wet_ring(p);
  print("ci", p, clamp);
  std::printf("  Ritz %.4f Hz, dry %.4f Hz: suction %+.2f %%, clamp %+.2f %%\n", f_ritz,
              dry_frequency(2, p.rho_s), 100 * (suction.f / f_ritz - 1),
              100 * (clamp.f / f_ritz - 1));
  EXPECT_EQ(suction.leaked, 0);
  EXPECT_NEAR(suction.f / f_ritz, 1.0, 0.03);
  // The clamp lets the near-surface water go: a higher frequency (measured +3.2 % over the
  // suction run with numerics.wall_acceleration = body_mean, +6.5 % with local; the
  // zero-pressure test below is the clamp's clear failure).
  EXPECT_GT(clamp.f / suction.f, 1.015);
}

// Without gravity the water is at zero pressure: the clamp lets the water go on the first
// outward stroke and it never comes back; the ring then vibrates at its dry frequency
// (measured +1.4 % above thin-ring theory; the dry SPH ring is +1.0 %). With suction it
// stays wet (−12 % below dry; potential flow −19 %: at zero ambient pressure the SPH
// contact carries only ~2/3 of the added mass, an open problem also seen on an oscillating
// disc in open water, docs/validation.md §5).
TEST(WetRing, ClampLetsGoOfTheRingAtZeroAmbientPressure) {
  WetRingParams p;
  p.rho_s = floating_density();
  const double f_dry = dry_frequency(2, p.rho_s);
  p.cavitation = 0.0;
  const WetRingResult clamp = run_wet_ring(p);
  print("ci", p, clamp);
  std::printf("  dry %.4f Hz: clamp %+.2f %%\n", f_dry, 100 * (clamp.f / f_dry - 1));
  EXPECT_NEAR(clamp.f / f_dry, 1.0, 0.03);
}

TEST(WetRing, DISABLED_OneRun) {
  auto env = [](const char* k, double d) {
    const char* v = std::getenv(k);
    return v ? std::atof(v) : d;
  };
  WetRingParams p;
  p.rho_s = floating_density();
  p.dx = env("SLAMSPH_WET_RING_DX", p.dx);
  p.c0 = env("SLAMSPH_WET_RING_C0", p.c0);
  p.half_width = env("SLAMSPH_WET_RING_HALF_WIDTH", p.half_width);
  p.depth = env("SLAMSPH_WET_RING_DEPTH", p.depth);
  p.periods = env("SLAMSPH_WET_RING_PERIODS", p.periods);
  p.cavitation = env("SLAMSPH_WET_RING_CAVITATION", p.cavitation);
  p.water = env("SLAMSPH_WET_RING_WATER", 1.0) != 0.0;
  p.gravity = env("SLAMSPH_WET_RING_GRAVITY", 0.0) != 0.0;
  p.g = env("SLAMSPH_WET_RING_G", p.g);
  p.rho_s = env("SLAMSPH_WET_RING_RHO_S", p.rho_s);
  p.amplitude = env("SLAMSPH_WET_RING_AMPLITUDE", p.amplitude);
  p.hydrostatic_correction = env("SLAMSPH_WET_RING_HYDROSTATIC_CORRECTION", 1.0) != 0.0;
  const WetRingResult r = run_wet_ring(p);
  print("run", p, r);
  std::printf("csv,%g,%g,%g,%g,%d,%d,%g,%zu,%zu,%.6f,%.6f,%.6f,%d,%ld,%ld,%ld,%.5f,%.1f\n", p.dx,
              p.c0, p.half_width, p.depth, p.water, p.gravity, p.cavitation, r.fluid, r.ring, r.f,
              dry_frequency(2, p.rho_s), std::sqrt(wet_omega2(8, true, p.rho_s)) / (2 * kPi),
              r.crossings, r.steps, r.substeps, r.leaked, r.max_wall_speed, r.seconds);
}
