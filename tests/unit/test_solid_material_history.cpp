// The material law is evaluated exactly once per solid sub-step (solid/stress_update.h):
// body.history.updates counts the committing passes. After set-up it is 1 (the initial
// state); each advance_body adds exactly its sub-steps; force re-evaluation
// (refresh_internal_forces), energies and output fields add none. Also: the history fields a
// law declares reach the body (names, units, initial values) and the output.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/parallel.h"
#include "solid/deformation_gradient.h"
#include "solid/stress_update.h"
#include "test_solid_lattices.h"

using namespace slamsph;
using namespace slamsph::testing;

namespace {

constexpr double kDx = 0.005;

ElasticMaterialInput steel() {
  ElasticMaterialInput m;
  m.name = "steel";
  m.model = J2LinearHardeningModel{250e6, 2e9};
  m.density = 7800.0;
  m.youngs_modulus = 200e9;
  m.poisson_ratio = 0.3;
  m.hourglass = 0.1;
  return m;
}

}  // namespace

TEST(SolidMaterialHistory, LawUpdatedOncePerSubStep) {
  for (const ElasticMaterialInput& mat : {plate_material(0.1), steel()}) {
    SolidBody b = make_body(box_lattice(12, 4, kDx), kDx, "tl_sfpm", mat);
    for (std::size_t i = 0; i < b.size(); ++i) b.v[i] = {0.0, 0.5 * b.X[i].x};  // bend it
    EXPECT_EQ(b.history.updates, 1u) << mat.name;
    std::uint64_t expected = 1;
    const Executor exec(2);
    for (int call = 0; call < 4; ++call) {
      advance_body(b, 0.0, (1.0 + call) * 2.5 * stable_time_step(b), {0.0, -9.81}, exec);
      expected += static_cast<std::uint64_t>(b.last_substeps);
      EXPECT_GE(b.last_substeps, 3);
      refresh_internal_forces(b, exec);  // force evaluation only
      body_energies(b);
      solid_output_fields(b);
      EXPECT_EQ(b.history.updates, expected) << mat.name << " call " << call;
    }
  }
}

TEST(SolidMaterialHistory, DeclaredFieldsReachTheBodyAndTheOutput) {
  SolidBody svk = make_body(box_lattice(6, 4, kDx), kDx, "tl_sfpm", plate_material());
  EXPECT_TRUE(svk.history.fields.empty());
  EXPECT_TRUE(std::holds_alternative<StVenantKirchhoff>(svk.material.law));

  SolidBody b = make_body(box_lattice(6, 4, kDx), kDx, "tl_sfpm", steel());
  ASSERT_TRUE(std::holds_alternative<J2LinearHardening>(b.material.law));
  ASSERT_EQ(b.history.fields.size(), 5u);
  ASSERT_EQ(b.history.values.size(), 5u);
  EXPECT_EQ(b.history.fields[4].name, "equivalent_plastic_strain");
  EXPECT_EQ(b.history.fields[4].unit, "-");
  for (std::size_t k = 0; k < 5; ++k) {
    ASSERT_EQ(b.history.values[k].size(), b.size());
    EXPECT_EQ(b.history.values[k][3], J2LinearHardening::kHistory[k].initial);
  }
  // Yield every particle in uniaxial strain, then check the plastic strain is output.
  for (std::size_t i = 0; i < b.size(); ++i) b.x[i] = Mat2{1.01, 0.0, 0.0, 1.0} * b.X[i];
  compute_deformation_gradients(b, b.topology, Executor(1));
  update_stress(b, b.F, 0.0, Executor(1));
  // The output goes through the body's field registry (VTK flag = the law's output flag).
  bool found = false;
  SolidBody::visit_fields(b, [&](const FieldSpec& spec, const auto& f) {
    if (spec.name != "equivalent_plastic_strain") return;
    found = true;
    EXPECT_TRUE(spec.vtk);
    EXPECT_TRUE(spec.persistent);
    ASSERT_EQ(f.size(), b.size());
    // log strain 0.00995 > e_y = 250e6 / (2 * 76.9e9) = 0.0016: ε̄p = (2μe − σ_y)/(3μ + H)
    const double mu = 200e9 / 2.6, e = std::log(1.01);
    EXPECT_NEAR(field_as_doubles(f)[10], (2 * mu * e - 250e6) / (3 * mu + 2e9), 1e-9);
  });
  EXPECT_TRUE(found);
}
