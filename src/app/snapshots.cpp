#include "app/snapshots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>

#include "app/keel_angle.h"
#include "io/plot.h"
#include "solid/materials/st_venant_kirchhoff.h"

namespace slamsph {

namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string short_num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.5g", v);
  return buf;
}

std::string two_digits(std::size_t i) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02zu", i + 1);
  return buf;
}

Box grow(Box b, Vec2 p) {
  b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y)};
  b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y)};
  return b;
}

}  // namespace

SnapshotWriter::SnapshotWriter(const CaseConfig& cfg, std::string out_dir, bool write_output,
                               bool quiet, double start_time)
    : cfg_(cfg),
      dir_(std::move(out_dir) + "/snapshots"),
      enabled_(write_output && !cfg.output.snapshots.empty()),
      quiet_(quiet),
      taken_at_(cfg.output.snapshots) {
  const auto& t = cfg_.output.snapshots;
  while (next_ < t.size() && t[next_] < start_time - 1e-15) ++next_;
  for (std::size_t i = 0; i < next_; ++i) skin_taken_.push_back(i);
}

void SnapshotWriter::take_due(const FsiStepper& st) {
  if (!enabled_) return;
  const auto& t = cfg_.output.snapshots;
  // The first step at or after a time takes it; several times passed in one step share it.
  while (next_ < t.size() && st.time() >= t[next_] - 1e-15) {
    std::filesystem::create_directories(dir_);
    taken_at_[next_] = st.time();
    write(st, next_);
    if (!cfg_.output.skin_profile.empty()) write_skin_profile(st, next_);
    ++next_;
  }
}

void SnapshotWriter::write(const FsiStepper& st, std::size_t index) {
  const FsiSystem& sys = st.system();
  const std::string stem = "snapshot_" + two_digits(index);
  // The view: the case's, else around the elastic bodies (else every body), clipped to
  // the domain.
  Box view = cfg_.output.snapshot_view;
  if (!cfg_.output.has_snapshot_view()) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box bb{{inf, inf}, {-inf, -inf}};
    for (const bool elastic_only : {true, false}) {
      for (const SolidBody& b : sys.bodies)
        if (!elastic_only || b.is_elastic())
          for (const Vec2& p : b.x) bb = grow(bb, p);
      if (bb.max.x >= bb.min.x) break;
    }
    if (!(bb.max.x >= bb.min.x)) bb = cfg_.numerics.domain;
    const Vec2 pad = 0.5 * (bb.max - bb.min);
    const Box& d = cfg_.numerics.domain;
    view = {{std::max(d.min.x, bb.min.x - pad.x), std::max(d.min.y, bb.min.y - pad.y)},
            {std::min(d.max.x, bb.max.x + pad.x), std::min(d.max.y, bb.max.y + pad.y)}};
  }
  // Data: x, y, set (0 water, 1 elastic, 2 rigid, 3 failed elastic), value, radius of the
  // drawn disc. Failed particles (a material with failure, issue 11) are drawn over the rest
  // as open circles, so where the structure broke shows on the final state.
  double pmin = std::numeric_limits<double>::infinity(), pmax = -pmin, emax = 0.0;
  std::size_t failed = 0;
  {
    std::ofstream f(dir_ + "/" + stem + ".csv");
    f << "x [m],y [m],set [-],value [Pa or -],radius [m]\n";
    const FluidParticles& w = sys.fluid;
    const double rf = 0.5 * cfg_.numerics.dx;
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (!inside(view, w.x[i])) continue;
      f << num(w.x[i].x) << ',' << num(w.x[i].y) << ",0," << num(w.p[i]) << ',' << num(rf) << '\n';
      pmin = std::min(pmin, w.p[i]);
      pmax = std::max(pmax, w.p[i]);
    }
    for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
      const SolidBody& body = sys.bodies[b];
      const bool el = body.is_elastic() && body.F.size() == body.size();
      const bool own = body.spacing.size() == body.size();  // parts of their own spacing
      const std::vector<double>* fl = el ? body.history.find("failed") : nullptr;
      for (std::size_t i = 0; i < body.size(); ++i) {
        if (!inside(view, body.x[i])) continue;
        const double r = 0.5 * (own ? body.spacing[i] : cfg_.bodies[b].dx);
        const double e = el ? equivalent_strain(green_lagrange(body.F[i])) : 0.0;
        const bool broken = fl && (*fl)[i] > 0.5;
        failed += broken ? 1 : 0;
        emax = std::max(emax, e);
        f << num(body.x[i].x) << ',' << num(body.x[i].y) << ','
          << (broken ? 3
              : el   ? 1
                     : 2)
          << ',' << num(e) << ',' << num(r) << '\n';
      }
    }
  }
  if (!(pmax > pmin)) pmin = std::isfinite(pmin) ? pmin - 1.0 : 0.0, pmax = pmin + 2.0;
  if (!(emax > 0.0)) emax = 1e-6;
  // Canvas: the plot area keeps the view's aspect ratio (equal scales on both axes).
  const int width = 1200;
  const double area_w = 0.66, area_h = 0.80;
  const double aspect = (view.max.y - view.min.y) / (view.max.x - view.min.x);
  const int height = std::clamp(static_cast<int>(width * area_w * aspect / area_h), 300, 2400);
  const double requested = cfg_.output.snapshots[index];
  std::string s = gnuplot_preamble(stem + ".png", width, height);
  s += "unset key\nset grid front\nset multiplot\n";
  s += "set lmargin at screen 0.09\nset rmargin at screen " + num(0.09 + area_w) +
       "\nset bmargin at screen 0.10\nset tmargin at screen 0.90\n";
  s += "set xrange [" + num(view.min.x) + ":" + num(view.max.x) + "]\nset yrange [" +
       num(view.min.y) + ":" + num(view.max.y) + "]\n";
  s += "set xlabel 'x [m]'\nset ylabel 'y [m]'\n";
  s +=
      "set title " +
      gnuplot_quote("t = " + short_num(st.time()) + " s (first step at or after " + num(requested) +
                    " s): equivalent strain in the structure, pressure in the water") +
      "\n";
  // Layer 1: water by pressure (rainbow), rigid bodies grey.
  s += "set palette rgb 33,13,10\nset cbrange [" + num(pmin) + ":" + num(pmax) + "]\n";
  s += "set colorbox user origin screen 0.78, screen 0.15 size screen 0.02, screen 0.7\n";
  s += "set cblabel 'water pressure [Pa]'\n";
  s += "plot " + gnuplot_quote(stem + ".csv") +
       " skip 1 using 1:($3 == 0 ? $2 : NaN):5:4 with circles fill solid noborder lc palette, \\\n"
       "     '' skip 1 using 1:($3 == 2 ? $2 : NaN):5 with circles fill solid noborder lc rgb "
       "'#909090'\n";
  // Layer 2: elastic bodies by strain (hot), on top; same frame, no second grid or title.
  s += "unset title\nunset grid\nset border 0\nunset xtics\nunset ytics\nunset xlabel\n"
       "unset ylabel\n";
  s += "set palette rgb 7,5,15\nset cbrange [0:" + num(emax) + "]\n";
  s += "set colorbox user origin screen 0.89, screen 0.15 size screen 0.02, screen 0.7\n";
  s += "set cblabel 'equivalent strain [-]'\n";
  if (failed > 0)
    s += "set label 1 " +
         gnuplot_quote(std::to_string(failed) + " failed particle" + (failed > 1 ? "s" : "") +
                       " (open circles)") +
         " at graph 0.02, graph 0.96 front textcolor rgb '#0080c0'\n";
  s += "plot " + gnuplot_quote(stem + ".csv") +
       " skip 1 using 1:($3 == 1 ? $2 : NaN):5:4 with circles fill solid noborder lc palette";
  if (failed > 0)
    s += ", \\\n     '' skip 1 using 1:($3 == 3 ? $2 : NaN) with points pt 6 ps 1.2 lw 2 lc rgb "
         "'#00c0ff'";
  s += "\n";
  s += "unset multiplot\n";
  std::string message;
  const int rc = run_gnuplot_script(dir_, stem, s, "gnuplot", message);
  if (rc != 0 && !warned_ && !quiet_) {
    std::fprintf(stderr, "warning: snapshot PNGs not drawn (%s); the CSV and .gp are kept\n",
                 message.c_str());
    warned_ = true;
  }
}

void SnapshotWriter::write_skin_profile(const FsiStepper& st, std::size_t index) {
  const FsiSystem& sys = st.system();
  const BodyConfig* bc = nullptr;
  const SolidBody* body = nullptr;
  for (std::size_t b = 0; b < sys.bodies.size(); ++b)
    if (sys.bodies[b].name == cfg_.output.skin_profile) body = &sys.bodies[b], bc = &cfg_.bodies[b];
  if (!body || body->P.size() != body->size()) return;
  const ShapeConfig& sh = bc->shape;
  // The skin: a ring, or a fuselage's part "skin" (its stringers, floor and columns are not
  // on the skin's mid-surface).
  double r_out = sh.outer_radius, r_in = sh.inner_radius;
  int layers = sh.layers;
  if (sh.type == "fuselage") {
    r_out = 0.5 * sh.fuselage.diameter;
    r_in = r_out - sh.fuselage.skin_thickness;
    layers = sh.fuselage.skin_layers;
  }
  auto on_skin = [&](std::size_t i) {
    if (body->part.size() != body->size() || body->part[i] >= body->part_names.size()) return true;
    return sh.type != "fuselage" || body->part_names[body->part[i]] == "skin";
  };
  const double r_mid = 0.5 * (r_in + r_out);
  const double half_layer = 0.5 * (r_out - r_in) / std::max(1, layers);
  struct Point {
    double angle, pyy;
  };
  std::vector<Point> pts;
  for (std::size_t i = 0; i < body->size(); ++i) {
    const Vec2 d = body->X[i] - sh.centre;
    if (!on_skin(i) || std::abs(norm(d) - r_mid) > half_layer * (1.0 + 1e-6)) continue;
    double deg = keel_angle_deg(d);
    if (deg < 0.0) deg += 360.0;
    pts.push_back({deg, body->P[i].yy});
  }
  std::sort(pts.begin(), pts.end(),
            [](const Point& a, const Point& b) { return a.angle < b.angle; });
  const std::string name = "skin_pyy_" + two_digits(index) + ".csv";
  {
    std::ofstream f(dir_ + "/" + name);
    f << "angle from keel [deg],P_yy [Pa]\n";
    // The two middle layers of an even count share angles: one row per angle, averaged.
    for (std::size_t i = 0; i < pts.size();) {
      std::size_t j = i;
      double sum = 0.0;
      while (j < pts.size() && pts[j].angle - pts[i].angle < 1e-6) sum += pts[j++].pyy;
      f << num(pts[i].angle) << ',' << num(sum / static_cast<double>(j - i)) << '\n';
      i = j;
    }
  }
  skin_taken_.push_back(index);
  std::string s = gnuplot_preamble("skin_pyy.png", 1100, 650);
  s += "set title " +
       gnuplot_quote("First Piola-Kirchhoff P_yy along the mid-surface of " + body->name) + "\n";
  s += "set xlabel 'angle from the keel, anticlockwise [deg]'\nset ylabel 'P_yy [Pa]'\n";
  s += "set xrange [0:360]\nset xtics 45\nset key top right box opaque\nplot ";
  for (std::size_t k = 0; k < skin_taken_.size(); ++k) {
    const std::size_t n = skin_taken_[k];
    if (k) s += ", \\\n     ";
    s += gnuplot_quote("skin_pyy_" + two_digits(n) + ".csv") +
         " skip 1 using 1:2 with linespoints pt 7 ps 0.5 lw 1.5 title " +
         gnuplot_quote("t = " + short_num(taken_at_[n]) + " s");
  }
  s += "\n";
  std::string message;
  run_gnuplot_script(dir_, "skin_pyy", s, "gnuplot", message);
}

}  // namespace slamsph
