// Reference curves and validation metrics from docs/references.md:
//  §1/§11 cylinder water entry at constant speed: slamming coefficient Cs = F / (ρ V² R),
//     submergence s = V t. 2D theories: von Kármán (1929) with the exact circle
//     Cs = π(1 − s/R); Wagner (1932) with the parabola, Cs = 2π; Wagner with the exact
//     circle; the modified Logvinovich model (Korobkin 2004). 3D experimental context:
//     Campbell & Weynberg (1980, as in DNV-RP-C205) Cs = 5.15/(1 + 19 s/D) + 0.55 s/D.
//  §2 dam-break surge front Z = x/a against T = t·sqrt(2g/a): Martin & Moyce (1952) and
//     Koshizuka & Oka (1996) tables.
//  §5 cantilever plate (Gray, Monaghan & Swift 2001): thin-plate frequency and tip amplitude.
//  §6 elastic gate (Antoci, Gallati & Sibilla 2007): experimental tip-displacement peaks
//     (approximate, [L] in the README).
// Metrics compare a simulated time series with these references.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace slamsph {

// ---- §1 cylinder water entry ---------------------------------------------------------
// Wagner = the parabola approximation (Cs = 2π); WagnerCircle and ModifiedLogvinovich use
// the exact circle (formulas and derivation in reference_curves.cpp and docs/validation.md).
enum class SlammingTheory {
  CampbellWeynberg,
  VonKarman,
  Wagner,
  WagnerCircle,
  ModifiedLogvinovich
};
const char* slamming_theory_name(SlammingTheory th);  // "Campbell-Weynberg", ...
// true for the 2D potential-flow theories; false for Campbell–Weynberg (a fit to
// experiments on finite cylinders: 3D end effects and air).
bool slamming_theory_is_2d(SlammingTheory th);
// Every theory, in the order above.
std::vector<SlammingTheory> all_slamming_theories();

// Cs(s/D) of a theory. von Kármán is clamped at 0 beyond s/D = 0.5 (it is not valid there);
// WagnerCircle and ModifiedLogvinovich are NaN beyond full wetting, s/R > 1 − 2/π (s/D > 0.1817).
double slamming_coefficient(SlammingTheory th, double s_over_d);

// Wagner's condition for the exact circle (generalised Wagner condition
// ∫₀^{π/2} f(c sin θ) dθ = (π/2) s with f = R − sqrt(R² − x²)): s/R = 1 − (2/π) E(k),
// k = c/R the wetted half-width; returns k for 0 ≤ s/R ≤ 1 − 2/π, NaN beyond.
double wagner_circle_half_width(double s_over_r);
// Largest s/R of the exact-circle Wagner solution (full wetting, k = 1): 1 − 2/π.
double wagner_circle_max_s_over_r();
// Modified Logvinovich model (Korobkin 2004) for the circle at constant speed: the zero of
// the body pressure, x0/c (0 if the pressure is nowhere positive).
double logvinovich_circle_pressure_zero(double s_over_r);
// F = Cs ρ V² R [N/m].
double slamming_force(SlammingTheory th, double s_over_d, double density, double velocity,
                      double radius);

// Parameters of a constant-speed entry. t_contact: time the cylinder touches the free
// surface (s = V (t − t_contact)).
struct SlammingCase {
  double density = 1000.0;  // [kg/m^3]
  double velocity = 0.0;    // entry speed V > 0 [m/s]
  double radius = 0.0;      // R [m], D = 2R
  double t_contact = 0.0;   // [s]
};

// ---- §2 dam break ---------------------------------------------------------------------
struct FrontTable {
  std::string name;
  std::vector<double> T;  // t sqrt(2g/a)
  std::vector<double> Z;  // x/a
};
FrontTable martin_moyce_1952();
FrontTable koshizuka_oka_1996();

// ---- §5 cantilever plate --------------------------------------------------------------
// Thin-plate first-mode angular frequency ω² = E H² k⁴ / (12 ρ (1 − ν²)), kL = 1.875,
// L the free length [rad/s].
double cantilever_omega(double youngs, double density, double poisson, double thickness,
                        double free_length);
// Tip amplitude ≈ V_f c0 / ω with c0 = sqrt(K/ρ), K = E / (3(1 − 2ν)) [m].
double cantilever_tip_amplitude(double vf, double youngs, double density, double poisson,
                                double omega);

// ---- §6 elastic gate ------------------------------------------------------------------
struct GateExperiment {
  double peak_dx = 0.040;    // horizontal tip displacement peak [m] (approximate)
  double t_peak_min = 0.15;  // time window of that peak [s]
  double t_peak_max = 0.20;
  double peak_dy_min = 0.012;  // vertical tip displacement peak range [m]
  double peak_dy_max = 0.014;
};
GateExperiment antoci_2007_gate();

// ---- metrics --------------------------------------------------------------------------
struct Peak {
  double time = 0.0;
  double value = 0.0;
  std::size_t index = 0;
};
// Largest value (absolute = false) or largest |value| (absolute = true, the signed value
// is returned) of v(t); NaNs are skipped. Throws std::invalid_argument if the series is
// empty, all NaN, or t and v differ in size.
Peak find_peak(const std::vector<double>& t, const std::vector<double>& v, bool absolute = false);

// Signed relative error (simulated − reference) / |reference|.
double relative_error(double simulated, double reference);

// Linear interpolation of v(t) at tq; t strictly increasing. NaN outside [t.front(), t.back()].
double interpolate(const std::vector<double>& t, const std::vector<double>& v, double tq);

struct SeriesError {
  double rms = 0.0;         // RMS of the relative errors
  double max_abs = 0.0;     // largest |relative error|
  double at = 0.0;          // abscissa (s/D or T) of that largest error
  std::size_t samples = 0;  // comparison points used (0: no overlap; rms/max are NaN)
};

// Relative error of a simulated force history F(t) against a theory on s/D in
// [s_lo, s_hi], compared at `samples` uniformly spaced s/D values (simulated F linearly
// interpolated at t = t_contact + (s/D) D / V). Points the simulation does not reach are
// skipped.
SeriesError slamming_history_error(const std::vector<double>& t, const std::vector<double>& force,
                                   SlammingTheory th, const SlammingCase& c, double s_lo = 0.05,
                                   double s_hi = 0.3, int samples = 51);

// Relative error of a simulated surge front x(t) (measured from the wall the column rests
// against) against a table: the simulated Z = x/a is interpolated at the table's T values
// with T ≤ T_max (t = T / sqrt(2g/a)); table points outside the simulated time are skipped.
// `time_shift` (in T units) compares the simulated Z(T - shift) with the table's Z(T): a
// simulation that starts `shift` earlier than the experiment's clock (whose gate or
// diaphragm took time to clear the column).
SeriesError front_error(const std::vector<double>& t, const std::vector<double>& front_x,
                        double column_width, double gravity, const FrontTable& table, double T_max,
                        double time_shift = 0.0);

struct ShiftedFrontError {
  double shift = 0.0;  // the delay in T units (0 ... max_shift, steps of 0.01)
  SeriesError error;   // front_error at that delay
};

// The start-up delay that minimises the largest front error (a diagnostic: the issue's
// targets use shift 0). Table points with T - shift < 0 are skipped.
ShiftedFrontError best_front_shift(const std::vector<double>& t, const std::vector<double>& front_x,
                                   double column_width, double gravity, const FrontTable& table,
                                   double T_max, double max_shift = 0.5);

}  // namespace slamsph
