#include "app/validation_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

#include "io/csv_writer.h"
#include "io/entry_series.h"
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
    p.t_contact = 0.0;  // used only without a body path (bodies.csv)
    // The still free surface over the body: the top of the highest water block under its
    // centre (s(t) = surface − lowest point; io/entry_series.h).
    for (const FluidBlockConfig& blk : cfg.fluid.blocks)
      if (blk.box.min.x <= b.shape.centre.x && b.shape.centre.x <= blk.box.max.x)
        p.surface_y =
            std::isnan(p.surface_y) ? blk.box.max.y : std::max(p.surface_y, blk.box.max.y);
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
      p.radius > 0.0) {
    // Like with like (issue 9; docs/validation.md §3): Cs = F/(ρ V(t)² R) against s(t)/D
    // from the body's actual path, t0 the geometric contact time. The peak is reported with
    // its s/D, dx/s* and Mach number, not against a theory's F(0): it is an under-resolved
    // acoustic event whose value depends on dx and c0 (docs/validation.md §1).
    EntrySeries es;
    std::string why;
    if (!load_entry_series(out_dir, p.body, "", p.surface_y, p.radius, p.density, p.velocity,
                           p.t_contact, es, why) ||
        es.t.empty())
      return false;
    out.set("kind", std::string("cylinder_entry"));
    out.set("body", p.body);
    out.set("t0_geometric_contact_s", es.t0);
    out.set("t0_from_body_path", es.t0_from_path);
    out.set("speed_at_contact_m_per_s", es.speed_at_contact);
    std::vector<double> vt, vv;
    for (double ms : {0.0, 2.0, 5.0, 10.0, 20.0, 30.0, 40.0, 50.0}) {
      const double v = interpolate(es.t, es.v, 1e-3 * ms);
      if (std::isnan(v)) continue;
      vt.push_back(1e-3 * ms);
      vv.push_back(v);
    }
    out.set("velocity_history_t_minus_t0_s", vt);
    out.set("velocity_history_m_per_s", vv);
    std::size_t ipk = 0;
    for (std::size_t k = 1; k < es.f.size(); ++k)
      if (es.f[k] > es.f[ipk]) ipk = k;
    JsonObject pk;
    pk.set("force_N_per_m", es.f[ipk]);
    pk.set("t_minus_t0_s", es.t[ipk]);
    pk.set("s_over_D", es.sd[ipk]);
    pk.set("Cs", es.cs[ipk]);
    // s* = R V²/c0²: the submergence where the acoustic stage ends.
    const double c0 = cfg.fluid.sound_speed, vpk = es.v[ipk];
    pk.set("dx_over_acoustic_depth", cfg.numerics.dx * c0 * c0 / (p.radius * vpk * vpk));
    pk.set("mach", vpk / c0);
    out.set("peak", pk);
    // Mean Cs over windows after the peak and before the tank echo: 0.05-0.25 (von Karman
    // and Campbell-Weynberg) and 0.05-0.15 (where every theory is defined).
    std::vector<JsonObject> means;
    for (const auto& [lo, hi] : {std::pair{0.05, 0.25}, std::pair{0.05, 0.15}}) {
      const WindowMean m = mean_cs(es, lo, hi);
      JsonObject mo;
      mo.set("s_over_D_range", std::vector<double>{lo, hi});
      mo.set("samples", static_cast<long>(m.samples));
      if (m.samples == 0) {
        means.push_back(mo);
        continue;
      }
      mo.set("Cs", m.value);
      for (SlammingTheory th : all_slamming_theories()) {
        JsonObject o;
        o.set("two_dimensional", slamming_theory_is_2d(th));
        double acc = 0.0;
        for (std::size_t k = 0; k < es.sd.size(); ++k)
          if (es.sd[k] >= lo && es.sd[k] <= hi && std::isfinite(es.cs[k]))
            acc += slamming_coefficient(th, es.sd[k]);
        if (std::isfinite(acc)) {
          o.set("Cs", acc / double(m.samples));
          o.set("relative_difference", m.value / (acc / double(m.samples)) - 1.0);
        } else {
          o.set("Cs", std::string("not defined over the whole window"));
        }
        mo.set(slamming_theory_name(th), o);
      }
      means.push_back(mo);
    }
    out.set("mean_Cs", means);
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
