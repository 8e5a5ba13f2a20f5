// Fluid–solid contact (spec §4; coupling/virtual_pressure.h, contact_pair.h, contact_rates.h):
//  - the virtual state of a solid particle against a hand computation, with gravity AND a
//    solid acceleration (its static term), the no-slip velocity, the dry case and a ghost
//    that must ignore fluid behind its surface;
//  - one contact pair's Riemann star state, force and continuity term against the formulas
//    of paper Eqs. 12–13 written out here (not through solve_riemann), including the
//    no-adhesion clip p* >= 0 (today's rule, docs/model.md §4);
//  - action = reaction of the gather-style contact rates on a disordered cloud, with and
//    without viscosity: sum of fluid forces plus sum of solid forces vanishes to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/cell_grid.h"
#include "core/parallel.h"
#include "coupling/contact_pair.h"
#include "coupling/contact_rates.h"
#include "coupling/interaction_lists.h"
#include "coupling/virtual_pressure.h"

using namespace slamsph;

namespace {

constexpr double kH = 0.013;

ContactParticles one_solid(Vec2 x, Vec2 v, Vec2 a) {
  ContactParticles c;
  c.resize(1);
  c.x[0] = x;
  c.v[0] = v;
  c.a[0] = a;
  c.volume[0] = 1e-4;
  return c;
}

NeighbourList all_of(std::size_t nq, std::size_t np) {
  NeighbourList l;
  l.start.push_back(0);
  for (std::size_t i = 0; i < nq; ++i) {
    for (std::size_t j = 0; j < np; ++j) l.index.push_back(static_cast<std::uint32_t>(j));
    l.start.push_back(static_cast<std::uint32_t>(l.index.size()));
  }
  return l;
}

// Deterministic pseudo-random numbers in [-1, 1) (portable, unlike <random> distributions).
struct Lcg {
  std::uint64_t s;
  double next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-52 - 1.0;
  }
};

}  // namespace

TEST(CouplingVirtualPressure, HandComputationWithSolidAcceleration) {
  // Three fluid particles at the same distance r from the solid particle: every kernel
  // weight is the same W(r), so Eq. 12 reduces to plain means:
  //   p'  = mean(p_f) + (g - a_s) . mean(rho_f (x_s - x_f)),
  //   v~  = 2 v_s - mean(v_f).
  const double r = 1.1 * kH;
  const Vec2 xs{0.5, 0.5};
  const Vec2 d[3] = {{0.0, 1.0}, {0.6, 0.8}, {-0.8, 0.6}};  // unit directions s -> f
  FluidParticles f;
  f.resize(3);
  const double p[3] = {1200.0, 900.0, 1500.0}, rho[3] = {1000.5, 1000.2, 1000.9};
  const Vec2 v[3] = {{0.1, -0.2}, {0.3, 0.0}, {-0.1, 0.4}};
  for (int j = 0; j < 3; ++j) {
    f.x[j] = xs + r * d[j];
    f.p[j] = p[j];
    f.rho[j] = rho[j];
    f.v[j] = v[j];
    f.m[j] = rho[j] * 1e-4;
  }
  const Vec2 g{0.0, -9.81}, as{1.5, 5.0}, vs{0.05, 0.2};
  ContactParticles c = one_solid(xs, vs, as);
  const TaitEos eos{1000.0, 30.0, 7.0};
  compute_virtual_state(c, f, all_of(1, 3), Kernel(KernelType::WendlandC2, kH), eos, g,
                        Executor(1));
  // By hand: mean p = 1200; mean rho_f (x_s - x_f) = -r/3 (rho_0 d_0 + rho_1 d_1 + rho_2 d_2)
  //   x: -r/3 (0 + 600.12 - 800.72) = r * 66.8666...,  y: -r/3 (1000.5 + 800.16 + 600.54)
  //   = -r * 800.4; (g - a_s) = (-1.5, -14.81):
  //   p' = 1200 + r (-1.5 * 66.86667 + 14.81 * 800.4) = 1200 + r * 11753.624 = 1368.0768...
  const double mx = r * (600.12 - 800.72) / -3.0, my = -r * (1000.5 + 800.16 + 600.54) / 3.0;
  const double p_expected = 1200.0 + (-1.5) * mx + (-14.81) * my;
  EXPECT_NEAR(p_expected, 1368.0768, 1e-3);  // the hand value
  EXPECT_EQ(c.wetted[0], 1);
  EXPECT_NEAR(c.p[0], p_expected, 1e-9);
  EXPECT_NEAR(c.rho[0], eos.density(p_expected), 1e-9);
  EXPECT_NEAR(c.v_noslip[0].x, 2 * 0.05 - 0.1, 1e-12);
  EXPECT_NEAR(c.v_noslip[0].y, 2 * 0.2 - 0.2 / 3.0, 1e-12);
}

TEST(CouplingVirtualPressure, DryParticleAndGhostFacing) {
  FluidParticles f;
  f.resize(2);
  f.x[0] = {0.0, 0.01};   // above the solid particle
  f.x[1] = {0.0, -0.01};  // below it
  f.p[0] = 100.0;
  f.p[1] = 900.0;
  f.rho[0] = f.rho[1] = 1000.0;
  f.m[0] = f.m[1] = 0.1;
  ContactParticles c;
  c.resize(3);
  c.x[0] = {0.0, 0.0};  // an ordinary particle: sees both
  c.x[1] = {0.0, 0.0};  // a ghost whose parent faces up: sees only the fluid above
  c.ghost[1] = 1;
  c.normal[1] = {0.0, 1.0};
  c.anchor[1] = {0.0, 0.0};
  c.x[2] = {5.0, 5.0};  // far from all fluid: dry
  c.v[2] = {0.3, 0.0};
  const TaitEos eos{1000.0, 30.0, 7.0};
  compute_virtual_state(c, f, all_of(3, 2), Kernel(KernelType::WendlandC2, kH), eos, {},
                        Executor(1));
  EXPECT_NEAR(c.p[0], 500.0, 1e-9);  // equal weights: the mean
  EXPECT_NEAR(c.p[1], 100.0, 1e-9);  // only the fluid on the parent's side
  EXPECT_EQ(c.wetted[2], 0);
  EXPECT_EQ(c.p[2], 0.0);
  EXPECT_EQ(c.rho[2], eos.rho0);
  EXPECT_EQ(c.v_noslip[2].x, 0.3);
}

TEST(CouplingContactPair, StarStateForceAndContinuityByHand) {
  const Kernel k(KernelType::WendlandC2, kH);
  const double c0 = 25.0, omega = 3.0;
  ContactPairInput in{};
  in.xi = {0.1, 0.2};
  in.xs = in.xi + Vec2{0.006, -0.008};  // r = 0.01, e = (0.6, -0.8) from fluid to solid
  in.vi = {1.0, -2.0};                  // U_L = 0.6 + 1.6 = 2.2
  in.vs = {0.5, 0.5};                   // U_R = 0.3 - 0.4 = -0.1
  in.vs_noslip = {0.0, 0.0};
  in.rhoi = 1002.0;
  in.pi = 2000.0;
  in.Vi = 1e-4;
  in.rhos = 1001.0;
  in.ps = 1500.0;
  in.Vs = 0.8e-4;
  in.g_rel = {0.0, -12.0};
  const ContactPairResult res = contact_pair<false>(in, k, c0, omega, 0.0);
  ASSERT_TRUE(res.active);
  // By hand: du = 2.3, beta = min(3 * 2.3, 25) = 6.9;
  // dp_static = (1002 + 1001)/2 * g_rel . (x_i - x_s) = 1001.5 * (-12)(0.008) = -96.144;
  // U* = (1002 * 2.2 + 1001 * (-0.1) + (2000 - 1500 + 96.144)/25) / 2003
  // p* = (1001 * 2000 + 1002 * 1500 + 6.9 * 1002 * 1001 * 2.3) / 2003 = 9696.7757.
  const double us = (1002.0 * 2.2 - 100.1 + (500.0 + 96.144) / 25.0) / 2003.0;
  const double ps = (1001.0 * 2000.0 + 1002.0 * 1500.0 + 6.9 * 1002.0 * 1001.0 * 2.3) / 2003.0;
  EXPECT_NEAR(ps, 9696.7757, 1e-3);
  const double dW = k.dw(0.01);
  // f_is = -2 V_i V_s p* grad_i W, grad_i W = W'(r) (x_i - x_s)/r = -W' e.
  const Vec2 e{0.6, -0.8};
  const Vec2 f_expected = (-2.0 * 1e-4 * 0.8e-4 * ps * dW) * (-1.0 * e);
  EXPECT_NEAR(res.force.x, f_expected.x, 1e-12 * norm(f_expected));
  EXPECT_NEAR(res.force.y, f_expected.y, 1e-12 * norm(f_expected));
  EXPECT_LT(dot(res.force, e), 0.0);  // pushes the fluid away from s
  // drho term: V_s (v_i - v*) . grad_i W = V_s (U_L - U*) (-W').
  EXPECT_NEAR(res.drho_term, 0.8e-4 * (2.2 - us) * (-dW), 1e-12 * std::abs(0.8e-4 * dW));
  EXPECT_EQ(res.force_viscous.x, 0.0);
}

TEST(CouplingContactPair, NoAdhesionClipsNegativeStarPressure) {
  // cavitation_pressure = 0 (docs/model.md §4): p* = max(p*, 0), so a receding solid under
  // suction exerts no pull; the continuity term sees the cavity at the fluid's own velocity
  // (U* = U_L + max(p_L - 0, 0)/(rho c0) = U_L here), so it is zero too (issue 9: force and
  // continuity limited consistently; before, the continuity term still felt the solid).
  const Kernel k(KernelType::WendlandC2, kH);
  ContactPairInput in{};
  in.xi = {0.0, 0.0};
  in.xs = {0.0, -0.01};
  in.vi = {0.0, 0.0};
  in.vs = {0.0, -1.0};  // moving away from the fluid
  in.rhoi = in.rhos = 1000.0;
  in.pi = -500.0;
  in.ps = -500.0;
  in.Vi = in.Vs = 1e-4;
  const ContactPairResult res = contact_pair<false>(in, k, 25.0, 3.0, 0.0);
  ASSERT_TRUE(res.active);
  EXPECT_EQ(res.force.x, 0.0);
  EXPECT_EQ(res.force.y, 0.0);
  EXPECT_EQ(res.drho_term, 0.0);
  // With suction allowed (the default -101325 Pa) the same pair pulls.
  EXPECT_LT(contact_pair<false>(in, k, 25.0, 3.0, 0.0, -101325.0).force.y, 0.0);
  // Outside the support: inactive.
  in.xs = {0.0, -2.0 * kH};
  EXPECT_FALSE((contact_pair<false>(in, k, 25.0, 3.0, 0.0).active));
}

namespace {

// A disordered water block over three layers of wall particles (dx = 1 cm).
void contact_scene(FluidParticles& f, ContactParticles& c) {
  Lcg rng{42};
  const double dx = 0.01;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 12; ++i) {
      f.resize(f.size() + 1);
      const std::size_t k = f.size() - 1;
      f.x[k] = {(i + 0.5 + 0.3 * rng.next()) * dx, (j + 0.5 + 0.3 * rng.next()) * dx};
      f.v[k] = {0.5 * rng.next(), 0.5 * rng.next()};
      f.rho[k] = 1000.0 * (1.0 + 0.01 * rng.next());
      f.p[k] = 1.0e3 * (1.0 + rng.next());
      f.m[k] = f.rho[k] * dx * dx;
    }
  for (int l = 0; l < 3; ++l)
    for (int i = 0; i < 14; ++i) {
      c.resize(c.size() + 1);
      const std::size_t s = c.size() - 1;
      c.x[s] = {(i - 0.5) * dx, -(l + 0.5) * dx};
      c.v[s] = {0.1 * rng.next(), 0.3 + 0.1 * rng.next()};
      c.a[s] = {0.0, 2.0 * rng.next()};
      c.volume[s] = dx * dx;
    }
}

void action_reaction(double viscosity) {
  const double dx = 0.01;
  FluidParticles f;
  ContactParticles c;
  contact_scene(f, c);
  const Kernel k(KernelType::WendlandC2, 1.3 * dx);
  const TaitEos eos{1000.0, 25.0, 7.0};
  const Executor exec(2);
  CellGrid gf, gc;
  gf.build(f.x, k.support());
  gc.build(c.x, k.support());
  NeighbourList fc, cf;
  build_neighbour_list(f.x, c.x, gc, k.support(), false, exec, fc);
  build_neighbour_list(c.x, f.x, gf, k.support(), false, exec, cf);
  const Vec2 g{0.0, -9.81};
  compute_virtual_state(c, f, cf, k, eos, g, exec);
  for (std::size_t i = 0; i < f.size(); ++i) {
    f.a[i] = Vec2{};
    f.drho[i] = 0.0;
  }
  const ContactParams prm{25.0, 3.0, viscosity, g};
  add_contact_to_fluid(f, c, fc, k, prm, exec);
  compute_contact_reaction(c, f, cf, k, prm, exec);
  Vec2 on_fluid, on_solid, visc;
  double scale = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    on_fluid += f.m[i] * f.a[i];
    scale += f.m[i] * norm(f.a[i]);
  }
  for (std::size_t s = 0; s < c.size(); ++s) {
    on_solid += c.force[s];
    visc += c.force_viscous[s];
  }
  ASSERT_GT(scale, 1e-3);
  EXPECT_LT(norm(on_fluid + on_solid), 1e-12 * scale);
  EXPECT_GT(norm(on_solid), 0.01 * scale);  // a real net load on the wall
  if (viscosity > 0.0)
    EXPECT_GT(norm(visc), 0.0);
  else
    EXPECT_EQ(norm(visc), 0.0);
}

}  // namespace

TEST(CouplingContactRates, ActionEqualsReactionInviscid) {
  action_reaction(0.0);
}

TEST(CouplingContactRates, ActionEqualsReactionViscous) {
  action_reaction(1e-3);
}

// The reaction from the pair forces the fluid's sum kept (ContactPairForces, through
// InteractionLists::cf_in_fc) against the reaction that evaluates every pair again: the same
// bits, with viscosity, with ghosts that face only part of the water and a dry particle.
TEST(CouplingContactRates, ReactionFromTheKeptPairForcesIsBitIdentical) {
  const double dx = 0.01;
  FluidParticles f;
  ContactParticles c;
  contact_scene(f, c);
  for (std::size_t s = 28; s < c.size(); ++s) {  // the third layer: ghosts facing +x
    c.ghost[s] = 1;
    c.anchor[s] = {0.06, 0.0};
    c.normal[s] = {1.0, 0.0};
  }
  const Kernel k(KernelType::WendlandC2, 1.3 * dx);
  const Executor exec(2);
  InteractionLists lists(k.support(), k.support(), 0.2 * k.support());
  lists.update(f, c, exec, true);  // may reorder f
  ASSERT_EQ(lists.cf_in_fc().size(), lists.cf().index.size());
  for (std::size_t s = 0; s < c.size(); ++s)
    for (std::uint32_t m = lists.cf().start[s]; m < lists.cf().start[s + 1]; ++m) {
      const std::uint32_t q = lists.cf_in_fc()[m];
      ASSERT_LT(q, lists.fc().index.size());
      ASSERT_EQ(lists.fc().index[q], s);  // the same pair, seen from the fluid
      ASSERT_GE(q, lists.fc().start[lists.cf().index[m]]);
      ASSERT_LT(q, lists.fc().start[lists.cf().index[m] + 1]);
    }
  const Vec2 g{0.0, -9.81};
  compute_virtual_state(c, f, lists.cf(), k, TaitEos{1000.0, 25.0, 7.0}, g, exec);
  c.wetted[3] = 0;  // a dry particle: no pair of it acts
  const ContactParams prm{25.0, 3.0, 1e-3, g};
  ContactPairForces kept;
  add_contact_to_fluid(f, c, lists.fc(), k, prm, exec, RatePass::Both, &kept);
  ContactParticles again = c;
  compute_contact_reaction(c, f, lists.cf(), k, prm, exec, &kept, &lists.cf_in_fc());
  compute_contact_reaction(again, f, lists.cf(), k, prm, exec);
  int acting = 0;
  for (std::size_t s = 0; s < c.size(); ++s) {
    ASSERT_EQ(std::memcmp(&c.force[s], &again.force[s], sizeof(Vec2)), 0) << s;
    ASSERT_EQ(std::memcmp(&c.force_viscous[s], &again.force_viscous[s], sizeof(Vec2)), 0) << s;
    acting += norm(c.force[s]) > 0.0;
  }
  EXPECT_GT(acting, 10);
  int skipped_by_ghosts = 0;
  for (std::size_t s = 28; s < c.size(); ++s)
    for (std::uint32_t m = lists.cf().start[s]; m < lists.cf().start[s + 1]; ++m)
      skipped_by_ghosts += !c.faces(s, f.x[lists.cf().index[m]]);
  EXPECT_GT(skipped_by_ghosts, 0);
}

TEST(CouplingContactRates, OnePairMatchesThePairFunctionWithRelativeGravity) {
  // The rate loops must hand the pair function the fluid's volume m/rho and the static
  // state of the solid particle g - a_s (spec §4), not g alone.
  const Kernel k(KernelType::WendlandC2, kH);
  FluidParticles f;
  f.resize(1);
  f.x[0] = {0.0, 0.012};
  f.v[0] = {0.1, -0.3};
  f.rho[0] = 1001.0;
  f.p[0] = 700.0;
  f.m[0] = 0.11;
  ContactParticles c = one_solid({0.002, 0.0}, {0.0, 0.4}, {0.0, 30.0});
  c.wetted[0] = 1;
  c.p[0] = 650.0;
  c.rho[0] = 1000.8;
  c.v_noslip[0] = {-0.1, 1.1};
  const Vec2 g{0.0, -9.81};
  const ContactParams prm{25.0, 3.0, 0.0, g};
  const NeighbourList one = all_of(1, 1);
  add_contact_to_fluid(f, c, one, k, prm, Executor(1));
  compute_contact_reaction(c, f, one, k, prm, Executor(1));
  const ContactPairInput in{f.x[0], f.v[0],        1001.0, 700.0, 0.11 / 1001.0, c.x[0],
                            c.v[0], c.v_noslip[0], 1000.8, 650.0, 1e-4,          Vec2{0.0, -39.81}};
  const ContactPairResult r = contact_pair<false>(in, k, 25.0, 3.0, 0.0);
  ASSERT_TRUE(r.active);
  EXPECT_NEAR(f.a[0].x * 0.11, r.force.x, 1e-12 * norm(r.force));
  EXPECT_NEAR(f.a[0].y * 0.11, r.force.y, 1e-12 * norm(r.force));
  EXPECT_NEAR(f.drho[0], 2.0 * 1001.0 * r.drho_term, 1e-12 * std::abs(2002.0 * r.drho_term));
  EXPECT_EQ(c.force[0].x, -r.force.x);
  EXPECT_EQ(c.force[0].y, -r.force.y);
}

TEST(CouplingContactRates, StaticTermSwitchedOffDropsTheRelativeGravity) {
  // fluid.hydrostatic_correction = false (docs/model.md §2) must remove the static state
  // from the contact's U* too: the rate loops then hand the pair function g_rel = 0, so
  // gravity and the solid's acceleration no longer change the contact force.
  const Kernel k(KernelType::WendlandC2, kH);
  FluidParticles f;
  f.resize(1);
  f.x[0] = {0.0, 0.012};
  f.v[0] = {0.1, -0.3};
  f.rho[0] = 1001.0;
  f.p[0] = 700.0;
  f.m[0] = 0.11;
  ContactParticles c = one_solid({0.002, 0.0}, {0.0, 0.4}, {0.0, 30.0});
  c.wetted[0] = 1;
  c.p[0] = 650.0;
  c.rho[0] = 1000.8;
  c.v_noslip[0] = {-0.1, 1.1};
  ContactParams prm{25.0, 3.0, 0.0, Vec2{0.0, -9.81}};
  prm.hydrostatic_correction = false;
  const NeighbourList one = all_of(1, 1);
  add_contact_to_fluid(f, c, one, k, prm, Executor(1));
  compute_contact_reaction(c, f, one, k, prm, Executor(1));
  const ContactPairInput in{f.x[0], f.v[0],        1001.0, 700.0, 0.11 / 1001.0, c.x[0],
                            c.v[0], c.v_noslip[0], 1000.8, 650.0, 1e-4,          Vec2{}};
  const ContactPairResult r = contact_pair<false>(in, k, 25.0, 3.0, 0.0);
  ASSERT_TRUE(r.active);
  EXPECT_NEAR(f.a[0].y * 0.11, r.force.y, 1e-12 * norm(r.force));
  EXPECT_NEAR(f.drho[0], 2.0 * 1001.0 * r.drho_term, 1e-12 * std::abs(2002.0 * r.drho_term));
  EXPECT_EQ(c.force[0].x, -r.force.x);
  EXPECT_EQ(c.force[0].y, -r.force.y);
  // The static state enters U* (riemann_solver.h), hence the continuity term: with it this
  // pair's density rate differs, so the comparison above tells the two apart.
  ContactPairInput with = in;
  with.g_rel = Vec2{0.0, -39.81};
  EXPECT_GT(std::abs(contact_pair<false>(with, k, 25.0, 3.0, 0.0).drho_term - r.drho_term),
            1e-3 * std::abs(r.drho_term));
}
