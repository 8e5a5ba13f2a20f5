// Contact with a body finer than the water (docs/model.md §4, "Bodies finer than the water";
// issue 10 item 2): a two-layer skin at 1/r of the water's spacing, r = 1, 2, 4, 8, with its
// ghost layers (coupling/ghost_layers.h) and water on both sides.
//  - the kernel support of a water particle next to the skin is complete on each side:
//    sum over water and facing contact particles of V grad W vanishes (the condition for
//    a uniform pressure to exert no force; without it the water is pushed into the skin);
//  - the number of ghosts per surface particle stays at most 5, not r times more (the
//    ghost cells are half a water spacing deep);
//  - momentum exchange is exact at every ratio: the summed contact force on the water is
//    minus the force the body receives, ghosts' forces returned to their parents.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "core/cell_grid.h"
#include "core/parallel.h"
#include "coupling/contact_layout.h"
#include "coupling/contact_rates.h"
#include "coupling/surface_normals.h"
#include "coupling/virtual_pressure.h"

using namespace slamsph;

namespace {

constexpr double kDx = 0.01;   // water spacing
constexpr double kL = 0.4;     // skin length
constexpr double kHoDx = 1.3;  // h / dx, water and body

struct Lcg {
  std::uint64_t s;
  double next() {  // in [-1, 1)
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-52 - 1.0;
  }
};

// A horizontal rigid skin of two layers at spacing kDx / r, top face at y = 0.
SolidBody skin(int r) {
  const double d = kDx / r;
  SolidBody b;
  b.name = "skin";
  b.kind = BodyKind::RigidFixed;
  b.dx = d;
  b.kernel = Kernel(KernelType::WendlandC2, kHoDx * d);
  const int nx = static_cast<int>(std::lround(kL / d));
  for (int l = 0; l < 2; ++l)
    for (int i = 0; i < nx; ++i) b.X.push_back({(i + 0.5) * d, -(l + 0.5) * d});
  const std::size_t n = b.X.size();
  b.x = b.X;
  b.V0.assign(n, d * d);
  b.rho0.assign(n, 2700.0);
  b.m.assign(n, 2700.0 * d * d);
  b.v.assign(n, Vec2{});
  b.a.assign(n, Vec2{});
  b.f_fluid.assign(n, Vec2{});
  b.clamped.assign(n, 0);
  b.layer.assign(n, -1);
  return b;
}

// Water above the skin (rows above y = 0) and/or below it (below y = -2d), the first row half
// a water spacing off the face (as the case builder places it).
FluidParticles water(int r, int rows, bool above, bool below) {
  const double d = kDx / r;
  FluidParticles f;
  const int nx = static_cast<int>(std::lround(kL / kDx));
  for (int side = 0; side < 2; ++side) {
    if (!(side == 0 ? above : below)) continue;
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < nx; ++i) {
        f.resize(f.size() + 1);
        const std::size_t k = f.size() - 1;
        const double y = (j + 0.5) * kDx;
        f.x[k] = {(i + 0.5) * kDx, side == 0 ? y : -2.0 * d - y};
        f.rho[k] = 1000.0;
        f.m[k] = 1000.0 * kDx * kDx;
      }
  }
  return f;
}

struct SkinSetup {
  SolidBody body;
  ContactLayout layout;
  ContactParticles contact;
  FluidParticles fluid;
  Kernel kc{KernelType::WendlandC2, kHoDx* kDx};  // contact kernel: the water's h
  NeighbourList fc, cf;

  SkinSetup(int r, int rows, bool ghosts, bool above = true, bool below = true)
      : body(skin(r)), fluid(water(r, rows, above, below)) {
    std::vector<std::vector<Vec2>> normals{reference_surface_normals(body.X, body.V0, body.kernel)};
    layout = plan_contact_layout({body}, normals, ghosts ? kc.support() : 0.0, kDx);
    init_contact_particles(contact, layout);
    gather_body_state(contact, layout, std::vector<SolidBody>{body});
    const Executor exec(1);
    CellGrid gf, gc;
    gf.build(fluid.x, kc.support());
    gc.build(contact.x, kc.support());
    build_neighbour_list(fluid.x, contact.x, gc, kc.support(), false, exec, fc);
    build_neighbour_list(contact.x, fluid.x, gf, kc.support(), false, exec, cf);
  }

  // sum over water j != i and facing contact particles s of V grad_i W, times h.
  Vec2 support_deficit(std::size_t i) const {
    Vec2 g;
    for (std::size_t j = 0; j < fluid.size(); ++j) {
      const Vec2 d = fluid.x[i] - fluid.x[j];
      const double r2 = norm2(d);
      if (j == i || r2 >= kc.support() * kc.support()) continue;
      g += (fluid.m[j] / fluid.rho[j] * kc.dw_over_r(std::sqrt(r2))) * d;
    }
    for (std::uint32_t k = fc.start[i]; k < fc.start[i + 1]; ++k) {
      const std::uint32_t s = fc.index[k];
      if (!contact.faces(s, fluid.x[i])) continue;
      const Vec2 d = fluid.x[i] - contact.x[s];
      const double r2 = norm2(d);
      if (r2 >= kc.support() * kc.support()) continue;
      g += (contact.volume[s] * kc.dw_over_r(std::sqrt(r2))) * d;
    }
    return kc.h() * g;
  }
};

// Index of the water particle nearest to p.
std::size_t nearest(const FluidParticles& f, Vec2 p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < f.size(); ++i)
    if (norm2(f.x[i] - p) < norm2(f.x[best] - p)) best = i;
  return best;
}

}  // namespace

TEST(CouplingSpacingRatio, KernelSupportCompleteOnEachSideOfAThinSkin) {
  for (int r : {1, 2, 4, 8}) {
    const double d = kDx / r;
    // Water on one side at a time (the other side dry): the ghosts complete the support.
    const SkinSetup up(r, 4, true, true, false), down(r, 4, true, false, true);
    const SkinSetup up_bare(r, 4, false, true, false);
    // Water particles in the first row above and below, mid-span.
    const std::size_t above = nearest(up.fluid, {0.205, 0.5 * kDx});
    const std::size_t below = nearest(down.fluid, {0.205, -2.0 * d - 0.5 * kDx});
    const Vec2 ga = up.support_deficit(above), gb = down.support_deficit(below);
    const Vec2 na = up_bare.support_deficit(above);
    // Ghosts per surface particle (every particle of a two-layer skin is on a surface).
    const double per_surface =
        static_cast<double>(up.layout.ghosts.size()) / static_cast<double>(up.body.size());
    std::printf(
        "r = %d: h sum V grad W above (%.2e, %.2e), below (%.2e, %.2e); without ghosts "
        "(%.3f, %.3f); %zu ghosts = %.2f per surface particle\n",
        r, ga.x, ga.y, gb.x, gb.y, na.x, na.y, up.layout.ghosts.size(), per_surface);
    // Measured |sum| h: 0 (r = 1), 0.0096, 0.017, 0.015 (r = 2, 4, 8); with one ghost per
    // body layer 0.0096, 0.013, 0.014; without ghosts 0, 0.077, 0.29, 0.44.
    EXPECT_LT(norm(ga), 0.025) << "r = " << r;
    EXPECT_LT(norm(gb), 0.025) << "r = " << r;
    // At r = 1 the ghosts lie beyond a first-row particle's support (they act on water
    // pressed closer); at r >= 2 the skin is thinner than the support and without them
    // the sum points away from the skin.
    if (r >= 2) {
      EXPECT_GT(norm(na), 0.05) << "r = " << r;
    }
    // Ghost cells half a water spacing deep: at most 5 per surface particle at every ratio
    // (20 at r = 8 with one ghost per missing body layer).
    EXPECT_LE(per_surface, 5.0) << "r = " << r;
  }
}

namespace {

void expect_exact_exchange(int r, double viscosity) {
  SkinSetup s(r, 5, true);
  Lcg rng{static_cast<std::uint64_t>(7 + r)};
  for (std::size_t i = 0; i < s.fluid.size(); ++i) {
    s.fluid.x[i] += Vec2{0.2 * kDx * rng.next(), 0.1 * kDx * rng.next()};
    s.fluid.v[i] = {0.5 * rng.next(), 0.5 * rng.next()};
    s.fluid.rho[i] = 1000.0 * (1.0 + 0.01 * rng.next());
    s.fluid.p[i] = 2.0e3 * (1.0 + rng.next());
  }
  // Keep the water off the skin after the jitter (half a water spacing from its faces).
  const double d = kDx / r;
  for (Vec2& x : s.fluid.x)
    if (x.y > -d)
      x.y = std::max(x.y, 0.3 * kDx);
    else
      x.y = std::min(x.y, -2.0 * d - 0.3 * kDx);
  // A moving skin: velocity and acceleration enter U* and the virtual pressure.
  std::vector<SolidBody> bodies{s.body};
  for (std::size_t i = 0; i < bodies[0].size(); ++i) {
    bodies[0].v[i] = {0.1 * rng.next(), 0.3 + 0.1 * rng.next()};
    bodies[0].a[i] = {0.0, 2.0 * rng.next()};
  }
  bodies[0].kind = BodyKind::RigidPrescribed;
  gather_body_state(s.contact, s.layout, bodies);
  const Executor exec(2);
  CellGrid gf, gc;
  gf.build(s.fluid.x, s.kc.support());
  gc.build(s.contact.x, s.kc.support());
  build_neighbour_list(s.fluid.x, s.contact.x, gc, s.kc.support(), false, exec, s.fc);
  build_neighbour_list(s.contact.x, s.fluid.x, gf, s.kc.support(), false, exec, s.cf);
  const TaitEos eos{1000.0, 25.0, 7.0};
  const Vec2 g{0.0, -9.81};
  compute_virtual_state(s.contact, s.fluid, s.cf, s.kc, eos, g, exec);
  const ContactParams prm{25.0, 3.0, viscosity, g};
  add_contact_to_fluid(s.fluid, s.contact, s.fc, s.kc, prm, exec);
  compute_contact_reaction(s.contact, s.fluid, s.cf, s.kc, prm, exec);
  scatter_contact_forces(s.contact, s.layout, bodies);
  Vec2 on_water, on_body, on_ghosts;
  double scale = 0.0;
  for (std::size_t i = 0; i < s.fluid.size(); ++i) {
    on_water += s.fluid.m[i] * s.fluid.a[i];
    scale += s.fluid.m[i] * norm(s.fluid.a[i]);
  }
  for (const Vec2& fb : bodies[0].f_fluid) on_body += fb;
  for (std::size_t c = s.layout.first_ghost(); c < s.contact.size(); ++c)
    on_ghosts += s.contact.force[c];
  std::printf("r = %d, nu = %g: water %.6e %.6e, body %.6e %.6e (ghosts %.3e %.3e), |sum| %.2e\n",
              r, viscosity, on_water.x, on_water.y, on_body.x, on_body.y, on_ghosts.x, on_ghosts.y,
              norm(on_water + on_body));
  ASSERT_GT(scale, 1.0);
  EXPECT_LT(norm(on_water + on_body), 1e-12 * scale) << "r = " << r;
  // At r >= 2 the ghosts carry a real part of the load, so their return to the parents is
  // tested (at r = 1 they lie beyond the support of this undisturbed water).
  if (r >= 2) {
    EXPECT_GT(norm(on_ghosts), 0.01 * norm(on_body)) << "r = " << r;
  }
}

}  // namespace

TEST(CouplingSpacingRatio, MomentumExchangeExactInviscid) {
  for (int r : {1, 2, 4, 8}) expect_exact_exchange(r, 0.0);
}

TEST(CouplingSpacingRatio, MomentumExchangeExactViscous) {
  for (int r : {1, 2, 4, 8}) expect_exact_exchange(r, 1e-3);
}
