#include "geometry/fuselage_section.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/cell_grid.h"

namespace slamsph {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kWhole = 1e-6;  // tolerance of "a whole number of spacings" (relative)

std::string mm(double v) {
  std::ostringstream os;
  os << v * 1e3 << " mm";
  return os.str();
}

[[noreturn]] void fail(const std::string& key, const std::string& what) {
  throw FuselageShapeError(key, what);
}

// `len` as a whole number of spacings `d` (error naming `key` otherwise).
long whole(double len, double d, const std::string& key, const std::string& what) {
  const double q = len / d;
  const long n = std::lround(q);
  if (n < 1 || std::abs(q - static_cast<double>(n)) > kWhole * std::max(1.0, q))
    fail(key, what + " " + mm(len) + " is not a whole number of particle spacings (" + mm(d) +
                  "); expected a positive multiple of " + mm(d));
  return n;
}

// Indices of a run of m arc steps centred on the stringer angle (see the header): the
// grid phase is ½ step when the web is an even number of steps, so webs and I flanges of
// the same parity are centred exactly.
long run_start(long m) {
  return -(m / 2);
}

}  // namespace

long fuselage_skin_count(const FuselageShape& s) {
  const double d = s.skin_spacing();
  const double r_mid = 0.5 * s.diameter - 0.5 * s.skin_thickness;
  const long c = std::max(1, s.stringers.count);
  return c * std::max(1L, std::lround(2.0 * kPi * r_mid / (d * static_cast<double>(c))));
}

ParticleLattice fuselage_section(Vec2 centre, const FuselageShape& s) {
  if (!(s.diameter > 0.0)) fail("diameter", "the diameter must be > 0");
  if (!(s.skin_thickness > 0.0) || !(s.skin_thickness < 0.25 * s.diameter))
    fail("skin.thickness", "the skin thickness must be in (0, D/4)");
  if (s.skin_layers < 2)
    fail("skin.layers",
         "a skin needs at least 2 particle layers (the solid's gradient needs "
         "a non-collinear neighbour set)");
  const double d = s.skin_spacing();
  const double r_out = 0.5 * s.diameter, r_in = r_out - s.skin_thickness;
  const long n = fuselage_skin_count(s);
  const double dth = 2.0 * kPi / static_cast<double>(n);
  for (int k = 0; k < s.skin_layers; ++k) {
    const double arc = (r_in + (k + 0.5) * d) * dth;
    if (std::abs(arc - d) > 0.05 * d)
      fail("skin.layers", "the skin's layers do not share one arc count within 5 % (arc " +
                              mm(arc) + " vs spacing " + mm(d) + "); expected a thinner skin");
  }

  // Stringer runs in arc steps on the inner skin face.
  const FuselageStringers& st = s.stringers;
  long m_w = 1, m_f = 1, rows = 0, rows_f = 0;
  if (st.count < 0) fail("stringers.count", "the stringer count must be >= 0");
  if (st.count > 0) {
    if (st.section != "I" && st.section != "L")
      fail("stringers.section", "the section must be \"I\" or \"L\"");
    const double arc_in = r_in * dth;
    m_w = std::lround(st.web_thickness / arc_in);
    m_f = std::lround(st.flange_width / arc_in);
    if (m_w < 2)
      fail("stringers.web_thickness",
           "a web needs at least 2 particles across (web_thickness >= 2 arc steps = " +
               mm(2 * arc_in) + ")");
    if (m_f < m_w + 1)
      fail("stringers.flange_width",
           "the flange must be wider than the web by >= 1 arc step (" + mm(arc_in) + ")");
    if (st.section == "I" && (m_f - m_w) % 2 != 0)
      fail("stringers.flange_width",
           "an I flange centred on its web needs (flange_width - web_thickness) an even number "
           "of arc steps (" +
               std::to_string(m_f) + " and " + std::to_string(m_w) + " steps of " + mm(arc_in) +
               "); expected e.g. flange_width " + mm(static_cast<double>(m_f + 1) * arc_in));
    if (m_f + 2 > n / st.count)
      fail("stringers.flange_width", "the stringers do not fit: " + std::to_string(st.count) +
                                         " flanges of " + std::to_string(m_f) +
                                         " arc steps need >= 2 steps between them (" +
                                         std::to_string(n / st.count) + " steps per stringer)");
    rows = whole(st.height, d, "stringers.height", "the stringer height");
    rows_f = whole(st.flange_thickness, d, "stringers.flange_thickness", "the flange thickness");
    const long web_rows = rows - (st.section == "I" ? 2 : 1) * rows_f;
    if (web_rows < 1)
      fail("stringers.height", "the stringer height leaves no web between the flanges");
    if ((r_in - st.height) * dth < 0.8 * d)
      fail("stringers.height", "the stringer reaches radius " + mm(r_in - st.height) +
                                   " where the polar grid's arc step falls below 0.8 dx");
  }
  const double phase = (st.count > 0 && m_w % 2 == 0) ? 0.5 : 0.0;
  const double th0 = st.offset_deg * kPi / 180.0;
  auto angle = [&](long j) { return th0 + (static_cast<double>(j) + phase) * dth; };
  auto polar = [&](double r, double a) {
    return Vec2{centre.x + r * std::cos(a), centre.y + r * std::sin(a)};
  };

  ParticleLattice out;
  const auto skin = static_cast<std::uint32_t>(FuselagePart::Skin);
  for (int k = 0; k < s.skin_layers; ++k) {
    const double lo = r_in + k * d, hi = (k + 1 == s.skin_layers) ? r_out : r_in + (k + 1) * d;
    const double v = 0.5 * (hi * hi - lo * lo) * dth;
    for (long j = 0; j < n; ++j) out.add(polar(r_in + (k + 0.5) * d, angle(j)), v, k, skin, d);
  }
  const auto stringer = static_cast<std::uint32_t>(FuselagePart::Stringers);
  const long per = st.count > 0 ? n / st.count : 0;
  // First arc step of stringer c's flange relative to its angle: centred (I); for an L,
  // flush with the web's counter-clockwise-most step on the right half (cos θ >= 0, the
  // flange extends counter-clockwise) and mirrored on the left half, so the section is
  // symmetric about the vertical line through the centre (the grid is: n is even).
  auto flange_start = [&](int c) {
    if (st.section == "I") return run_start(m_f);
    const double mid = th0 + static_cast<double>(c * per) * dth;
    return std::cos(mid) >= -1e-12 ? run_start(m_w) : run_start(m_w) + m_w - m_f;
  };
  for (int c = 0; c < st.count; ++c)
    for (long q = 0; q < rows; ++q) {
      const bool flange =
          q < rows_f || (st.section == "I" && q >= rows - rows_f);  // foot / inner flange
      const long m = flange ? m_f : m_w;
      const long j0 = flange ? flange_start(c) : run_start(m);
      const double hi = r_in - q * d, lo = r_in - (q + 1) * d;
      const double v = 0.5 * (hi * hi - lo * lo) * dth;
      for (long j = j0; j < j0 + m; ++j)
        out.add(polar(r_in - (q + 0.5) * d, angle(c * per + j)), v, -1, stringer, d);
    }

  // Floor and columns (Cartesian, spacing df, cells aligned on x = centre.x).
  const FuselageFloor& fl = s.floor;
  if (!fl.present) {
    if (!s.columns.x.empty()) fail("columns", "columns stand on the floor: a [floor] is needed");
    return out;
  }
  const double df = s.floor_spacing();
  if (!(df > 0.0)) fail("floor.dx", "the floor spacing must be > 0");
  const long frows = whole(fl.thickness, df, "floor.thickness", "the floor thickness");
  const double y_bot = fl.height - 0.5 * fl.thickness;  // relative to the centre
  if (!(std::abs(fl.height) + 0.5 * fl.thickness < r_in - 2.0 * df))
    fail("floor.height", "the floor (mid-plane " + mm(fl.height) + ", thickness " +
                             mm(fl.thickness) + ") does not lie inside the skin (inner radius " +
                             mm(r_in) + ", minus 2 floor spacings)");
  // Cells of one row or column from `a` (a cell boundary) to the skin face at distance L:
  // regular cells, the last one of length in [½, 3/2) df ending on the face.
  auto run_to_face = [&](double L, auto&& emit) {
    const long m = std::max(1L, std::lround(L / df));
    for (long j = 0; j + 1 < m; ++j) emit((j + 0.5) * df, df);
    const double last = L - static_cast<double>(m - 1) * df;
    emit(static_cast<double>(m - 1) * df + 0.5 * last, last);
  };
  const auto floor_id = static_cast<std::uint32_t>(FuselagePart::Floor);
  for (long k = 0; k < frows; ++k) {
    const double y = y_bot + (k + 0.5) * df;
    const double L = std::sqrt(r_in * r_in - y * y);
    run_to_face(L, [&](double x, double len) {
      out.add({centre.x + x, centre.y + y}, len * df, -1, floor_id, df);
      out.add({centre.x - x, centre.y + y}, len * df, -1, floor_id, df);
    });
  }
  const FuselageColumns& co = s.columns;
  const auto column_id = static_cast<std::uint32_t>(FuselagePart::Columns);
  if (!co.x.empty()) {
    const long cw = whole(co.width, df, "columns.width", "the column width");
    const double L_floor = std::sqrt(r_in * r_in - y_bot * y_bot);
    std::vector<double> sorted = co.x;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t c = 0; c < sorted.size(); ++c) {
      const double left = sorted[c] - 0.5 * co.width;
      const double q = left / df;
      if (std::abs(q - std::round(q)) > kWhole * std::max(1.0, std::abs(q)))
        fail("columns.x", "column at x = " + mm(sorted[c]) +
                              ": its edges (x ± width/2) must "
                              "lie on the floor's cell boundaries, multiples of " +
                              mm(df) + " from the centre");
      if (!(std::abs(sorted[c]) + 0.5 * co.width < L_floor - 2.0 * df))
        fail("columns.x", "column at x = " + mm(sorted[c]) + " does not stand under the floor");
      if (c > 0 && left < sorted[c - 1] + 0.5 * co.width + 2.0 * df)
        fail("columns.x", "columns at x = " + mm(sorted[c - 1]) + " and " + mm(sorted[c]) +
                              " overlap or are closer than 2 floor spacings");
      for (long j = 0; j < cw; ++j) {
        const double x = left + (j + 0.5) * df;
        const double L = y_bot + std::sqrt(r_in * r_in - x * x);  // floor bottom to skin face
        if (!(L > df)) fail("columns.x", "column at x = " + mm(sorted[c]) + " has no height");
        run_to_face(L, [&](double depth, double len) {
          out.add({centre.x + x, centre.y + y_bot - depth}, len * df, -1, column_id, df);
        });
      }
    }
  }

  // A floor or column cell centre in a stringer's sector (radially within the stringer's
  // height plus half a cell, angularly within its flange's outer cell edges plus half a
  // cell): overlap.
  if (st.count > 0) {
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (out.part[i] != floor_id && out.part[i] != column_id) continue;
      const Vec2 p = out.x[i] - centre;
      const double r = norm(p);
      if (r < r_in - st.height - 0.5 * df) continue;
      const double a = std::atan2(p.y, p.x);
      for (int c = 0; c < st.count; ++c) {
        const double mid = th0 + static_cast<double>(c * per) * dth;
        // The flange's cells span steps [lo − ½, hi + ½] (+ phase) around `mid`.
        const double lo = static_cast<double>(flange_start(c)) + phase - 0.5;
        const double hi = lo + static_cast<double>(m_f);
        const double da = std::remainder(a - mid, 2.0 * kPi) / dth;
        const double margin = 0.5 * df / (r * dth);
        if (da >= lo - margin && da <= hi + margin)
          fail("stringers.offset_deg",
               "stringer " + std::to_string(c) + " (at " + std::to_string(mid * 180.0 / kPi) +
                   " deg) overlaps the " + fuselage_part_names()[out.part[i]] + " near (" +
                   mm(p.x) + ", " + mm(p.y) +
                   ") from the centre; expected an offset_deg, floor height or column position "
                   "that keeps them apart");
      }
    }
  }

  // Parts must meet, not overlap: particles of different parts closer than 0.3 (d_i + d_j)
  // (the closest legitimate joint, a last floor cell of ½ df on the skin, is 0.375 (d + df)
  // for df = d) mean a stringer crosses the floor or a column.
  CellGrid grid;
  const double reach = 0.6 * std::max(d, df);
  grid.build(out.x, reach);
  for (std::size_t i = 0; i < out.size(); ++i)
    grid.for_each_candidate(out.x[i], [&](std::uint32_t j) {
      if (j <= i || out.part[j] == out.part[i]) return;
      if (norm(out.x[j] - out.x[i]) < 0.3 * (out.spacing[i] + out.spacing[j])) {
        const auto& names = fuselage_part_names();
        const std::string a = names[out.part[i]], b = names[out.part[j]];
        const std::string key =
            (a == "stringers" || b == "stringers") ? "stringers.offset_deg" : "columns.x";
        fail(key, "parts '" + a + "' and '" + b + "' overlap near (" + mm(out.x[i].x - centre.x) +
                      ", " + mm(out.x[i].y - centre.y) +
                      ") from the centre; expected a stringer offset, floor height or column "
                      "position that keeps them apart");
      }
    });
  return out;
}

}  // namespace slamsph
