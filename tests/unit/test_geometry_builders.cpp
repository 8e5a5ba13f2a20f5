// Geometry builders: counts, total volumes against the analytic areas, arc spacing, wall
// placement and no duplicate points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <set>

#include "core/cell_grid.h"
#include "geometry/geometry.h"

using namespace slamsph;

namespace {

// Smallest pair distance (cell list over a radius r_max; returns r_max if none closer).
double min_pair_distance(const std::vector<Vec2>& x, double r_max) {
  CellGrid grid;
  grid.build(x, r_max);
  double best = r_max;
  for (std::size_t i = 0; i < x.size(); ++i)
    grid.for_each_candidate(x[i], [&](std::uint32_t j) {
      if (j != i) best = std::min(best, norm(x[i] - x[j]));
    });
  return best;
}

// Arc spacing per layer: arc length r_k Δθ between angularly consecutive particles of each
// layer (for the disc's 3-particle centre layer the chord is 0.866 t, the arc 1.047 t).
void arc_spacing_band(const ParticleLattice& p, Vec2 c, double& lo, double& hi) {
  lo = std::numeric_limits<double>::max();
  hi = 0.0;
  const int nl = *std::max_element(p.layer.begin(), p.layer.end()) + 1;
  for (int k = 0; k < nl; ++k) {
    std::vector<double> ang;
    double r = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.layer[i] == k) {
        ang.push_back(std::atan2(p.x[i].y - c.y, p.x[i].x - c.x));
        r = norm(p.x[i] - c);
      }
    std::sort(ang.begin(), ang.end());
    for (std::size_t i = 0; i < ang.size(); ++i) {
      double d = (i + 1 < ang.size() ? ang[i + 1] : ang[0] + 2 * std::numbers::pi) - ang[i];
      lo = std::min(lo, r * d);
      hi = std::max(hi, r * d);
    }
  }
}

}  // namespace

TEST(GeometryBox, CountVolumeAndCellCentres) {
  const double dx = 0.01;
  const Box b{{-0.2, 0.1}, {0.3, 0.4}};  // 50 x 30 cells
  const ParticleLattice p = fill_box(b, dx);
  ASSERT_EQ(p.size(), 1500u);
  EXPECT_NEAR(p.total_volume(), 0.5 * 0.3, 1e-12);
  double xmin = 1e9, ymax = -1e9;
  for (const Vec2& q : p.x) {
    xmin = std::min(xmin, q.x);
    ymax = std::max(ymax, q.y);
    EXPECT_TRUE(q.x > b.min.x && q.x < b.max.x && q.y > b.min.y && q.y < b.max.y);
  }
  EXPECT_NEAR(xmin, b.min.x + 0.5 * dx, 1e-12);
  EXPECT_NEAR(ymax, b.max.y - 0.5 * dx, 1e-12);
  EXPECT_NEAR(min_pair_distance(p.x, 2 * dx), dx, 1e-12);
  EXPECT_TRUE(std::all_of(p.layer.begin(), p.layer.end(), [](int l) { return l == -1; }));
}

TEST(GeometryBox, NonMultipleSideRoundsCountAndStillCoversBox) {
  const Box b{{0.0, 0.0}, {0.146, 0.292}};  // 29.2 x 58.4 cells at dx = 5 mm
  const ParticleLattice p = fill_box(b, 0.005);
  EXPECT_EQ(p.size(), 29u * 58u);
  EXPECT_NEAR(p.total_volume(), 0.146 * 0.292, 1e-13);
}

TEST(GeometryTank, WallsOutsideInnerBoxAndSurfaceAtBoundary) {
  const double dx = 0.01;
  const int L = 3;
  const Box in{{0.0, 0.0}, {1.0, 0.4}};  // 100 x 40 cells
  for (bool open_top : {true, false}) {
    const ParticleLattice p = tank_walls(in, dx, L, open_top);
    // Band area between the inner box and the box grown by L dx (no lid band if open).
    const double W = 1.0 + 2 * L * dx, H = 0.4 + (open_top ? 1 : 2) * L * dx;
    const double band = W * H - 1.0 * 0.4;
    EXPECT_NEAR(p.total_volume(), band, 1e-12) << open_top;
    const std::size_t expect =
        open_top ? (106u * 3u + 2u * 3u * 40u) : (2u * 106u * 3u + 2u * 3u * 40u);
    EXPECT_EQ(p.size(), expect);
    double gap_bottom = 1e9, gap_left = 1e9, gap_right = 1e9, gap_top = 1e9;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 q = p.x[i];
      const bool inside = q.x > in.min.x && q.x < in.max.x && q.y > in.min.y && q.y < in.max.y;
      EXPECT_FALSE(inside);
      if (q.x > in.min.x && q.x < in.max.x) {
        if (q.y < in.min.y) gap_bottom = std::min(gap_bottom, in.min.y - q.y);
        if (q.y > in.max.y) gap_top = std::min(gap_top, q.y - in.max.y);
      }
      if (q.y > in.min.y && q.y < in.max.y) {
        if (q.x < in.min.x) gap_left = std::min(gap_left, in.min.x - q.x);
        if (q.x > in.max.x) gap_right = std::min(gap_right, q.x - in.max.x);
      }
      EXPECT_GE(p.layer[i], 0);
      EXPECT_LT(p.layer[i], L);
    }
    // Innermost particles half a spacing off the inner box: the wall surface (cell faces)
    // is exactly the inner box boundary.
    EXPECT_NEAR(gap_bottom, 0.5 * dx, 1e-12);
    EXPECT_NEAR(gap_left, 0.5 * dx, 1e-12);
    EXPECT_NEAR(gap_right, 0.5 * dx, 1e-12);
    if (!open_top)
      EXPECT_NEAR(gap_top, 0.5 * dx, 1e-12);
    else
      EXPECT_EQ(gap_top, 1e9);
    EXPECT_NEAR(min_pair_distance(p.x, 2 * dx), dx, 1e-12);
  }
}

TEST(GeometryTank, CornersFilled) {
  const double dx = 0.1;
  const ParticleLattice p = tank_walls({{0, 0}, {1, 1}}, dx, 2, false);
  // Every cell of the 14 x 14 outer grid outside the 10 x 10 inner box is present once.
  std::set<std::pair<long, long>> cells;
  for (const Vec2& q : p.x)
    cells.insert({std::lround(q.x / dx - 0.5), std::lround(q.y / dx - 0.5)});
  EXPECT_EQ(cells.size(), p.size());
  EXPECT_EQ(p.size(), 14u * 14u - 100u);
  EXPECT_TRUE(cells.count({-2, -2}) && cells.count({11, 11}) && cells.count({-1, 10}));
}

TEST(GeometryDisc, VolumeEqualsPiR2AndOuterEdgeAtR) {
  const double R = 0.1, dx = 0.005;  // 20 layers
  const Vec2 c{0.5, 0.55};
  const ParticleLattice p = disc(c, R, dx);
  EXPECT_NEAR(p.total_volume(), std::numbers::pi * R * R, 1e-14);
  // Particle count close to the area / dx^2 (within 1 %).
  EXPECT_NEAR(static_cast<double>(p.size()), std::numbers::pi * R * R / (dx * dx),
              0.01 * std::numbers::pi * R * R / (dx * dx));
  double rmax = 0.0;
  for (const Vec2& q : p.x) rmax = std::max(rmax, norm(q - c));
  EXPECT_NEAR(rmax, R - 0.5 * dx, 1e-12);  // outer layer's outer edge at R
  EXPECT_EQ(*std::max_element(p.layer.begin(), p.layer.end()), 19);
  double lo, hi;
  arc_spacing_band(p, c, lo, hi);
  // Arc spacing band: chord between consecutive particles within [0.9, 1.1] dx.
  EXPECT_GT(lo, 0.9 * dx);
  EXPECT_LT(hi, 1.1 * dx);
  EXPECT_GT(min_pair_distance(p.x, 2 * dx), 0.5 * dx);
}

TEST(GeometryDisc, RadiusNotMultipleOfDx) {
  const double R = 0.0123, dx = 0.001;  // 12 layers of 1.025 mm
  const ParticleLattice p = disc({0, 0}, R, dx);
  EXPECT_NEAR(p.total_volume(), std::numbers::pi * R * R, 1e-15);
  double rmax = 0.0;
  for (const Vec2& q : p.x) rmax = std::max(rmax, norm(q));
  EXPECT_NEAR(rmax, R - 0.5 * R / 12, 1e-12);
}

TEST(GeometryRing, ThinSkinAlignedLayers) {
  // Fuselage skin: D = 600 mm, t = 3 mm, 2 layers (1.5 mm).
  const double ro = 0.3, ri = 0.297;
  const Vec2 c{1.5, 2.5};
  const ParticleLattice p = ring(c, ri, ro, 2);
  EXPECT_NEAR(p.total_volume(), std::numbers::pi * (ro * ro - ri * ri), 1e-15);
  const long n = std::lround(2 * std::numbers::pi * 0.2985 / 0.0015);
  EXPECT_EQ(p.size(), static_cast<std::size_t>(2 * n));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = norm(p.x[i] - c);
    EXPECT_NEAR(r, ri + (p.layer[i] + 0.5) * 0.0015, 1e-12);
  }
  double lo, hi;
  arc_spacing_band(p, c, lo, hi);
  EXPECT_GT(lo, 0.95 * 0.0015);
  EXPECT_LT(hi, 1.05 * 0.0015);
  EXPECT_GT(min_pair_distance(p.x, 0.003), 0.5 * 0.0015);
}

TEST(GeometryRing, ThickRingPerLayerCounts) {
  const double ri = 0.02, ro = 0.1;
  const ParticleLattice p = ring({0, 0}, ri, ro, 16);  // t = 5 mm, far from thin
  EXPECT_NEAR(p.total_volume(), std::numbers::pi * (ro * ro - ri * ri), 1e-15);
  for (int k : {0, 15})
    EXPECT_EQ(std::count(p.layer.begin(), p.layer.end(), k),
              std::lround(2 * std::numbers::pi * (ri + (k + 0.5) * 0.005) / 0.005));
  double lo, hi;
  arc_spacing_band(p, {0, 0}, lo, hi);
  EXPECT_GT(lo, 0.9 * 0.005);
  EXPECT_LT(hi, 1.1 * 0.005);
  EXPECT_GT(min_pair_distance(p.x, 0.01), 0.5 * 0.005);
}

// Face-laid polygon lattice (geometry/polygon_lattice.h). Checks per polygon: volumes sum
// to the area; surface (layer 0) particles exactly dx/2 from the boundary; along every edge
// of length >= 10 dx consecutive surface particles 0.9–1.1 dx apart; no pair closer than
// dx/2; interior volumes within 25 % of dx²; every particle inside. The old Cartesian fill
// fails the surface check on any sloped face (its surface cells sit 0–dx/2 off the face).
void check_face_laid(const std::vector<Vec2>& poly, double dx, const char* name) {
  const ParticleLattice p = polygon(poly, dx);
  const double area = polygon_area(poly);
  EXPECT_NEAR(p.total_volume(), area, 1e-12 * area) << name;
  const std::size_t n = poly.size();
  double worst_offset = 0.0, gap_lo = 1e9, gap_hi = 0.0, v_lo = 1e9, v_hi = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_TRUE(point_in_polygon(p.x[i], poly)) << name << " particle " << i;
    if (p.layer[i] == 0)
      worst_offset =
          std::max(worst_offset, std::abs(polygon_boundary_distance(p.x[i], poly) - 0.5 * dx));
    if (p.layer[i] == -1) {
      v_lo = std::min(v_lo, p.volume[i] / (dx * dx));
      v_hi = std::max(v_hi, p.volume[i] / (dx * dx));
    }
  }
  for (std::size_t e = 0; e < n; ++e) {
    const Vec2 a = poly[e], b = poly[(e + 1) % n];
    const double len = norm(b - a);
    if (len < 10 * dx) continue;
    const Vec2 t = (b - a) / len;
    std::vector<double> s;  // surface particles of this edge, by arc position
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.layer[i] == 0 && std::abs(std::abs(cross(t, p.x[i] - a)) - 0.5 * dx) < 1e-9 * dx &&
          dot(p.x[i] - a, t) > 0.0 && dot(p.x[i] - a, t) < len)
        s.push_back(dot(p.x[i] - a, t));
    std::sort(s.begin(), s.end());
    ASSERT_GT(s.size(), 5u) << name << " edge " << e;
    for (std::size_t k = 1; k < s.size(); ++k) {
      gap_lo = std::min(gap_lo, (s[k] - s[k - 1]) / dx);
      gap_hi = std::max(gap_hi, (s[k] - s[k - 1]) / dx);
    }
  }
  const double dmin = min_pair_distance(p.x, 2 * dx) / dx;
  std::printf(
      "[polygon] %s: %zu particles, volume error %.1e, surface offset error %.1e dx, "
      "surface spacing %.3f..%.3f dx, min distance %.3f dx, interior volume %.3f..%.3f dx^2\n",
      name, p.size(), p.total_volume() / area - 1.0, worst_offset / dx, gap_lo, gap_hi, dmin, v_lo,
      v_hi);
  EXPECT_LT(worst_offset, 1e-9 * dx) << name;
  EXPECT_GE(gap_lo, 0.9) << name;
  EXPECT_LE(gap_hi, 1.1) << name;
  EXPECT_GE(dmin, 0.5) << name;
  if (v_hi > 0.0) {
    EXPECT_GT(v_lo, 0.75) << name;
    EXPECT_LT(v_hi, 1.25) << name;
  }
}

TEST(GeometryPolygon, FaceLaidLattice) {
  // Axis-aligned rectangle: 200 particles of dx² (the face strips tile it exactly).
  const std::vector<Vec2> sq{{0, 0}, {0.2, 0}, {0.2, 0.1}, {0, 0.1}};
  const ParticleLattice r = polygon(sq, 0.01);
  EXPECT_EQ(r.size(), 200u);
  EXPECT_NEAR(r.total_volume(), 0.02, 1e-14);
  check_face_laid(sq, 0.01, "rectangle");
  // Clockwise triangle, area 0.5 * 0.3 * 0.2 = 0.03 (corners 56°, 34°, 90°).
  const std::vector<Vec2> tri{{0, 0}, {0.1, 0.2}, {0.3, 0}};
  EXPECT_NEAR(polygon_area(tri), 0.03, 1e-15);
  check_face_laid(tri, 0.002, "triangle");
  // A 10° deadrise wedge 0.3 m wide (keel corner 160°, knuckles 10°+90°).
  const double h = 0.15 * std::tan(10.0 * std::numbers::pi / 180.0);
  const std::vector<Vec2> wedge{{0, 0}, {0.15, h}, {0.15, h + 0.05}, {-0.15, h + 0.05}, {-0.15, h}};
  check_face_laid(wedge, 0.0025, "wedge");
  // Non-convex chevron (a reflex vertex of 240° at the notch).
  const std::vector<Vec2> chev{
      {0, 0}, {0.2, 0}, {0.2, 0.1}, {0.1, 0.1 - 0.1 / std::sqrt(3.0)}, {0, 0.1}};
  check_face_laid(chev, 0.004, "chevron");
}

TEST(GeometryBuildShape, DispatchMatchesBuilders) {
  ShapeConfig s;
  s.type = "tank";
  s.box = {{0, 0}, {1, 0.5}};
  EXPECT_EQ(build_shape(s, 0.05).size(), tank_walls(s.box, 0.05, 4, true).size());
  const Box bb = shape_bounds(s, 0.05);
  EXPECT_NEAR(bb.min.x, -0.2, 1e-15);
  EXPECT_NEAR(bb.max.y, 0.5, 1e-15);
  s.type = "ring";
  s.centre = {0, 0};
  s.inner_radius = 0.1;
  s.outer_radius = 0.12;
  EXPECT_EQ(build_shape(s, 0.005).size(), ring({0, 0}, 0.1, 0.12, 4).size());
  s.type = "disc";
  s.radius = 0.05;
  EXPECT_EQ(build_shape(s, 0.01).size(), disc({0, 0}, 0.05, 0.01).size());
  s.type = "hexagon";
  EXPECT_THROW(build_shape(s, 0.01), std::invalid_argument);
}
