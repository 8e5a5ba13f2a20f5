// The slamming series of a cylinder entering water (issue 9; docs/validation.md §3): the
// force history F(t) of a body that moves freely (or at constant speed) expressed as the
// slamming coefficient Cs = F / (ρ V(t)² R) against the submergence s(t)/D, with the
// body's actual speed V(t) and its lowest point's actual depth s(t) below the still free
// surface. t0 is the geometric contact time s(t0) = 0, not the start of the run: the
// kernel-range force begins before it. This is what the constant-speed theories of
// reference_curves.h can be compared with, like with like.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace slamsph {

struct EntrySeries {
  double t0 = 0.0;           // geometric contact time [s]
  bool t0_from_path = true;  // false: the body started below the surface; t0 extrapolated
  double speed_at_contact = 0.0;
  double radius = 0.0, density = 0.0;
  // One entry per force sample inside the body path's time range:
  std::vector<double> t;   // time since contact t − t0 [s]
  std::vector<double> sd;  // s/D, s = y_surface − (y_c − R) (> 0: submerged)
  std::vector<double> v;   // V = −v_y [m/s] (downwards positive)
  std::vector<double> f;   // vertical force on the body [N/m]
  std::vector<double> cs;  // F / (ρ V² R)
};

// Builds the series from the force samples (t_force, force) and the body path (t_body,
// com_y, vel_y), both time-ordered; V and the centre are interpolated linearly at the force
// times. The lowest point is com_y − R (exact for a rigid disc; an elastic disc's keel
// moves by its deformation, which the case reports separately). Throws
// std::invalid_argument if the path has fewer than two samples or the body never moves
// down (no contact time can be defined).
EntrySeries entry_series(const std::vector<double>& t_force, const std::vector<double>& force,
                         const std::vector<double>& t_body, const std::vector<double>& com_y,
                         const std::vector<double>& vel_y, double surface_y, double radius,
                         double density);

// The series of a finished run in `dir`: the force column "<body> Fy [N/m]" (or
// `force_column` if not empty) of forces.csv and, when bodies.csv has "<body> com_y [m]" and
// "<body> vel_y [m/s]" and surface_y is finite, the body's actual path. Without a path the
// body is taken at constant speed `velocity` touching the surface at `t_contact`.
// Returns false with a message naming the file and the missing column.
bool load_entry_series(const std::string& dir, const std::string& body,
                       const std::string& force_column, double surface_y, double radius,
                       double density, double velocity, double t_contact, EntrySeries& out,
                       std::string& message);

// Mean of Cs over the samples with s/D in [lo, hi] (NaN if none) and the number used.
struct WindowMean {
  double value = 0.0;
  std::size_t samples = 0;
};
WindowMean mean_cs(const EntrySeries& s, double lo, double hi);

// Writes the series as CSV (slamming_cs.csv): t − t0, s/D, V, F, Cs and, per theory of
// reference_curves.h, its Cs at the same s/D (empty where the theory is not defined) and
// its force ρ V(t)² R Cs_ref with the actual speed.
void write_entry_series(const EntrySeries& s, const std::string& path);

}  // namespace slamsph
