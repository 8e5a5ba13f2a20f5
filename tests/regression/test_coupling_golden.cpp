// Golden regression values, one group per physics operator: the fused GSPH fluid pass
// (inviscid and viscous), the fluid–solid contact (virtual state, pair forces both ways),
// the solid force operators (stress, artificial viscosity, hourglass; TL-SFPM and TLSPH)
// and each material law (SVK; J2 along a load path). Inputs are small deterministic particle
// sets (a portable LCG, no <random> distributions). Any deterministic change of the physics
// of these operators changes some value by far more than the tolerance and fails here; a
// change of summation order alone (round-off, ~1e-15) does not.
//
// The golden numbers were derived from the code as landed (commit 08d1a40, 2026-11-29) by
// running this test with SLAMSPH_PRINT_GOLDEN=1, which prints the current values in the
// form used below; they are stored to 13 significant digits and compared with a relative
// tolerance of 1e-9. A deliberate physics change must regenerate them the same way and say
// so in its commit. Every value is also checked at 1 and 2 threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "../unit/test_solid_lattices.h"
#include "core/cell_grid.h"
#include "core/parallel.h"
#include "coupling/contact_rates.h"
#include "coupling/virtual_pressure.h"
#include "fluid/gsph_fluid_rates.h"
#include "solid/artificial_viscosity.h"
#include "solid/deformation_gradient.h"
#include "solid/hourglass_control.h"
#include "solid/stress_update.h"
#include "solid/tl_pair_force.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

using Values = std::vector<std::pair<std::string, double>>;

struct Lcg {
  std::uint64_t s;
  double next() {  // [-1, 1)
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-52 - 1.0;
  }
};

void compare(const char* group, const Values& got, const Values& want) {
  if (std::getenv("SLAMSPH_PRINT_GOLDEN")) {
    std::printf("  // %s\n", group);
    for (const auto& [k, v] : got) std::printf("  {\"%s\", %.12e},\n", k.c_str(), v);
    return;
  }
  ASSERT_EQ(got.size(), want.size()) << group;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].first, want[i].first) << group;
    EXPECT_NEAR(got[i].second, want[i].second, 1e-9 * std::abs(want[i].second))
        << group << ": " << want[i].first;
  }
}

// ---- fluid ----------------------------------------------------------------------------

constexpr double kDx = 0.01;

FluidParticles fluid_cloud() {
  Lcg r{7};
  FluidParticles f;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 12; ++i) {
      f.resize(f.size() + 1);
      const std::size_t k = f.size() - 1;
      f.x[k] = {(i + 0.5 + 0.25 * r.next()) * kDx, (j + 0.5 + 0.25 * r.next()) * kDx};
      f.v[k] = {0.4 * r.next(), 0.4 * r.next()};
      f.rho[k] = 1000.0 * (1.0 + 0.005 * r.next());
      f.p[k] = 2000.0 * (1.0 + r.next());
      f.m[k] = 1000.0 * kDx * kDx * (1.0 + 0.05 * r.next());
      f.id[k] = static_cast<std::int64_t>(k);
    }
  return f;
}

Values fluid_values(double viscosity, const Executor& exec) {
  FluidParticles f = fluid_cloud();
  const Kernel k(KernelType::WendlandC2, 1.3 * kDx);
  CellGrid grid;
  grid.build(f.x, k.support());
  BandedPairs nl;
  build_banded_pairs(f.x, grid, k.support(), exec, nl);
  compute_gsph_fluid_rates(f, nl, k, {25.0, 3.0, viscosity, {0.0, -9.81}}, exec);
  double sa = 0.0, sd = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    sa += norm(f.a[i]);
    sd += std::abs(f.drho[i]);
  }
  return {{"a[17].x", f.a[17].x}, {"a[17].y", f.a[17].y},   {"drho[17]", f.drho[17]},
          {"a[64].x", f.a[64].x}, {"drho[64]", f.drho[64]}, {"sum|a|", sa},
          {"sum|drho|", sd}};
}

// ---- contact --------------------------------------------------------------------------

Values contact_values(double viscosity, const Executor& exec) {
  FluidParticles f = fluid_cloud();
  Lcg r{11};
  ContactParticles c;
  for (int l = 0; l < 3; ++l)
    for (int i = 0; i < 14; ++i) {
      c.resize(c.size() + 1);
      const std::size_t s = c.size() - 1;
      c.x[s] = {(i - 0.5) * kDx, -(l + 0.5) * kDx};
      c.v[s] = {0.1 * r.next(), 0.2 + 0.1 * r.next()};
      c.a[s] = {0.5 * r.next(), 3.0 * r.next()};
      c.volume[s] = kDx * kDx;
      c.normal[s] = l == 0 ? Vec2{0.0, 1.0} : Vec2{};
    }
  const Kernel k(KernelType::WendlandC2, 1.3 * kDx);
  CellGrid gf, gc;
  gf.build(f.x, k.support());
  gc.build(c.x, k.support());
  NeighbourList fc, cf;
  build_neighbour_list(f.x, c.x, gc, k.support(), false, exec, fc);
  build_neighbour_list(c.x, f.x, gf, k.support(), false, exec, cf);
  const Vec2 g{0.0, -9.81};
  compute_virtual_state(c, f, cf, k, TaitEos{1000.0, 25.0, 7.0}, g, exec);
  const ContactParams prm{25.0, 3.0, viscosity, g};
  add_contact_to_fluid(f, c, fc, k, prm, exec);
  compute_contact_reaction(c, f, cf, k, prm, exec);
  Vec2 total;
  for (std::size_t s = 0; s < c.size(); ++s) total += c.force[s];
  return {{"p'[5]", c.p[5]},
          {"rho'[5]", c.rho[5]},
          {"p'[20]", c.p[20]},
          {"v~[5].x", c.v_noslip[5].x},
          {"force[5].x", c.force[5].x},
          {"force[5].y", c.force[5].y},
          {"force[20].y", c.force[20].y},
          {"fluid a[3].y", f.a[3].y},
          {"fluid drho[3]", f.drho[3]},
          {"total.x", total.x},
          {"total.y", total.y}};
}

// ---- solid ----------------------------------------------------------------------------

Values solid_values(const char* scheme, const ElasticMaterialInput& mat, const Executor& exec) {
  const double dx = 0.005;
  Lcg r{3};
  std::vector<Vec2> X = box_lattice(12, 6, dx);
  for (Vec2& p : X) p += Vec2{0.1 * dx * r.next(), 0.1 * dx * r.next()};
  SolidBody b = make_body(X, dx, scheme, mat);
  // A non-affine deformation and a velocity field (stress, viscosity and hourglass all act).
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vec2 P = b.X[i];
    b.x[i] = P + Vec2{0.02 * P.x + 0.3 * dx * std::sin(40.0 * P.y),
                      0.01 * std::sin(30.0 * P.x) * dx / 0.005};
    b.v[i] = {0.2 * std::cos(25.0 * P.y), -0.3 * P.x / 0.06};
  }
  compute_deformation_gradients(b, b.topology, exec);
  update_stress(b, b.F, 1e-6, exec);
  std::vector<Vec2> fs(b.size()), fv(b.size()), fh(b.size());
  std::vector<double> q(b.size());
  compute_stress_forces(b, b.topology, exec, fs);
  compute_artificial_viscosity(b, b.topology, b.v, exec, fv, q);
  compute_hourglass_forces(b, b.topology, 1.0, exec, fh);
  double s = 0.0, v = 0.0, h = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    s += norm(fs[i]);
    v += norm(fv[i]);
    h += norm(fh[i]);
  }
  return {{"F[30].xx", b.F[30].xx},   {"F[30].xy", b.F[30].xy},
          {"P[30].xx", b.P[30].xx},   {"f_stress[30].x", fs[30].x},
          {"f_stress[0].y", fs[0].y}, {"f_av[30].x", fv[30].x},
          {"heat[30]", q[30]},        {"f_hg[30].y", fh[30].y},
          {"sum|f_stress|", s},       {"sum|f_av|", v},
          {"sum|f_hg|", h},           {"E_hg", hourglass_energy(b, b.topology, 1.0, exec)}};
}

// ---- laws -----------------------------------------------------------------------------

Values law_values() {
  const Mat2 F{1.08, 0.13, -0.05, 0.93};
  const StVenantKirchhoff svk(svk_from_young(2.0e6, 0.3975));
  const Mat2 P = svk.update(Mat2::identity(), F, 1e-6, {});
  Values v{{"svk P.xx", P.xx},
           {"svk P.xy", P.xy},
           {"svk P.yx", P.yx},
           {"svk P.yy", P.yy},
           {"svk psi", svk.energy_density(F, {})},
           {"svk s_zz", svk.cauchy_zz(F, {})}};
  // J2: a non-proportional path (stretch, then shear, then partial release).
  const J2LinearHardening j2 = std::get<J2LinearHardening>(
      make_material_law(J2LinearHardeningModel{250e6, 2e9}, 200e9, 0.3));
  std::array<double, J2LinearHardening::kSlots> h{};
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = J2LinearHardening::kHistory[k].initial;
  Mat2 Fo = Mat2::identity(), Pj;
  for (int n = 1; n <= 30; ++n) {
    const double t = n / 30.0;
    const Mat2 Fn = t <= 0.5   ? Mat2{1.0 + 0.02 * t, 0.0, 0.0, 1.0 - 0.004 * t}
                    : t <= 0.8 ? Mat2{1.01, 0.03 * (t - 0.5), 0.0, 0.998}
                               : Mat2{1.01 - 0.02 * (t - 0.8), 0.009, 0.0, 0.998};
    Pj = j2.update(Fo, Fn, 1e-6, h);
    Fo = Fn;
  }
  v.insert(v.end(), {{"j2 P.xx", Pj.xx},
                     {"j2 P.xy", Pj.xy},
                     {"j2 P.yy", Pj.yy},
                     {"j2 eps_p", h[J2LinearHardening::kPlasticStrain]},
                     {"j2 Cp^-1 xy", h[J2LinearHardening::kCpInvXY]},
                     {"j2 psi", j2.energy_density(Fo, h)},
                     {"j2 s_zz", j2.cauchy_zz(Fo, h)}});
  return v;
}

ElasticMaterialInput steel_j2() {
  ElasticMaterialInput m;
  m.name = "steel";
  m.model = J2LinearHardeningModel{250e6, 2e9};
  m.density = 7800.0;
  m.youngs_modulus = 200e9;
  m.poisson_ratio = 0.3;
  m.av_alpha = 1.0;
  m.hourglass = 0.1;
  return m;
}

// clang-format off
const Values kFluidInviscid{
  {"a[17].x", -1.660635728065e+01},
  {"a[17].y", -2.348444661006e+01},
  {"drho[17]", -2.061742269974e+04},
  {"a[64].x", 5.296722070739e+01},
  {"drho[64]", 7.668730868299e+03},
  {"sum|a|", 1.451121545661e+04},
  {"sum|drho|", 1.327311532280e+06},
};
const Values kFluidViscous{
  {"a[17].x", -1.554513169477e+01},
  {"a[17].y", -3.171349127640e+01},
  {"drho[17]", -2.061742269974e+04},
  {"a[64].x", 4.108522385535e+01},
  {"drho[64]", 7.668730868299e+03},
  {"sum|a|", 1.467599867818e+04},
  {"sum|drho|", 1.327311532280e+06},
};
const Values kContactInviscid{
  {"p'[5]", 1.915285362065e+03},
  {"rho'[5]", 1.003036652372e+03},
  {"p'[20]", 7.090624715010e+02},
  {"v~[5].x", 3.286338446190e-01},
  {"force[5].x", 5.452971094157e-03},
  {"force[5].y", -2.036826123240e+01},
  {"force[20].y", -6.234508988539e-01},
  {"fluid a[3].y", 1.038490192652e+02},
  {"fluid drho[3]", 7.297441879980e+02},
  {"total.x", 2.412283968724e-01},
  {"total.y", -2.396783189959e+02},
};
const Values kContactViscous{
  {"p'[5]", 1.915285362065e+03},
  {"rho'[5]", 1.003036652372e+03},
  {"p'[20]", 7.090624715010e+02},
  {"v~[5].x", 3.286338446190e-01},
  {"force[5].x", -4.916035223873e-01},
  {"force[5].y", -2.095783629850e+01},
  {"force[20].y", -6.529974284793e-01},
  {"fluid a[3].y", 1.056026117328e+02},
  {"fluid drho[3]", 7.297441879980e+02},
  {"total.x", -1.468162110277e+00},
  {"total.y", -2.460409962953e+02},
};
const Values kSolidTlSfpmSvk{
  {"F[30].xx", 1.020407498512e+00},
  {"F[30].xy", 5.258350015092e-02},
  {"P[30].xx", 1.583338188107e+05},
  {"f_stress[30].x", 7.158229748542e+01},
  {"f_stress[0].y", 3.504600431939e+03},
  {"f_av[30].x", -2.605425049792e-01},
  {"heat[30]", 6.790060880265e-03},
  {"f_hg[30].y", -3.787446399555e+00},
  {"sum|f_stress|", 7.969048526327e+04},
  {"sum|f_av|", 6.182093964694e+01},
  {"sum|f_hg|", 5.578841801620e+02},
  {"E_hg", 1.061775886365e-01},
};
const Values kSolidTlSphSvk{
  {"F[30].xx", 1.020085938440e+00},
  {"F[30].xy", 5.265273129823e-02},
  {"P[30].xx", 1.589448117727e+05},
  {"f_stress[30].x", -2.118327673666e+02},
  {"f_stress[0].y", 3.308930097969e+03},
  {"f_av[30].x", -1.308588212271e-01},
  {"heat[30]", 2.585465407564e-02},
  {"f_hg[30].y", -2.919308196300e+00},
  {"sum|f_stress|", 6.861614812430e+04},
  {"sum|f_av|", 6.400579013518e+01},
  {"sum|f_hg|", 8.719477694355e+02},
  {"E_hg", 1.551094528641e-01},
};
const Values kSolidTlSfpmJ2{
  {"F[30].xx", 1.020407498512e+00},
  {"F[30].xy", 5.258350015092e-02},
  {"P[30].xx", 1.876639748001e+09},
  {"f_stress[30].x", 4.196842592235e+06},
  {"f_stress[0].y", 4.445315069089e+06},
  {"f_av[30].x", -1.840973542343e+02},
  {"heat[30]", 4.797805422369e+00},
  {"f_hg[30].y", -3.787446399555e+05},
  {"sum|f_stress|", 7.300618993823e+08},
  {"sum|f_av|", 4.368220619584e+04},
  {"sum|f_hg|", 5.578841801620e+07},
  {"E_hg", 1.061775886365e+04},
};
const Values kLaws{
  {"svk P.xx", 2.152359352502e+05},
  {"svk P.xy", 7.071635760723e+04},
  {"svk P.yx", 5.292778044417e+04},
  {"svk P.yy", -1.659682359614e+04},
  {"svk psi", 1.164885738907e+04},
  {"svk s_zz", 6.958749741263e+04},
  {"j2 P.xx", 4.841933874806e+08},
  {"j2 P.xy", 4.419091403149e+07},
  {"j2 P.yy", 7.524220480000e+08},
  {"j2 eps_p", 1.230585327851e-02},
  {"j2 Cp^-1 xy", -8.444095423292e-03},
  {"j2 psi", 1.483470885275e+06},
  {"j2 s_zz", 7.486354752249e+08},
};
// clang-format on

}  // namespace

TEST(GoldenPhysics, GsphFluidPass) {
  for (int threads : {1, 2}) {
    compare("fluid inviscid", fluid_values(0.0, Executor(threads)), kFluidInviscid);
    compare("fluid viscous", fluid_values(1e-3, Executor(threads)), kFluidViscous);
  }
}

TEST(GoldenPhysics, FluidSolidContact) {
  for (int threads : {1, 2}) {
    compare("contact inviscid", contact_values(0.0, Executor(threads)), kContactInviscid);
    compare("contact viscous", contact_values(1e-3, Executor(threads)), kContactViscous);
  }
}

TEST(GoldenPhysics, SolidForces) {
  for (int threads : {1, 2}) {
    compare("solid tl_sfpm svk", solid_values("tl_sfpm", plate_material(0.1), Executor(threads)),
            kSolidTlSfpmSvk);
    compare("solid tlsph svk", solid_values("tlsph", plate_material(0.1), Executor(threads)),
            kSolidTlSphSvk);
    compare("solid tl_sfpm j2", solid_values("tl_sfpm", steel_j2(), Executor(threads)),
            kSolidTlSfpmJ2);
  }
}

TEST(GoldenPhysics, MaterialLaws) {
  compare("laws", law_values(), kLaws);
}
