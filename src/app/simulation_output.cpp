// Simulation::run: the time loop with every output a user reads (VTK series, CSV with
// units, summary.json, progress line, resolved case) and the divergence stop.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "app/simulation.h"
#include "app/validation_report.h"
#include "core/error.h"
#include "io/case_file.h"
#include "io/csv_writer.h"
#include "io/json_writer.h"
#include "io/progress_line.h"
#include "io/vtk_writer.h"
#include "solid/body_dynamics.h"

namespace slamsph {

namespace {

std::vector<double> vec_values(const std::vector<Vec2>& v) {
  std::vector<double> out(2 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[2 * i] = v[i].x, out[2 * i + 1] = v[i].y;
  return out;
}

}  // namespace

void Simulation::write_frame(VtkSeries& vtk) const {
  if (fluid_.size() > 0) {
    std::vector<PointField> ff;
    ff.push_back({"velocity", "m/s", 2, vec_values(fluid_.v), {}});
    ff.push_back({"pressure", "Pa", 1, fluid_.p, {}});
    ff.push_back({"density", "kg/m^3", 1, fluid_.rho, {}});
    std::vector<double> id(fluid_.size()), set(fluid_.size(), 0.0);
    for (std::size_t i = 0; i < fluid_.size(); ++i) id[i] = static_cast<double>(fluid_.id[i]);
    ff.push_back({"id", "-", 1, id, {}});
    ff.push_back({"set", "-", 1, set, {}});
    std::vector<double> crossed(fluid_.crossed.begin(), fluid_.crossed.end());
    ff.push_back({"crossed_solid", "-", 1, crossed, {}});  // leak counter flag (1 = crossed)
    vtk.write(time_, "fluid", fluid_.x, ff);
  }
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const SolidBody& body = bodies_[b];
    std::vector<PointField> bf;
    for (SolidField& sf : solid_output_fields(body))
      bf.push_back({sf.name, sf.unit, sf.components, std::move(sf.values), {}});
    std::vector<double> pv(body.size()), id(body.size()), set(body.size(), double(b + 1));
    std::vector<Vec2> force(body.size());
    for (std::size_t i = 0; i < body.size(); ++i) {
      pv[i] = contact_.p[contact_offset_[b] + i];
      id[i] = static_cast<double>(i);
      force[i] = body.f_fluid[i];
    }
    bf.push_back({"contact_pressure", "Pa", 1, pv, {}});
    bf.push_back({"fluid_force", "N/m", 2, vec_values(force), {}});
    bf.push_back({"id", "-", 1, id, {}});
    bf.push_back({"set", "-", 1, set, {}});
    vtk.write(time_, body.name, body.x, bf);
  }
  vtk.end_frame();
}

int Simulation::run() {
  namespace fs = std::filesystem;
  const bool out = opt_.write_output;
  const std::string dir = opt_.out_dir;
  std::unique_ptr<VtkSeries> vtk;
  std::unique_ptr<CsvWriter> forces, probes, bodies_csv;
  if (out) {
    fs::create_directories(dir);
    std::ofstream(dir + "/case.resolved.toml") << resolved_case_toml(cfg_);
    if (cfg_.output.vtk) vtk = std::make_unique<VtkSeries>(dir);
    if (!bodies_.empty()) {
      std::vector<std::string> h{"time [s]"};
      for (const SolidBody& b : bodies_) {
        h.push_back(b.name + " Fx [N/m]");
        h.push_back(b.name + " Fy [N/m]");
        h.push_back(b.name + " Fx_pressure [N/m]");
        h.push_back(b.name + " Fy_pressure [N/m]");
        h.push_back(b.name + " Fx_viscous [N/m]");
        h.push_back(b.name + " Fy_viscous [N/m]");
      }
      forces = std::make_unique<CsvWriter>(dir + "/forces.csv", h);
      std::vector<std::string> hb{"time [s]"};
      for (const SolidBody& b : bodies_) {
        for (const char* q : {"com_x [m]", "com_y [m]", "vel_x [m/s]", "vel_y [m/s]",
                              "acc_x [m/s^2]", "acc_y [m/s^2]", "kinetic [J/m]", "strain [J/m]",
                              "dissipated [J/m]", "hourglass [J/m]"})
          hb.push_back(b.name + " " + q);
      }
      bodies_csv = std::make_unique<CsvWriter>(dir + "/bodies.csv", hb);
    }
    std::vector<std::string> hp{"time [s]"};
    for (const std::string& s : probe_headers()) hp.push_back(s);
    hp.push_back("leaked_particles [-]");
    probes = std::make_unique<CsvWriter>(dir + "/probes.csv", hp);
  }

  const double end = cfg_.numerics.end_time;
  const double vtk_dt = cfg_.output.interval > 0.0 ? cfg_.output.interval : end / 50.0;
  const double probe_dt = cfg_.output.probe_interval;
  double next_vtk = 0.0, next_probe = 0.0;
  std::vector<Vec2> peak(bodies_.size()), impulse(bodies_.size());
  std::vector<double> peak_mag(bodies_.size(), 0.0), peak_time(bodies_.size(), 0.0);

  auto record = [&](double dt_prev, const std::vector<BodyLoad>& prev) {
    if (forces) {
      std::vector<double> row{time_};
      for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const BodyLoad& l = loads_[b];
        row.insert(row.end(), {l.total.x, l.total.y, l.total.x - l.viscous.x,
                               l.total.y - l.viscous.y, l.viscous.x, l.viscous.y});
      }
      forces->row(row);
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
      const Vec2 F = loads_[b].total;
      if (norm(F) > peak_mag[b]) peak_mag[b] = norm(F), peak[b] = F, peak_time[b] = time_;
      if (dt_prev > 0.0) impulse[b] += 0.5 * dt_prev * (F + prev[b].total);
    }
  };
  auto record_probes = [&]() {
    if (!probes) return;
    std::vector<double> row{time_};
    for (double v : probe_row()) row.push_back(v);
    row.push_back(static_cast<double>(leaked_));
    probes->row(row);
  };
  auto record_bodies = [&]() {
    if (!bodies_csv) return;
    std::vector<double> row{time_};
    for (const SolidBody& b : bodies_) {
      const BodySummary m = body_summary(b);
      const BodyEnergies e = body_energies(b);
      row.insert(row.end(),
                 {m.com.x, m.com.y, m.mean_velocity.x, m.mean_velocity.y, m.mean_acceleration.x,
                  m.mean_acceleration.y, e.kinetic, e.strain, e.dissipated, e.hourglass});
    }
    bodies_csv->row(row);
  };

  const bool show_progress = !opt_.quiet && isatty(STDERR_FILENO);
  ProgressLine progress(end, show_progress);
  const auto t0 = std::chrono::steady_clock::now();
  long frame_step = -1;  // step count at the last output frame
  int code = 0;
  std::string failure;
  record(0.0, loads_);
  try {
    while (time_ < end * (1.0 - 1e-12)) {
      if (opt_.max_steps && steps_ >= *opt_.max_steps) break;
      if (out && time_ >= next_probe - 1e-15) {
        record_probes();
        next_probe += probe_dt;
        if (next_probe <= time_) next_probe = time_ + probe_dt;
      }
      if (out && time_ >= next_vtk - 1e-15) {  // VTK frames and bodies.csv rows
        if (vtk) write_frame(*vtk);
        frame_step = steps_;
        record_bodies();
        next_vtk += vtk_dt;
      }
      const std::vector<BodyLoad> prev = loads_;
      step();
      record(limit_.dt, prev);
      progress.update(time_, steps_, limit_.dt);
    }
    if (out) record_probes(), record_bodies();
    if (vtk) write_frame(*vtk);
  } catch (const DivergenceError& e) {
    code = 3;
    failure = e.what();
    // Keep the state the run diverged in, unless that frame was just written.
    if (vtk && steps_ != frame_step) {
      try {
        write_frame(*vtk);
      } catch (...) {
      }
    }
  }
  progress.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (forces) forces->flush();
  if (probes) probes->flush();
  if (bodies_csv) bodies_csv->flush();

  JsonObject summary;
  summary.set("case", cfg_.name);
  summary.set("version", std::string(SLAMSPH_VERSION));
  summary.set("status", code == 0 ? std::string("completed") : std::string("diverged"));
  if (code != 0) summary.set("failure", failure);
  JsonObject counts;
  counts.set("fluid", static_cast<long>(fluid_.size()));
  for (const SolidBody& b : bodies_) counts.set(b.name, static_cast<long>(b.size()));
  summary.set("particles", counts);
  summary.set("fluid_steps", steps_);
  summary.set("solid_substeps", solid_substeps_);
  summary.set("dual_time_stepping", cfg_.numerics.dual_time_stepping);
  summary.set("end_time_reached", time_);
  summary.set("wall_seconds", wall);
  const double ps = wall > 0.0 ? double(fluid_.size()) * double(steps_) / wall : 0.0;
  summary.set("fluid_particle_steps_per_second", ps);
  summary.set("threads", exec_.threads());
  summary.set("neighbour_rebuilds", lists_->rebuilds());
  summary.set("leaked_particles", leaked_);
  summary.set("warnings", warnings_);  // the set-up warnings printed before the run
  std::vector<JsonObject> loads;
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    JsonObject o;
    o.set("body", bodies_[b].name);
    o.set("peak_force_N_per_m", std::vector<double>{peak[b].x, peak[b].y});
    o.set("peak_time_s", peak_time[b]);
    o.set("impulse_N_s_per_m", std::vector<double>{impulse[b].x, impulse[b].y});
    loads.push_back(o);
  }
  summary.set("bodies", loads);
  if (code == 0 && out) {
    JsonObject validation;
    if (validation_report(cfg_, dir, validation)) summary.set("validation", validation);
  }
  if (out) summary.write_file(dir + "/summary.json");
  if (!opt_.quiet) {
    std::fprintf(stderr,
                 "%s: fluid particles: %zu, %ld fluid steps to t = %.6g s in %.2f s (%.4g "
                 "particle-steps/s, %d threads)\n",
                 cfg_.name.c_str(), fluid_.size(), steps_, time_, wall, ps, exec_.threads());
  }
  if (code != 0) {
    std::fprintf(stderr, "error: run diverged: %s\n", failure.c_str());
    if (out) std::fprintf(stderr, "outputs written so far are kept in %s\n", dir.c_str());
  }
  return code;
}

}  // namespace slamsph
