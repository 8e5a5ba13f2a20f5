#include "geometry/polygon_lattice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/cell_grid.h"

namespace slamsph {

bool point_in_polygon(Vec2 p, const std::vector<Vec2>& v) {
  bool inside = false;
  const std::size_t n = v.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = v[i], b = v[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double xc = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < xc) inside = !inside;
    }
  }
  return inside;
}

double polygon_area(const std::vector<Vec2>& v) {
  double s = 0.0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) s += cross(v[j], v[i]);
  return 0.5 * std::abs(s);
}

double polygon_boundary_distance(Vec2 p, const std::vector<Vec2>& v) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
    const Vec2 e = v[i] - v[j];
    const double s = std::clamp(dot(p - v[j], e) / norm2(e), 0.0, 1.0);
    best = std::min(best, norm(p - (v[j] + s * e)));
  }
  return best;
}

namespace {

double signed_area(const std::vector<Vec2>& v) {
  double s = 0.0;
  for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) s += cross(v[j], v[i]);
  return 0.5 * s;
}

struct Bounds {
  Vec2 lo, hi;
};

Bounds bounds(const std::vector<Vec2>& v) {
  Vec2 lo = v[0], hi = v[0];
  for (const Vec2& p : v) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  return {lo, hi};
}

// Cell centres of the dx lattice over the bounding box that `keep` accepts.
template <class Keep>
std::vector<Vec2> lattice_points(const std::vector<Vec2>& v, double dx, Keep keep) {
  const Bounds b = bounds(v);
  const long nx = std::lround(std::ceil((b.hi.x - b.lo.x) / dx - 1e-9));
  const long ny = std::lround(std::ceil((b.hi.y - b.lo.y) / dx - 1e-9));
  std::vector<Vec2> out;
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      const Vec2 p{b.lo.x + (static_cast<double>(i) + 0.5) * dx,
                   b.lo.y + (static_cast<double>(j) + 0.5) * dx};
      if (keep(p)) out.push_back(p);
    }
  return out;
}

// Face layers (header, step 1) of a counter-clockwise polygon.
void face_layers(const std::vector<Vec2>& v, double dx, int layers, ParticleLattice& out) {
  const std::size_t n = v.size();
  const double eps = 1e-9 * dx;
  auto tangent = [&](std::size_t i) {
    return (v[(i + 1) % n] - v[i]) / norm(v[(i + 1) % n] - v[i]);
  };
  auto inward = [](Vec2 t) { return Vec2{-t.y, t.x}; };  // left of a CCW edge
  // Interior angle at vertex i (between edge i−1 and edge i), in (0, 2π).
  auto interior_angle = [&](std::size_t i) {
    const Vec2 a = tangent((i + n - 1) % n), b = tangent(i);
    return std::numbers::pi - std::atan2(cross(a, b), dot(a, b));
  };
  auto keep = [&](Vec2 p, double d) {
    return point_in_polygon(p, v) && polygon_boundary_distance(p, v) >= d - eps;
  };
  for (int k = 0; k < layers; ++k) {
    const double d = (k + 0.5) * dx;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = v[i], b = v[(i + 1) % n], t = tangent(i), nn = inward(t);
      const double len = norm(b - a);
      const double th0 = interior_angle(i), th1 = interior_angle((i + 1) % n);
      const double t0 = th0 < std::numbers::pi ? d / std::tan(0.5 * th0) : 0.0;
      const double t1 = th1 < std::numbers::pi ? d / std::tan(0.5 * th1) : 0.0;
      const double ell = len - t0 - t1;
      const long m = ell > 0.0 ? std::max(1L, std::lround(ell / dx)) : 0;
      const std::size_t first = out.size();
      for (long j = 0; j < m; ++j) {
        const Vec2 p = a + (t0 + (j + 0.5) * ell / m) * t + d * nn;
        if (keep(p, d)) out.add(p, ell / m * dx, k);  // else another face is nearer
      }
      // Reflex sector at the edge's end vertex b (between this edge's and the next one's
      // normals), centred on b with radius d.
      if (th1 > std::numbers::pi + 1e-12) {
        const double phi = th1 - std::numbers::pi;
        const double sector = phi * (k + 0.5) * dx * dx;
        const long ms = std::lround(phi * (k + 0.5));
        const double a0 = std::atan2(nn.y, nn.x);  // rotate clockwise from this edge's normal
        if (ms > 0) {
          for (long j = 0; j < ms; ++j) {
            const double ang = a0 - (j + 0.5) * phi / ms;
            const Vec2 p = b + d * Vec2{std::cos(ang), std::sin(ang)};
            if (keep(p, d)) out.add(p, sector / ms, k);
          }
        } else if (out.size() > first) {
          out.volume.back() += sector;  // this edge's last particle (else: the residual)
        }
      }
    }
  }
}

// Clean-up (header, step 3): merge particles closer than `gap` into the earlier kept one.
ParticleLattice merge_close(const ParticleLattice& in, double gap) {
  CellGrid grid;
  grid.build(in.x, gap);
  std::vector<std::size_t> owner(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) owner[i] = i;
  const double r2 = gap * gap;
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (owner[i] != i) continue;
    grid.for_each_candidate(in.x[i], [&](std::uint32_t j) {
      if (j > i && owner[j] == j && norm2(in.x[j] - in.x[i]) < r2) owner[j] = i;
    });
  }
  ParticleLattice out;
  std::vector<std::size_t> slot(in.size());
  for (std::size_t i = 0; i < in.size(); ++i)
    if (owner[i] == i) {
      slot[i] = out.size();
      out.add(in.x[i], in.volume[i], in.layer[i]);
    }
  for (std::size_t i = 0; i < in.size(); ++i)
    if (owner[i] != i) out.volume[slot[owner[i]]] += in.volume[i];
  return out;
}

ParticleLattice face_fill(const std::vector<Vec2>& vertices, double dx, int layers) {
  if (layers < 1) throw std::invalid_argument("polygon: face_layers must be >= 1");
  const double area = polygon_area(vertices);
  std::vector<Vec2> v = vertices;
  if (signed_area(v) < 0.0) std::reverse(v.begin(), v.end());

  ParticleLattice laid;
  face_layers(v, dx, layers, laid);
  // Interior lattice (header, step 2).
  const double inner = layers * dx - 1e-9 * dx;
  const std::vector<Vec2> interior = lattice_points(v, dx, [&](Vec2 p) {
    return point_in_polygon(p, v) && polygon_boundary_distance(p, v) >= inner;
  });
  const double residual = area - laid.total_volume();
  if (!interior.empty()) {
    for (const Vec2& p : interior) laid.add(p, residual / static_cast<double>(interior.size()));
  } else if (laid.size() > 0) {
    const double s = area / laid.total_volume();
    for (double& vol : laid.volume) vol *= s;
  }
  return merge_close(laid, kFaceFillMinGap * dx);
}

}  // namespace

ParticleLattice polygon(const std::vector<Vec2>& vertices, double dx, PolygonFill fill,
                        int face_layers_count) {
  if (vertices.size() < 3) throw std::invalid_argument("polygon: need at least 3 vertices");
  if (!(dx > 0.0)) throw std::invalid_argument("polygon: dx must be > 0");
  if (!(polygon_area(vertices) > 0.0)) throw std::invalid_argument("polygon: zero area");
  if (fill == PolygonFill::Faces) return face_fill(vertices, dx, face_layers_count);
  ParticleLattice out;
  for (const Vec2& p :
       lattice_points(vertices, dx, [&](Vec2 q) { return point_in_polygon(q, vertices); }))
    out.add(p, dx * dx);
  return out;
}

}  // namespace slamsph
