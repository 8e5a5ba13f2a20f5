#include "app/recorder.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>
#include <type_traits>

#include "app/output_folder.h"
#include "app/validation_report.h"
#include "core/error.h"
#include "core/parallel.h"
#include "fluid/fluid_energy.h"
#include "io/atomic_file.h"
#include "io/case_file.h"
#include "io/csv_writer.h"
#include "io/json_writer.h"
#include "io/vtk_writer.h"
#include "solid/body_dynamics.h"
#include "solid/body_energy.h"

namespace slamsph {

namespace {

// Σ m v of the water, in the executor's fixed-order sum (the same for any thread count).
Vec2 fluid_momentum(const FluidParticles& f, const Executor& exec) {
  return exec.sum_of<Vec2>(f.size(), [&](std::size_t i) { return f.m[i] * f.v[i]; });
}

}  // namespace

Recorder::Recorder(const CaseConfig& cfg, const RunOptions& opt, const FsiStepper& stepper,
                   const ProbeSet& probes, const Executor& exec)
    : cfg_(cfg), opt_(opt), st_(stepper), probes_(probes), exec_(exec) {
  const double end = cfg_.numerics.end_time;
  vtk_dt_ = cfg_.output.interval > 0.0 ? cfg_.output.interval : end / 50.0;
  probe_dt_ = cfg_.output.probe_interval;
  const std::size_t nb = st_.system().bodies.size();
  peak_.assign(nb, Vec2{});
  impulse_.assign(nb, Vec2{});
  peak_mag_.assign(nb, 0.0);
  peak_time_.assign(nb, 0.0);
  part_peaks_.reset(st_.system().bodies);  // before a checkpoint restores its state
}

Recorder::~Recorder() = default;

void Recorder::start(std::vector<std::string> warnings, const RecorderResume* resume) {
  warnings_ = std::move(warnings);
  const std::vector<SolidBody>& bodies = st_.system().bodies;
  // A resumed run continues each file from its size at the checkpoint.
  auto csv = [&](const std::string& name, const std::vector<std::string>& headers) {
    const std::string path = opt_.out_dir + "/" + name;
    if (!resume) return std::make_unique<CsvWriter>(path, headers);
    for (const CsvResume& c : resume->csv)
      if (c.name == name)
        return std::make_unique<CsvWriter>(path, headers, CsvWriter::Resume{c.bytes, c.rows});
    throw InputError("checkpoint has no state for " + path);
  };
  failure_log_.reset(bodies);  // a resumed run does not report its failed particles again
  if (opt_.write_output) {
    const std::string& dir = opt_.out_dir;
    if (!resume) OutputFolder::check_free(dir, opt_.overwrite);
    folder_ = std::make_unique<OutputFolder>(
        dir, resume ? OutputFolder::Mode::Continue : OutputFolder::Mode::Fresh);
    std::vector<std::string> names{"summary.json", "case.resolved.toml", "probes.csv", "energy.csv",
                                   "momentum.csv"};
    if (!bodies.empty()) names.insert(names.end(), {"forces.csv", "bodies.csv"});
    if (cfg_.output.vtk) names.insert(names.end(), {"vtk/", "fields.pvd"});
    if (opt_.checkpoint_interval > 0.0) names.push_back("checkpoints/");
    // Listed before the snapshot writer creates it, so that a run killed before its next
    // flush still has the folder (and so its PNGs) in its manifest.
    if (!cfg_.output.snapshots.empty()) names.push_back("snapshots/");
    if (failure_log_.active()) names.push_back("failure.csv");
    folder_->record(names);
    RunStatus running;
    running.running = true;
    write_summary(running);
    CaseConfig resolved = cfg_;  // a resumed run keeps the first run's --set notes
    if (resume) resolved.overrides = resume->case_overrides;
    write_file_atomically(dir + "/case.resolved.toml", resolved_case_toml(resolved));
    const VtkOptions vo{cfg_.output.vtk_precision == "float64",
                        cfg_.output.vtk_compression == "zlib"};
    if (cfg_.output.vtk && resume && resume->vtk)
      vtk_ = std::make_unique<VtkSeries>(dir, vo, *resume->vtk);
    else if (cfg_.output.vtk)
      vtk_ = std::make_unique<VtkSeries>(dir, vo);
    if (!bodies.empty()) {
      std::vector<std::string> h{"time [s]"};
      for (const SolidBody& b : bodies) {
        h.push_back(b.name + " Fx [N/m]");
        h.push_back(b.name + " Fy [N/m]");
        h.push_back(b.name + " Fx_pressure [N/m]");
        h.push_back(b.name + " Fy_pressure [N/m]");
        h.push_back(b.name + " Fx_viscous [N/m]");
        h.push_back(b.name + " Fy_viscous [N/m]");
      }
      forces_ = csv("forces.csv", h);
      std::vector<std::string> hb{"time [s]"};
      for (const SolidBody& b : bodies) {
        for (const char* q : {"com_x [m]", "com_y [m]", "vel_x [m/s]", "vel_y [m/s]",
                              "acc_x [m/s^2]", "acc_y [m/s^2]", "kinetic [J/m]", "strain [J/m]",
                              "dissipated [J/m]", "hourglass [J/m]"})
          hb.push_back(b.name + " " + q);
      }
      bodies_csv_ = csv("bodies.csv", hb);
    }
    std::vector<std::string> hp{"time [s]"};
    for (const std::string& s : probes_.headers()) hp.push_back(s);
    hp.push_back("leaked_particles [-]");
    probes_csv_ = csv("probes.csv", hp);
    if (failure_log_.active()) failure_csv_ = csv("failure.csv", FailureLog::headers());
    std::vector<std::string> he{"time [s]", "fluid kinetic [J/m]", "fluid potential [J/m]",
                                "fluid internal [J/m]"};
    for (const SolidBody& b : bodies) {
      if (b.kind == BodyKind::RigidPrescribed) he.push_back(b.name + " fluid_work [J/m]");
      if (b.kind != BodyKind::Elastic && b.kind != BodyKind::RigidFree) continue;
      for (const char* q : {"kinetic [J/m]", "strain [J/m]", "hourglass [J/m]", "dissipated [J/m]",
                            "gravity_work [J/m]", "fluid_work [J/m]", "residual [J/m]"}) {
        if (std::string(q) == "residual [J/m]" && has_moving_clamp(b))
          he.push_back(b.name + " clamp_work [J/m]");  // only where a clamp moves
        he.push_back(b.name + " " + q);
      }
    }
    he.insert(he.end(), {"fluid residual [J/m]", "residual [J/m]"});
    energy_csv_ = csv("energy.csv", he);
    std::vector<std::string> hm{"time [s]"};
    for (const char* c : {"x", "y"}) hm.push_back(std::string("fluid momentum ") + c + " [N s/m]");
    for (const char* c : {"x", "y"})
      hm.push_back(std::string("fluid gravity_impulse ") + c + " [N s/m]");
    if (st_.params().absorbing_zone.active())
      for (const char* c : {"x", "y"})
        hm.push_back(std::string("fluid absorbing_zone ") + c + " [N s/m]");
    for (const SolidBody& b : bodies)
      for (const char* c : {"x", "y"}) hm.push_back(b.name + " fluid_impulse " + c + " [N s/m]");
    hm.insert(hm.end(), {"residual x [N s/m]", "residual y [N s/m]"});
    momentum_csv_ = csv("momentum.csv", hm);
  }
  if (!resume) {  // the energy balance is measured from the state at t = 0
    const Vec2 g = st_.params().gravity;
    const FluidEnergies f = fluid_energies(st_.system().fluid, st_.system().eos, g);
    energy0_ = {f.potential, f.kinetic + f.potential + f.internal};
    for (const SolidBody& b : bodies) {
      if (b.kind != BodyKind::Elastic && b.kind != BodyKind::RigidFree) continue;
      const BodyEnergyTerms t = body_energy_terms(b, g);
      energy0_.insert(energy0_.end(), {t.kinetic + t.strain + t.hourglass, t.potential});
    }
    momentum0_ = fluid_momentum(st_.system().fluid, exec_);
  }
  prev_loads_ = st_.body_loads();
  if (!resume) record_loads(0.0);  // a resumed run has this row already
}

std::vector<CsvResume> Recorder::csv_state() const {
  std::vector<CsvResume> out;
  for (const CsvWriter* w : {forces_.get(), probes_csv_.get(), bodies_csv_.get(), energy_csv_.get(),
                             momentum_csv_.get(), failure_csv_.get()}) {
    if (!w) continue;
    const std::string name = std::filesystem::path(w->path()).filename().string();
    out.push_back({name, std::filesystem::file_size(w->path()), w->rows_written()});
  }
  return out;
}

std::optional<VtkSeries::State> Recorder::vtk_state() const {
  if (!vtk_) return std::nullopt;
  return vtk_->state();
}

void Recorder::record_loads(double dt_prev) {
  const double time = st_.load_time();  // the symplectic step's loads are of t_n+1/2
  const std::vector<BodyLoad>& loads = st_.body_loads();
  if (forces_) {
    std::vector<double> row{time};
    for (const BodyLoad& l : loads)
      row.insert(row.end(), {l.total.x, l.total.y, l.total.x - l.viscous.x, l.total.y - l.viscous.y,
                             l.viscous.x, l.viscous.y});
    forces_->row(row);
  }
  for (std::size_t b = 0; b < loads.size(); ++b) {
    const Vec2 F = loads[b].total;
    if (norm(F) > peak_mag_[b]) peak_mag_[b] = norm(F), peak_[b] = F, peak_time_[b] = time;
    if (dt_prev > 0.0) impulse_[b] += 0.5 * dt_prev * (F + prev_loads_[b].total);
  }
}

void Recorder::record_probes() {
  if (!probes_csv_) return;
  std::vector<double> row{st_.time()};
  for (double v : probes_.row(st_, exec_)) row.push_back(v);
  row.push_back(static_cast<double>(st_.leaked_particles()));
  probes_csv_->row(row);
}

void Recorder::record_bodies() {
  if (!bodies_csv_) return;
  std::vector<double> row{st_.time()};
  for (const SolidBody& b : st_.system().bodies) {
    const BodySummary m = body_summary(b);
    const BodyEnergies e = body_energies(b);
    row.insert(row.end(),
               {m.com.x, m.com.y, m.mean_velocity.x, m.mean_velocity.y, m.mean_acceleration.x,
                m.mean_acceleration.y, e.kinetic, e.strain, e.dissipated, e.hourglass});
  }
  bodies_csv_->row(row);
}

// One row of energy.csv (README "Energy balance"). Fluid: R_f = Δ(K + V + U)_fluid + Σ W_fluid
// over the moving bodies (the energy the water gave them). Each elastic or rigid_free body:
// R_b = Δ(K + Ψ + E_hg) + D − W_gravity − W_fluid − W_clamps (the last only where a clamp
// moves; its column is written only then). The residual R = R_f + Σ R_b is what the
// discretisation lost (< 0) or made (> 0): mostly the Riemann solver's dissipation in the water.
void Recorder::record_energy() {
  if (!energy_csv_) return;
  const Vec2 g = st_.params().gravity;
  const FluidEnergies f = fluid_energies(st_.system().fluid, st_.system().eos, g);
  std::vector<double> row{st_.time(), f.kinetic, f.potential - energy0_[0], f.internal};
  double fluid_res = f.kinetic + f.potential + f.internal - energy0_[1];
  double total = 0.0;
  std::size_t k = 2;
  for (const SolidBody& b : st_.system().bodies) {
    const BodyEnergyTerms t = body_energy_terms(b, g);
    if (b.kind == BodyKind::RigidPrescribed) {
      row.push_back(t.external_work);  // only the fluid's (solid/rigid_motion.cpp)
      fluid_res += t.external_work;
    }
    if (b.kind != BodyKind::Elastic && b.kind != BodyKind::RigidFree) continue;
    const double w_gravity = energy0_[k + 1] - t.potential;
    const double w_fluid = t.external_work - w_gravity;
    const double res = t.kinetic + t.strain + t.hourglass - energy0_[k] + t.dissipated - w_gravity -
                       w_fluid - t.clamp_work;
    k += 2;
    row.insert(row.end(), {t.kinetic, t.strain, t.hourglass, t.dissipated, w_gravity, w_fluid});
    if (has_moving_clamp(b)) row.push_back(t.clamp_work);
    row.push_back(res);
    fluid_res += w_fluid;
    total += res;
  }
  total += fluid_res;
  row.insert(row.end(), {fluid_res, total});
  // The scale of the balance: the largest |term| written so far (residual columns aside).
  for (std::size_t c = 1; c + 2 < row.size(); ++c)
    if (energy_csv_->headers()[c].find(" residual [") == std::string::npos)
      energy_scale_ = std::max(energy_scale_, std::abs(row[c]));
  energy_max_residual_ = std::max(energy_max_residual_, std::abs(total));
  energy_last_residual_ = total;
  energy_csv_->row(row);
}

// One row of momentum.csv (README "Momentum balance"): the water's momentum P_f = Σ m v and
//   R = P_f − P_f(0) − M_f g t − Z + Σ_b I_b,
// Z the momentum change the absorbing zone made (Σ m Δv, a column only when the case has a
// zone), I_b the fluid impulse body b received as its integrator applied it (with the
// impulse still due to it under next_step; app/dual_time_stepping.h). Every other force on
// the water is a pair force (GSPH pairs, fluid/gsph_fluid_rates.h; contact pairs, whose
// reaction the bodies get, coupling/contact_rates.h), so R is round-off when the exchange is
// exact, and −Σ dt/2 (F_n+1 − F_n) of the free particles with fluid_force_correction = none.
void Recorder::record_momentum() {
  if (!momentum_csv_) return;
  const FluidParticles& f = st_.system().fluid;
  const Vec2 p = fluid_momentum(f, exec_);
  const double mass = exec_.sum_of<double>(f.size(), [&](std::size_t i) { return f.m[i]; });
  const Vec2 weight = (mass * st_.time()) * st_.params().gravity;
  const Vec2 dp = p - momentum0_;
  std::vector<double> row{st_.time(), p.x, p.y, weight.x, weight.y};
  Vec2 res = dp - weight;
  double scale = std::max(norm(dp), norm(weight));
  if (st_.params().absorbing_zone.active()) {
    const Vec2 z = st_.absorbing_zone_momentum();
    row.insert(row.end(), {z.x, z.y});
    res -= z;
    scale = std::max(scale, norm(z));
  }
  const std::vector<SolidBody>& bodies = st_.system().bodies;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    Vec2 impulse = st_.body_fluid_impulse(b);
    for (const Vec2& d : bodies[b].impulse_due) impulse += d;
    row.insert(row.end(), {impulse.x, impulse.y});
    res += impulse;
    scale = std::max(scale, norm(impulse));
  }
  row.insert(row.end(), {res.x, res.y});
  momentum_scale_ = std::max(momentum_scale_, scale);
  momentum_max_residual_ = {std::max(momentum_max_residual_.x, std::abs(res.x)),
                            std::max(momentum_max_residual_.y, std::abs(res.y))};
  momentum_last_residual_ = res;
  momentum_csv_->row(row);
}

void Recorder::write_frame() {
  const FsiSystem& sys = st_.system();
  const FluidParticles& fluid = sys.fluid;
  const double time = st_.time();
  // Stored fields flagged for VTK in their registry (core/field_registry.h), then the set
  // index (0 = fluid, b + 1 = body b) for colouring.
  auto registry_fields = [](const auto& set, std::vector<PointField>& out) {
    std::decay_t<decltype(set)>::visit_fields(set, [&](const FieldSpec& spec, const auto& f) {
      using T = typename std::decay_t<decltype(f)>::value_type;
      if (!spec.vtk || f.size() != set.size()) return;  // e.g. F, P of a rigid body: empty
      std::vector<std::string> names;
      if (field_components<T>() == 4) names = {"xx", "xy", "yx", "yy"};
      out.push_back({std::string(spec.name), std::string(spec.unit), field_components<T>(),
                     field_as_doubles(f), names, std::is_integral_v<T>});
    });
  };
  if (fluid.size() > 0) {
    std::vector<PointField> ff;
    registry_fields(fluid, ff);
    ff.push_back({"set", "-", 1, std::vector<double>(fluid.size(), 0.0), {}, true});
    vtk_->write(time, "fluid", fluid.x, ff);
  }
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    const SolidBody& body = sys.bodies[b];
    std::vector<PointField> bf;
    for (SolidField& sf : solid_output_fields(body)) {
      std::vector<std::string> names;
      if (sf.components == 4) names = {"xx", "xy", "yx", "yy"};
      if (sf.components == 6) names = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
      bf.push_back({sf.name, sf.unit, sf.components, std::move(sf.values), names});
    }
    std::vector<double> pv(body.size()), id(body.size()), set(body.size(), double(b + 1));
    for (std::size_t i = 0; i < body.size(); ++i) {
      pv[i] = std::max(sys.contact.p[sys.layout.offset[b] + i], cfg_.fluid.cavitation_pressure);
      id[i] = static_cast<double>(i);
    }
    bf.push_back({"contact_pressure", "Pa", 1, pv, {}});
    registry_fields(body, bf);
    bf.push_back({"id", "-", 1, id, {}, true});
    bf.push_back({"set", "-", 1, set, {}, true});
    vtk_->write(time, body.name, body.x, bf);
  }
  vtk_->end_frame();
}

void Recorder::before_step() {
  const double time = st_.time();
  if (opt_.write_output && time >= next_probe_ - 1e-15) {
    record_probes();
    next_probe_ += probe_dt_;
    if (next_probe_ <= time) next_probe_ = time + probe_dt_;
  }
  if (opt_.write_output && time >= next_vtk_ - 1e-15) {  // VTK frames and bodies.csv rows
    if (vtk_) write_frame();
    frame_step_ = st_.steps();
    record_bodies();
    record_energy();
    record_momentum();
    next_vtk_ += vtk_dt_;
  }
  prev_loads_ = st_.body_loads();
}

void Recorder::after_step() {
  record_loads(st_.last_step_limit().dt);
  part_peaks_.update(st_.system().bodies, st_.time());
  for (const std::vector<double>& row : failure_log_.scan(st_.system().bodies, st_.time()))
    if (failure_csv_) failure_csv_->row(row);
}

void Recorder::finish() {
  if (opt_.write_output) record_probes(), record_bodies(), record_energy(), record_momentum();
  if (vtk_) write_frame();
}

void Recorder::after_divergence() {
  if (vtk_ && st_.steps() != frame_step_) {
    try {
      write_frame();
    } catch (...) {
    }
  }
}

void Recorder::flush() {
  std::optional<std::system_error> first;
  auto attempt = [&](auto&& f) {
    try {
      f();
    } catch (const std::system_error& e) {
      if (!first) first = e;
    }
  };
  for (CsvWriter* w : {forces_.get(), probes_csv_.get(), bodies_csv_.get(), energy_csv_.get(),
                       momentum_csv_.get(), failure_csv_.get()})
    if (w) attempt([&] { w->flush(); });
  if (folder_) attempt([&] { folder_->record(); });
  if (first) throw *first;
}

void Recorder::write_summary(const RunStatus& status) const {
  const FsiSystem& sys = st_.system();
  const double wall = wall_before_ + status.wall_seconds;
  JsonObject summary;
  summary.set("case", cfg_.name);
  summary.set("version", std::string(SLAMSPH_VERSION));
  // "stopped": ended early on purpose (--max-steps); its peaks are not the case's peaks.
  // "running": written first, rewritten at the end; a folder left with it holds a run
  // that was killed or is still going. "failed": the environment refused (exit 4).
  const std::string state = status.running           ? "running"
                            : status.code == 4       ? "failed"
                            : status.code != 0       ? "diverged"
                            : status.signal != 0     ? "interrupted"
                            : status.stopped.empty() ? "completed"
                                                     : "stopped";
  summary.set("status", state);
  if (status.code != 0) summary.set("failure", status.failure);
  if (!status.stopped.empty()) summary.set("reason", status.stopped);
  JsonObject counts;
  counts.set("fluid", static_cast<long>(sys.fluid.size()));
  for (const SolidBody& b : sys.bodies) counts.set(b.name, static_cast<long>(b.size()));
  summary.set("particles", counts);
  summary.set("fluid_steps", st_.steps());
  summary.set("solid_substeps", st_.solid_substeps());
  // Which criterion set the fluid step, in steps (app/time_step_limit.h); bodies together.
  JsonObject limiters;
  for (const StepLimiter l : {StepLimiter::FluidAcousticCfl, StepLimiter::FluidAcceleration,
                              StepLimiter::SolidCfl, StepLimiter::EndTimeFraction}) {
    const std::string name = l == StepLimiter::SolidCfl ? "solid CFL" : describe({0.0, l, 0}, {});
    limiters.set(name, st_.steps_limited_by(l));
  }
  summary.set("step_limiters", limiters);
  summary.set("dual_time_stepping", cfg_.numerics.dual_time_stepping);
  summary.set("end_time_reached", st_.time());
  summary.set("wall_seconds", wall);  // the whole run, resumed segments included
  const double ps = wall > 0.0 ? double(sys.fluid.size()) * double(st_.steps()) / wall : 0.0;
  summary.set("fluid_particle_steps_per_second", ps);
  summary.set("threads", exec_.threads());
  // Where this process's wall time went (app/phase_times.h); a resumed run reports its own
  // segment only, like cpu_seconds.
  {
    JsonObject split;
    const PhaseTimes& t = st_.phase_times();
    t.visit([&](const char* name, double s) { split.set(name, s); });
    split.set("other", t.other(status.wall_seconds));
    summary.set("time_split_s", split);
    summary.set("cpu_seconds", status.cpu_seconds);
  }
  summary.set("thread_wait_policy", Executor::wait_policy());
  // Parallel loops that ran on fewer threads than asked because other programs kept the
  // CPUs busy (core/parallel.h, Executor::Load::Adapt); results do not depend on it.
  summary.set("loops_on_fewer_threads", static_cast<unsigned long>(exec_.sync_counts().reduced));
  summary.set("neighbour_rebuilds", st_.lists().rebuilds());
  summary.set("leaked_particles", st_.leaked_particles());
  summary.set("warnings", warnings_);  // the set-up warnings printed before the run
  std::vector<JsonObject> loads;
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    JsonObject o;
    o.set("body", sys.bodies[b].name);
    // No step, no history: a peak of the initial load only would read as a result.
    if (st_.steps() > 0) {
      o.set("peak_force_N_per_m", std::vector<double>{peak_[b].x, peak_[b].y});
      o.set("peak_time_s", peak_time_[b]);
    }
    o.set("impulse_N_s_per_m", std::vector<double>{impulse_[b].x, impulse_[b].y});
    loads.push_back(o);
  }
  summary.set("bodies", loads);
  if (failure_log_.active()) summary.set("failures", failure_log_.summary(sys.bodies));
  if (!sys.bodies.empty() && st_.steps() > 0) summary.set("parts", part_peaks_.summary(sys.bodies));
  if (energy_csv_) {
    // energy.csv's residual against its largest term (README "Energy balance").
    JsonObject en;
    en.set("residual_J_per_m", energy_last_residual_);
    en.set("largest_term_J_per_m", energy_scale_);
    const double s = energy_scale_ > 0.0 ? energy_scale_ : 1.0;
    en.set("residual_relative", energy_last_residual_ / s);
    en.set("max_abs_residual_relative", energy_max_residual_ / s);
    summary.set("energy_balance", en);
  }
  if (momentum_csv_) {
    // momentum.csv's residual against its largest term (README "Momentum balance").
    JsonObject mo;
    const Vec2 r = momentum_last_residual_, rmax = momentum_max_residual_;
    mo.set("residual_N_s_per_m", std::vector<double>{r.x, r.y});
    mo.set("max_abs_residual_N_s_per_m", std::vector<double>{rmax.x, rmax.y});
    mo.set("largest_term_N_s_per_m", momentum_scale_);
    const double s = momentum_scale_ > 0.0 ? momentum_scale_ : 1.0;
    mo.set("residual_relative", std::vector<double>{r.x / s, r.y / s});
    mo.set("max_abs_residual_relative", std::vector<double>{rmax.x / s, rmax.y / s});
    summary.set("momentum_balance", mo);
  }
  if (state == "completed" && opt_.write_output) {
    JsonObject validation;
    if (validation_report(cfg_, opt_.out_dir, validation)) summary.set("validation", validation);
  }
  if (opt_.write_output) summary.write_file(opt_.out_dir + "/summary.json");
}

}  // namespace slamsph
