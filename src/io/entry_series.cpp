#include "io/entry_series.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "io/csv_writer.h"
#include "io/reference_curves.h"

namespace slamsph {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

EntrySeries entry_series(const std::vector<double>& t_force, const std::vector<double>& force,
                         const std::vector<double>& t_body, const std::vector<double>& com_y,
                         const std::vector<double>& vel_y, double surface_y, double radius,
                         double density) {
  if (t_body.size() < 2 || com_y.size() != t_body.size() || vel_y.size() != t_body.size())
    throw std::invalid_argument("entry series: the body path needs at least two samples");
  if (t_force.size() != force.size())
    throw std::invalid_argument("entry series: force times and values differ in length");
  EntrySeries s;
  s.radius = radius;
  s.density = density;
  const std::size_t n = t_body.size();
  std::vector<double> depth(n);  // s(t) of the path samples
  for (std::size_t k = 0; k < n; ++k) depth[k] = surface_y - (com_y[k] - radius);
  if (depth[0] >= 0.0) {
    // Started touching or below: extrapolate back along the initial speed.
    if (!(-vel_y[0] > 0.0))
      throw std::invalid_argument("entry series: the body starts submerged and does not move down");
    s.t0 = t_body[0] - depth[0] / -vel_y[0];
    s.t0_from_path = depth[0] == 0.0;
  } else {
    bool found = false;
    for (std::size_t k = 0; k + 1 < n && !found; ++k)
      if (depth[k] < 0.0 && depth[k + 1] >= 0.0) {
        s.t0 =
            t_body[k] + (0.0 - depth[k]) * (t_body[k + 1] - t_body[k]) / (depth[k + 1] - depth[k]);
        found = true;
      }
    if (!found)
      throw std::invalid_argument("entry series: the body never reaches the free surface");
  }
  const std::vector<double> speed = [&] {
    std::vector<double> v(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = -vel_y[k];
    return v;
  }();
  s.speed_at_contact = s.t0 < t_body[0] ? speed[0] : interpolate(t_body, speed, s.t0);
  const double d = 2.0 * radius;
  for (std::size_t k = 0; k < t_force.size(); ++k) {
    const double tk = t_force[k];
    if (tk < t_body.front() || tk > t_body.back()) continue;
    const double sk = interpolate(t_body, depth, tk), vk = interpolate(t_body, speed, tk);
    s.t.push_back(tk - s.t0);
    s.sd.push_back(sk / d);
    s.v.push_back(vk);
    s.f.push_back(force[k]);
    s.cs.push_back(vk > 0.0 ? force[k] / (density * vk * vk * radius) : kNaN);
  }
  return s;
}

bool load_entry_series(const std::string& dir, const std::string& body,
                       const std::string& force_column, double surface_y, double radius,
                       double density, double velocity, double t_contact, EntrySeries& out,
                       std::string& message) {
  namespace fs = std::filesystem;
  const std::string fpath = dir + "/forces.csv";
  if (!fs::exists(fpath)) {
    message = "no " + fpath;
    return false;
  }
  const CsvTable f = read_csv(fpath);
  const std::string want = force_column.empty() ? body + " Fy [N/m]" : force_column;
  const int col = f.find(want);
  if (col < 1) {
    std::string cols;
    for (const std::string& h : f.headers) cols += (cols.empty() ? "" : ", ") + h;
    message = "column \"" + want + "\" not in " + fpath + " (columns: " + cols + ")";
    return false;
  }
  const std::vector<double>& time = f.columns[0];
  const std::vector<double>& force = f.columns[static_cast<std::size_t>(col)];
  const std::string bpath = dir + "/bodies.csv";
  if (std::isfinite(surface_y) && !body.empty() && fs::exists(bpath)) {
    const CsvTable b = read_csv(bpath);
    const int cy = b.find(body + " com_y [m]"), cv = b.find(body + " vel_y [m/s]");
    if (cy > 0 && cv > 0 && b.rows() >= 2) {
      try {
        out = entry_series(time, force, b.columns[0], b.columns[static_cast<std::size_t>(cy)],
                           b.columns[static_cast<std::size_t>(cv)], surface_y, radius, density);
        return true;
      } catch (const std::invalid_argument& e) {
        message = bpath + ": " + e.what();
        return false;
      }
    }
  }
  if (!(velocity > 0.0) || time.empty()) {
    message = "no body path in " + bpath + " and no entry speed";
    return false;
  }
  // Constant speed: a straight path through the surface at t_contact.
  const double y_touch = 0.0;
  const std::vector<double> tb{std::min(time.front(), t_contact),
                               std::max(time.back(), t_contact + 1e-9)};
  const std::vector<double> yb{y_touch + radius + velocity * (t_contact - tb[0]),
                               y_touch + radius - velocity * (tb[1] - t_contact)};
  out = entry_series(time, force, tb, yb, {-velocity, -velocity}, y_touch, radius, density);
  return true;
}

WindowMean mean_cs(const EntrySeries& s, double lo, double hi) {
  WindowMean m;
  double acc = 0.0;
  for (std::size_t k = 0; k < s.sd.size(); ++k)
    if (s.sd[k] >= lo && s.sd[k] <= hi && std::isfinite(s.cs[k])) {
      acc += s.cs[k];
      ++m.samples;
    }
  m.value = m.samples ? acc / double(m.samples) : kNaN;
  return m;
}

void write_entry_series(const EntrySeries& s, const std::string& path) {
  std::vector<std::string> headers{"t - t0 [s]", "s/D [-]", "V [m/s]", "F [N/m]", "Cs [-]"};
  const std::vector<SlammingTheory> th = all_slamming_theories();
  for (SlammingTheory t : th) headers.push_back(std::string(slamming_theory_name(t)) + " Cs [-]");
  for (SlammingTheory t : th) headers.push_back(std::string(slamming_theory_name(t)) + " F [N/m]");
  CsvWriter w(path, headers);
  std::vector<double> row(headers.size());
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    row[0] = s.t[k], row[1] = s.sd[k], row[2] = s.v[k], row[3] = s.f[k], row[4] = s.cs[k];
    for (std::size_t j = 0; j < th.size(); ++j) {
      const double c = s.sd[k] >= 0.0 ? slamming_coefficient(th[j], s.sd[k]) : kNaN;
      row[5 + j] = c;
      row[5 + th.size() + j] = c * s.density * s.v[k] * s.v[k] * s.radius;
    }
    w.row(row);
  }
}

}  // namespace slamsph
