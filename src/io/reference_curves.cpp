// Reference curves and metrics; sources in reference_curves.h and the validation README.
#include "io/reference_curves.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace slamsph {

const char* slamming_theory_name(SlammingTheory th) {
  switch (th) {
    case SlammingTheory::CampbellWeynberg:
      return "Campbell-Weynberg";
    case SlammingTheory::VonKarman:
      return "von Karman";
    case SlammingTheory::Wagner:
      return "Wagner";
    case SlammingTheory::WagnerCircle:
      return "Wagner (exact circle)";
    case SlammingTheory::ModifiedLogvinovich:
      return "modified Logvinovich";
  }
  return "?";
}

bool slamming_theory_is_2d(SlammingTheory th) {
  return th != SlammingTheory::CampbellWeynberg;
}

std::vector<SlammingTheory> all_slamming_theories() {
  return {SlammingTheory::CampbellWeynberg, SlammingTheory::VonKarman, SlammingTheory::Wagner,
          SlammingTheory::WagnerCircle, SlammingTheory::ModifiedLogvinovich};
}

double wagner_circle_max_s_over_r() {
  return 1.0 - 2.0 / std::numbers::pi;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Exact-circle Wagner state at submergence s/R: k = c/R and the expansion rate of the
// wetted region, a = (dc/dt)/V = 1/(ds/dc). From s/R = 1 − (2/π)E(k) and
// dE/dk = (E − K)/k: ds/dc = (2/π)(K − E)/k.
struct WagnerCircleState {
  double k = kNaN;
  double a = kNaN;  // (dc/dt)/V
  double K = kNaN, E = kNaN;
};

WagnerCircleState wagner_circle_state(double s_over_r) {
  WagnerCircleState st;
  if (!(s_over_r > 0.0) || s_over_r > wagner_circle_max_s_over_r()) return st;
  // s/R(k) increases monotonically from 0 (k = 0) to 1 − 2/π (k = 1): bisection.
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double s = 1.0 - (2.0 / std::numbers::pi) * std::comp_ellint_2(mid);
    (s < s_over_r ? lo : hi) = mid;
  }
  st.k = 0.5 * (lo + hi);
  if (st.k >= 1.0) st.k = std::nextafter(1.0, 0.0);
  st.K = std::comp_ellint_1(st.k);
  st.E = std::comp_ellint_2(st.k);
  st.a = std::numbers::pi * st.k / (2.0 * (st.K - st.E));
  return st;
}

// Modified Logvinovich model (Korobkin 2004, J. Eng. Math. 48:217; Tassin et al. 2010).
// The body-surface potential is the Wagner (flat-plate) potential continued to the body
// surface y = f(x) − h: φ_b = −ḣ[sqrt(c² − x²) + f(x) − h]. Bernoulli on the moving
// surface with the kinematic condition gives, at constant speed ḣ = V,
//   p/ρ = V c ċ / sqrt(c² − x²) − V²/2 − (V²/2) x² / ((c² − x²)(1 + f'²)),
// and for the circle 1 + f'² = R²/(R² − x²). The pressure is integrated where it is
// positive, |x| < x0. With ξ = x/c and a = ċ/V, p = 0 where a sqrt(1 − ξ²) = (1 − k²ξ⁴)/2.
double logvinovich_zero(const WagnerCircleState& st) {
  const double k2 = st.k * st.k;
  auto g = [&](double xi) {
    return st.a * std::sqrt(1.0 - xi * xi) - 0.5 * (1.0 - k2 * xi * xi * xi * xi);
  };
  if (!(g(0.0) > 0.0)) return 0.0;  // no positive pressure anywhere
  double lo = 0.0, hi = 1.0;        // g(1) = −(1 − k²)/2 < 0
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) > 0.0 ? lo : hi) = mid;
  }
  return lo;
}

// Cs = (2/R) ∫₀^{x0} p/(ρV²) dx in closed form (x = c sin θ for the first term;
// x²(R² − x²)/((c² − x²)R²) = (c²/(c² − x²) − 1)(1 − x²/R²) for the last):
//   Cs = 2[ k a asin ξ0 − k ξ0/2 − ( k(1 − k²) atanh ξ0 − k ξ0 (1 − k²) + k³ ξ0³/3 )/2 ].
double logvinovich_cs(const WagnerCircleState& st) {
  const double xi = logvinovich_zero(st);
  if (xi <= 0.0) return 0.0;
  const double k = st.k, k2 = k * k;
  return 2.0 * (k * st.a * std::asin(xi) - 0.5 * k * xi -
                0.5 * (k * (1.0 - k2) * std::atanh(xi) - k * xi * (1.0 - k2) +
                       k2 * k * xi * xi * xi / 3.0));
}

}  // namespace

double wagner_circle_half_width(double s_over_r) {
  if (s_over_r == 0.0) return 0.0;
  return wagner_circle_state(s_over_r).k;
}

double logvinovich_circle_pressure_zero(double s_over_r) {
  const WagnerCircleState st = wagner_circle_state(s_over_r);
  return std::isnan(st.k) ? kNaN : logvinovich_zero(st);
}

double slamming_coefficient(SlammingTheory th, double s_over_d) {
  constexpr double pi = std::numbers::pi;
  const double s_over_r = 2.0 * s_over_d;
  switch (th) {
    case SlammingTheory::CampbellWeynberg:
      return 5.15 / (1.0 + 19.0 * s_over_d) + 0.55 * s_over_d;
    case SlammingTheory::VonKarman:  // added mass ρπc²/2 with the geometric c² = 2Rs − s²
      return std::max(0.0, pi * (1.0 - s_over_r));
    case SlammingTheory::Wagner:
      return 2.0 * pi;
    case SlammingTheory::WagnerCircle: {  // F = d/dt(ρπc²V/2) = ρπ c ċ V
      if (s_over_r == 0.0) return 2.0 * pi;
      const WagnerCircleState st = wagner_circle_state(s_over_r);
      return pi * st.k * st.a;  // = π² k² / (2(K − E)); NaN beyond full wetting
    }
    case SlammingTheory::ModifiedLogvinovich: {
      if (s_over_r == 0.0) return 2.0 * pi;  // the Wagner limit
      const WagnerCircleState st = wagner_circle_state(s_over_r);
      return std::isnan(st.k) ? kNaN : logvinovich_cs(st);
    }
  }
  return kNaN;
}

double slamming_force(SlammingTheory th, double s_over_d, double density, double velocity,
                      double radius) {
  return slamming_coefficient(th, s_over_d) * density * velocity * velocity * radius;
}

FrontTable martin_moyce_1952() {
  return {"Martin & Moyce 1952",
          {0.41, 0.84, 1.19, 1.43, 1.63, 1.82, 1.97, 2.20, 2.32, 2.50, 2.64, 2.82, 2.96},
          {1.11, 1.23, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67}};
}

FrontTable koshizuka_oka_1996() {
  return {"Koshizuka & Oka 1996",
          {0, 0.381, 0.769, 1.153, 1.537, 1.935, 2.323, 2.719, 3.096},
          {1, 1.111, 1.252, 1.505, 1.892, 2.241, 2.615, 3.003, 3.624}};
}

double cantilever_omega(double youngs, double density, double poisson, double thickness,
                        double free_length) {
  const double k = 1.875 / free_length;
  const double k2 = k * k;
  return std::sqrt(youngs * thickness * thickness * k2 * k2 /
                   (12.0 * density * (1.0 - poisson * poisson)));
}

double cantilever_tip_amplitude(double vf, double youngs, double density, double poisson,
                                double omega) {
  const double bulk = youngs / (3.0 * (1.0 - 2.0 * poisson));
  return vf * std::sqrt(bulk / density) / omega;
}

GateExperiment antoci_2007_gate() {
  return {};
}

Peak find_peak(const std::vector<double>& t, const std::vector<double>& v, bool absolute) {
  if (t.size() != v.size()) throw std::invalid_argument("find_peak: t and v differ in size");
  Peak p;
  bool found = false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::isnan(v[i])) continue;
    const double key = absolute ? std::abs(v[i]) : v[i];
    const double best = absolute ? std::abs(p.value) : p.value;
    if (!found || key > best) {
      p = {t[i], v[i], i};
      found = true;
    }
  }
  if (!found) throw std::invalid_argument("find_peak: empty or all-NaN series");
  return p;
}

double relative_error(double simulated, double reference) {
  return (simulated - reference) / std::abs(reference);
}

double interpolate(const std::vector<double>& t, const std::vector<double>& v, double tq) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (t.empty() || t.size() != v.size() || !(tq >= t.front()) || !(tq <= t.back())) return nan;
  const auto it = std::lower_bound(t.begin(), t.end(), tq);
  const std::size_t j = static_cast<std::size_t>(it - t.begin());
  if (t[j] == tq) return v[j];
  const std::size_t i = j - 1;  // j >= 1 because tq > t.front()
  const double w = (tq - t[i]) / (t[j] - t[i]);
  return v[i] + w * (v[j] - v[i]);
}

namespace {
struct ErrorAccumulator {
  double sum2 = 0.0;
  SeriesError e;
  void add(double at, double rel) {
    sum2 += rel * rel;
    if (e.samples == 0 || std::abs(rel) > e.max_abs) {
      e.max_abs = std::abs(rel);
      e.at = at;
    }
    ++e.samples;
  }
  SeriesError result() const {
    SeriesError r = e;
    if (r.samples == 0) {
      r.rms = r.max_abs = r.at = std::numeric_limits<double>::quiet_NaN();
    } else {
      r.rms = std::sqrt(sum2 / static_cast<double>(r.samples));
    }
    return r;
  }
};
}  // namespace

SeriesError slamming_history_error(const std::vector<double>& t, const std::vector<double>& force,
                                   SlammingTheory th, const SlammingCase& c, double s_lo,
                                   double s_hi, int samples) {
  if (!(c.velocity > 0.0) || !(c.radius > 0.0))
    throw std::invalid_argument("slamming_history_error: velocity and radius must be > 0");
  if (samples < 2) throw std::invalid_argument("slamming_history_error: samples < 2");
  const double d = 2.0 * c.radius;
  ErrorAccumulator acc;
  for (int k = 0; k < samples; ++k) {
    const double sd = s_lo + (s_hi - s_lo) * k / (samples - 1);
    const double tq = c.t_contact + sd * d / c.velocity;
    const double f = interpolate(t, force, tq);
    if (std::isnan(f)) continue;
    const double ref = slamming_force(th, sd, c.density, c.velocity, c.radius);
    acc.add(sd, relative_error(f, ref));
  }
  return acc.result();
}

SeriesError front_error(const std::vector<double>& t, const std::vector<double>& front_x,
                        double column_width, double gravity, const FrontTable& table, double T_max,
                        double time_shift) {
  if (!(column_width > 0.0) || !(gravity > 0.0))
    throw std::invalid_argument("front_error: column width and gravity must be > 0");
  const double scale = std::sqrt(2.0 * gravity / column_width);  // T = t * scale
  ErrorAccumulator acc;
  for (std::size_t k = 0; k < table.T.size(); ++k) {
    if (table.T[k] > T_max || table.T[k] - time_shift < 0.0) continue;
    const double x = interpolate(t, front_x, (table.T[k] - time_shift) / scale);
    if (std::isnan(x)) continue;
    acc.add(table.T[k], relative_error(x / column_width, table.Z[k]));
  }
  return acc.result();
}

ShiftedFrontError best_front_shift(const std::vector<double>& t, const std::vector<double>& front_x,
                                   double column_width, double gravity, const FrontTable& table,
                                   double T_max, double max_shift) {
  ShiftedFrontError best;
  best.error = front_error(t, front_x, column_width, gravity, table, T_max, 0.0);
  const int steps = static_cast<int>(std::round(max_shift / 0.01));
  for (int k = 1; k <= steps; ++k) {
    const double shift = 0.01 * k;
    const SeriesError e = front_error(t, front_x, column_width, gravity, table, T_max, shift);
    if (e.samples > 0 && e.max_abs < best.error.max_abs) best = {shift, e};
  }
  return best;
}

}  // namespace slamsph
