#include "app/run_metrics.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "io/case_file.h"
#include "io/csv_writer.h"

namespace slamsph {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The first string or number value of "key" in a JSON text (summary.json is flat enough).
std::string json_value(const std::string& s, const std::string& key) {
  const std::size_t at = s.find("\"" + key + "\":");
  if (at == std::string::npos) return "";
  std::size_t b = s.find_first_not_of(" \t\n", at + key.size() + 3);
  if (b == std::string::npos) return "";
  if (s[b] == '"') return s.substr(b + 1, s.find('"', b + 1) - b - 1);
  const std::size_t e = s.find_first_of(",}\n", b);
  return s.substr(b, e - b);
}

CaseConfig resolved_case(const std::string& dir) {
  const std::string resolved = dir + "/case.resolved.toml";
  if (!std::filesystem::exists(resolved))
    throw InputError(dir + ": not a results folder (no case.resolved.toml)");
  return load_case(resolved);
}

std::string pick_body(const CaseConfig& cfg, const std::string& dir, const std::string& body) {
  if (!body.empty()) {
    for (const BodyConfig& b : cfg.bodies)
      if (b.name == body) return body;
    throw InputError(dir + ": the case has no body '" + body + "'");
  }
  for (const BodyConfig& b : cfg.bodies)
    if (b.kind != "rigid_fixed") return b.name;
  return cfg.bodies.empty() ? "" : cfg.bodies.front().name;
}

}  // namespace

std::string studied_body(const std::string& dir, const std::string& body) {
  return pick_body(resolved_case(dir), dir, body);
}

std::string metric_text(double v) {
  if (std::isnan(v)) return "n/a";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.5g", v);
  return buf;
}

RunMetrics read_run_metrics(const std::string& dir, const std::string& body) {
  const CaseConfig cfg = resolved_case(dir);
  RunMetrics m;
  m.dir = dir;
  m.body = pick_body(cfg, dir, body);
  m.peak_force = m.peak_force_y = m.peak_time = m.impulse_y = kNaN;
  m.peak_strain = m.peak_strain_time = m.peak_strain_x = m.peak_strain_y = kNaN;
  m.keel_deflection = m.wall_seconds = kNaN;

  const std::string summary = read_text(dir + "/summary.json");
  m.status = summary.empty() ? "unknown" : json_value(summary, "status");
  if (m.status.empty()) m.status = "unknown";
  if (const std::string w = json_value(summary, "wall_seconds"); !w.empty())
    m.wall_seconds = std::strtod(w.c_str(), nullptr);

  const std::string forces = dir + "/forces.csv";
  if (!m.body.empty() && std::filesystem::exists(forces)) {
    const CsvTable t = read_csv(forces);
    const int cx = t.find(m.body + " Fx [N/m]"), cy = t.find(m.body + " Fy [N/m]");
    if (cx > 0 && cy > 0 && t.rows() > 0) {
      const auto& time = t.columns[0];
      const auto& fx = t.columns[static_cast<std::size_t>(cx)];
      const auto& fy = t.columns[static_cast<std::size_t>(cy)];
      double best = -1.0;
      m.impulse_y = 0.0;
      for (std::size_t i = 0; i < t.rows(); ++i) {
        const double f = std::hypot(fx[i], fy[i]);
        if (f > best) best = f, m.peak_force = f, m.peak_force_y = fy[i], m.peak_time = time[i];
        if (i > 0) m.impulse_y += 0.5 * (time[i] - time[i - 1]) * (fy[i] + fy[i - 1]);
      }
    }
  }

  const std::string probes = dir + "/probes.csv";
  std::string strain_probe, keel_probe;
  for (const ProbeConfig& p : cfg.output.probes) {
    if (p.body != m.body) continue;
    if (p.kind == "body_max_strain" && strain_probe.empty()) strain_probe = p.name;
    if (p.kind == "keel_deflection" && keel_probe.empty()) keel_probe = p.name;
  }
  if ((!strain_probe.empty() || !keel_probe.empty()) && std::filesystem::exists(probes)) {
    const CsvTable t = read_csv(probes);
    const int cs = strain_probe.empty() ? -1 : t.find(strain_probe + " [-]");
    const int cX = strain_probe.empty() ? -1 : t.find(strain_probe + "_X [m]");
    const int cY = strain_probe.empty() ? -1 : t.find(strain_probe + "_Y [m]");
    if (cs > 0 && cX > 0 && cY > 0) {
      double best = -1.0;
      for (std::size_t i = 0; i < t.rows(); ++i) {
        const double e = t.columns[static_cast<std::size_t>(cs)][i];
        if (e > best) {
          best = e;
          m.peak_strain = e;
          m.peak_strain_time = t.columns[0][i];
          m.peak_strain_x = t.columns[static_cast<std::size_t>(cX)][i];
          m.peak_strain_y = t.columns[static_cast<std::size_t>(cY)][i];
        }
      }
    }
    const int ck = keel_probe.empty() ? -1 : t.find(keel_probe + " [m]");
    if (ck > 0) {
      double best = -1.0;
      for (double v : t.columns[static_cast<std::size_t>(ck)])
        if (std::abs(v) > best) best = std::abs(v), m.keel_deflection = v;
    }
  }
  return m;
}

}  // namespace slamsph
