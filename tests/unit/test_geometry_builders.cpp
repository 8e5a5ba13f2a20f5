// Geometry builders: counts, total volumes against the analytic areas, arc spacing, wall
// placement and no duplicate points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

TEST(GeometryPolygon, RectangleExactTriangleConverges) {
  const std::vector<Vec2> sq{{0, 0}, {0.2, 0}, {0.2, 0.1}, {0, 0.1}};
  const ParticleLattice r = polygon(sq, 0.01);
  EXPECT_EQ(r.size(), 200u);
  EXPECT_NEAR(r.total_volume(), 0.02, 1e-14);
  // Clockwise triangle, area 0.5 * 0.3 * 0.2 = 0.03: lattice area within 2 % at dx = 2 mm.
  const std::vector<Vec2> tri{{0, 0}, {0.1, 0.2}, {0.3, 0}};
  EXPECT_NEAR(polygon_area(tri), 0.03, 1e-15);
  const ParticleLattice t = polygon(tri, 0.002);
  EXPECT_NEAR(t.total_volume(), 0.03, 0.02 * 0.03);
  for (const Vec2& q : t.x) EXPECT_TRUE(point_in_polygon(q, tri));
  EXPECT_NEAR(min_pair_distance(t.x, 0.004), 0.002, 1e-12);
}

// Face fill (geometry/polygon_lattice.h, PolygonFill::Faces) on a rectangle, a clockwise
// triangle, the 30-degree wedge of cases/wedge_constant_speed.toml and a chevron (one reflex
// vertex): volumes sum to the exact area, every particle is inside at >= dx/2 from the
// boundary, no pair is closer than kFaceFillMinGap dx, every volume is positive and below
// 2.5 dx^2, and the surface layer lies on the lines parallel to the faces at dx/2.
TEST(GeometryPolygonFaces, ExactAreaInsideMinimumGap) {
  const double dx = 0.005;
  const std::vector<std::vector<Vec2>> shapes{
      {{0, 0}, {0.2, 0}, {0.2, 0.1}, {0, 0.1}},
      {{0, 0}, {0.1, 0.2}, {0.3, 0}},
      {{0.4, 0.415}, {0.5, 0.472735}, {0.5, 0.535}, {0.3, 0.535}, {0.3, 0.472735}},
      {{0, 0}, {0.1, 0.06}, {0.2, 0}, {0.2, 0.1}, {0.1, 0.16}, {0, 0.1}}};
  for (const auto& v : shapes) {
    const ParticleLattice p = polygon(v, dx, PolygonFill::Faces);
    const double a = polygon_area(v);
    EXPECT_NEAR(p.total_volume(), a, 1e-12 * a);
    EXPECT_GE(min_pair_distance(p.x, 2 * dx), kFaceFillMinGap * dx);
    std::size_t surface = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      EXPECT_TRUE(point_in_polygon(p.x[i], v));
      EXPECT_GE(polygon_boundary_distance(p.x[i], v), 0.5 * dx * (1 - 1e-9));
      EXPECT_GT(p.volume[i], 0.0);
      EXPECT_LT(p.volume[i], 2.5 * dx * dx);  // merged corner particles: up to 2.01 dx^2
      if (p.layer[i] == 0) {
        ++surface;
        EXPECT_NEAR(polygon_boundary_distance(p.x[i], v), 0.5 * dx, 1e-9 * dx);
      }
    }
    // Surface particles: about one per dx of perimeter (corners trim a few).
    double perimeter = 0.0;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) perimeter += norm(v[i] - v[j]);
    EXPECT_NEAR(static_cast<double>(surface), perimeter / dx, 0.1 * perimeter / dx);
  }
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
