#include "app/validation_report.h"

#include <cmath>
#include <filesystem>

#include "io/csv_writer.h"
#include "io/reference_curves.h"

namespace slamsph {

int entry_body_index(const CaseConfig& cfg) {
  for (std::size_t b = 0; b < cfg.bodies.size(); ++b)
    if (cfg.bodies[b].kind != "rigid_fixed") return static_cast<int>(b);
  return -1;
}

PlotParams plot_params_for(const CaseConfig& cfg) {
  PlotParams p;
  p.density = cfg.fluid.density;
  p.gravity = std::abs(cfg.numerics.gravity.y);
  const int eb = entry_body_index(cfg);
  if (eb >= 0) {
    const BodyConfig& b = cfg.bodies[eb];
    p.body = b.name;
    p.velocity = norm(b.velocity);
    p.radius = b.shape.type == "ring" ? b.shape.outer_radius : b.shape.radius;
    p.t_contact = 0.0;  // cases place the lowest point on the still free surface at t = 0
    if (b.initial_profile == "cantilever_mode") {
      if (const MaterialConfig* m = cfg.find_material(b.material)) {
        const double L = b.shape.box.max.x - b.shape.box.min.x;
        const double clamp =
            b.clamp.boxes.empty() ? 0.0 : b.clamp.boxes.front().max.x - b.shape.box.min.x;
        const double H = b.shape.box.max.y - b.shape.box.min.y;
        p.plate_omega =
            cantilever_omega(m->youngs_modulus, m->density, m->poisson_ratio, H, L - clamp);
        p.plate_amplitude = cantilever_tip_amplitude(b.mode_vf, m->youngs_modulus, m->density,
                                                     m->poisson_ratio, p.plate_omega);
      }
    }
  }
  if (!cfg.fluid.blocks.empty()) {
    const Box& blk = cfg.fluid.blocks.front().box;
    p.dam_width = blk.max.x - blk.min.x;
    p.wall_x = blk.min.x;
  }
  return p;
}

bool validation_report(const CaseConfig& cfg, const std::string& out_dir, JsonObject& out) {
  namespace fs = std::filesystem;
  const PlotParams p = plot_params_for(cfg);
  if (cfg.output.plot == "cylinder_entry" && fs::exists(out_dir + "/forces.csv") &&
      p.velocity > 0.0 && p.radius > 0.0) {
    const CsvTable t = read_csv(out_dir + "/forces.csv");
    const int col = t.find(p.body + " Fy [N/m]");
    if (col < 0) return false;
    const std::vector<double>& time = t.columns[0];
    const std::vector<double>& fy = t.columns[col];
    const Peak peak = find_peak(time, fy);
    const SlammingCase sc{p.density, p.velocity, p.radius, p.t_contact};
    out.set("kind", std::string("cylinder_entry"));
    out.set("body", p.body);
    out.set("peak_force_N_per_m", peak.value);
    out.set("peak_time_s", peak.time);
    out.set("peak_s_over_D", p.velocity * (peak.time - p.t_contact) / (2.0 * p.radius));
    for (SlammingTheory th :
         {SlammingTheory::CampbellWeynberg, SlammingTheory::VonKarman, SlammingTheory::Wagner}) {
      JsonObject o;
      const double ref = slamming_force(th, 0.0, p.density, p.velocity, p.radius);
      o.set("reference_peak_N_per_m", ref);
      o.set("peak_relative_error", relative_error(peak.value, ref));
      const SeriesError he = slamming_history_error(time, fy, th, sc, 0.05, 0.3);
      o.set("history_rms_relative_error_sD_0.05_0.3", he.rms);
      o.set("history_max_relative_error_sD_0.05_0.3", he.max_abs);
      o.set("history_samples", static_cast<long>(he.samples));
      out.set(slamming_theory_name(th), o);
    }
    return true;
  }
  if (cfg.output.plot == "dam_break" && fs::exists(out_dir + "/probes.csv") && p.dam_width > 0) {
    const CsvTable t = read_csv(out_dir + "/probes.csv");
    int col = -1;
    for (const ProbeConfig& pc : cfg.output.probes)
      if (pc.kind == "surge_front") col = t.find(pc.name + " [m]");
    if (col < 0) return false;
    std::vector<double> front = t.columns[col];
    for (double& x : front) x -= p.wall_x;
    out.set("kind", std::string("dam_break"));
    for (const FrontTable& tab : {martin_moyce_1952(), koshizuka_oka_1996()}) {
      const SeriesError e = front_error(t.columns[0], front, p.dam_width, p.gravity, tab, 2.5);
      JsonObject o;
      o.set("front_rms_relative_error_T_le_2.5", e.rms);
      o.set("front_max_relative_error_T_le_2.5", e.max_abs);
      o.set("at_T", e.at);
      o.set("samples", static_cast<long>(e.samples));
      // Diagnostic: the start-up delay (T units) that best explains the difference.
      const ShiftedFrontError b =
          best_front_shift(t.columns[0], front, p.dam_width, p.gravity, tab, 2.5);
      o.set("best_start_delay_T", b.shift);
      o.set("front_max_relative_error_T_le_2.5_after_delay", b.error.max_abs);
      out.set(tab.name, o);
    }
    return true;
  }
  return false;
}

}  // namespace slamsph
