// Polygon face fill (geometry/polygon_lattice.h) as the rest of the code sees it: the
// contact's surface normals on a sloped face, and the TL-SFPM gradient weights of both fills
// (the parser's default and refusal of `[body.shape] fill`: tests/unit/test_io_case_errors.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/kernel.h"
#include "core/parallel.h"
#include "coupling/surface_normals.h"
#include "geometry/polygon_lattice.h"
#include "solid/solid_topology.h"

using namespace slamsph;

// The colour-gradient normals the contact uses (coupling/surface_normals.h) on the wedge's
// sloped faces: with the face fill every surface particle farther than 3 dx from a vertex
// has the face's outward normal to 1 degree; the Cartesian staircase tilts some by more
// than 10 degrees (the force ripple of docs/validation.md "Wedge entry").
TEST(GeometryPolygonFaces, SurfaceNormalsMatchTheSlopedFace) {
  const double dx = 0.005;
  const std::vector<Vec2> w{
      {0.4, 0.415}, {0.5, 0.472735}, {0.5, 0.535}, {0.3, 0.535}, {0.3, 0.472735}};
  const Kernel kernel(KernelType::WendlandC2, 1.38 * dx);
  auto worst_deg = [&](PolygonFill fill, std::size_t& counted) {
    const ParticleLattice p = polygon(w, dx, fill);
    const std::vector<Vec2> n = reference_surface_normals(p.x, p.volume, kernel);
    double worst = 0.0;
    counted = 0;
    for (int side : {0, 1}) {  // edges apex -> right knuckle, left knuckle -> apex
      const Vec2 a = side == 0 ? w[0] : w[4], b = side == 0 ? w[1] : w[0];
      const Vec2 t = (b - a) / norm(b - a), out{t.y, -t.x};  // outward: right of a CCW edge
      for (std::size_t i = 0; i < p.size(); ++i) {
        const double s = dot(p.x[i] - a, t), d = -dot(p.x[i] - a, out);
        if (s < 3 * dx || s > norm(b - a) - 3 * dx || d > 0.75 * dx || d < 0.0) continue;
        ++counted;
        const double c = std::clamp(dot(n[i], out), -1.0, 1.0);
        worst = std::max(worst, std::acos(c) * 180.0 / std::numbers::pi);
      }
    }
    return worst;
  };
  std::size_t nf = 0, nc = 0;
  const double faces = worst_deg(PolygonFill::Faces, nf),
               cart = worst_deg(PolygonFill::Cartesian, nc);
  std::printf(
      "worst surface-normal error on the wedge faces: faces %.3g deg (%zu particles), "
      "cartesian %.3g deg (%zu)\n",
      faces, nf, cart, nc);
  EXPECT_GT(nf, 30u);
  EXPECT_LT(faces, 1.0);
  EXPECT_GT(cart, 10.0);
}

// Why the parser refuses fill = "faces" for elastic bodies (docs/model.md §3 "Polygon
// bodies"): the TL-SFPM topology of the wedge from the face fill has larger gradient weights
// (max |g_ij| dx, which divides the solid stable step, solid/body_dynamics.h) than the
// Cartesian lattice's, which stays at the regular-lattice bound 1.
TEST(PolygonFaces, TlSfpmGradientWeightsOfBothFills) {
  const double dx = 0.005;
  const std::vector<Vec2> w{
      {0.4, 0.415}, {0.5, 0.472735}, {0.5, 0.535}, {0.3, 0.535}, {0.3, 0.472735}};
  Executor serial(1);
  auto max_g = [&](PolygonFill fill) {
    const ParticleLattice p = polygon(w, dx, fill);
    TopologySpec spec;
    spec.dx = dx;
    spec.kernel = Kernel(KernelType::WendlandC2, 1.38 * dx);
    return build_solid_topology(p.x, p.volume, spec, serial).max_gradient * dx;
  };
  const double cart = max_g(PolygonFill::Cartesian), faces = max_g(PolygonFill::Faces);
  std::printf("TL-SFPM max |g_ij| dx on the wedge: cartesian %.3f, faces %.3f\n", cart, faces);
  EXPECT_LE(cart, 1.0 + 1e-12);
}
