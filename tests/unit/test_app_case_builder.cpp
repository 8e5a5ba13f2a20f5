// The case builder (src/app/case_builder.h) converts a body's kind once, with one rule: a
// name outside solid/body_kind.h is an error naming file and key (it once became
// rigid_fixed silently in one of two parsers). It also translates the case into plain
// physics values (BodySetup) and lays out the contact set (bodies first, then ghosts).
#include <gtest/gtest.h>

#include "app/case_builder.h"
#include "core/error.h"
#include "io/case_file.h"

using namespace slamsph;

namespace {

CaseConfig gate() {
  return load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/elastic_gate.toml");
}

}  // namespace

TEST(CaseBuilder, UnknownBodyKindIsAnErrorNamingFileAndKey) {
  CaseConfig cfg = gate();
  cfg.bodies.at(0).kind = "rigid_fxed";  // past the parser: a config built in code
  try {
    body_setup_from_case(cfg, 0);
    FAIL() << "unknown kind accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("elastic_gate.toml: body[0].kind"), std::string::npos) << m;
    EXPECT_NE(m.find("'rigid_fxed'"), std::string::npos) << m;
  }
  EXPECT_THROW(build_case(cfg), InputError);
}

TEST(CaseBuilder, TranslatesBodiesAndLaysOutContact) {
  const CaseConfig cfg = gate();
  for (std::size_t b = 0; b < cfg.bodies.size(); ++b) {
    const BodySetup s = body_setup_from_case(cfg, b);
    EXPECT_EQ(body_kind_name(s.kind), cfg.bodies[b].kind);
    EXPECT_EQ(s.material.has_value(), s.kind == BodyKind::Elastic);
  }
  const BuiltCase built = build_case(cfg);
  const FsiSystem& sys = built.system;
  ASSERT_EQ(sys.bodies.size(), cfg.bodies.size());
  EXPECT_EQ(sys.layout.offset.front(), 0u);
  for (std::size_t b = 0; b < sys.bodies.size(); ++b)
    EXPECT_EQ(sys.layout.offset[b + 1] - sys.layout.offset[b], sys.bodies[b].size());
  EXPECT_EQ(sys.contact.size(), sys.layout.size());
  for (std::size_t c = 0; c < sys.contact.size(); ++c)
    EXPECT_EQ(sys.contact.ghost[c] != 0, c >= sys.layout.first_ghost()) << c;
  EXPECT_GT(sys.fluid.size(), 0u);
  EXPECT_GE(sys.kernel_c.h(), sys.kernel_f.h());
  EXPECT_EQ(built.params.cfl, cfg.numerics.cfl);
  EXPECT_EQ(built.params.dual_time_stepping, cfg.numerics.dual_time_stepping);
}

// `failed_particles` reaches the built body: "eulerian" turns the Lagrangian → Eulerian
// switch on (solid/eulerian_failed_interaction.h), the default keeps failed particles in the
// total-Lagrangian sums.
TEST(CaseBuilder, FailedParticlesChoiceReachesTheBody) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/johnson_cook_bar.toml");
  ASSERT_EQ(cfg.bodies.at(0).failed_particles, "lagrangian");
  EXPECT_FALSE(build_case(cfg).system.bodies.at(0).eulerian_switch);
  cfg.bodies[0].failed_particles = "eulerian";
  EXPECT_TRUE(body_setup_from_case(cfg, 0).eulerian_switch);
  EXPECT_TRUE(build_case(cfg).system.bodies.at(0).eulerian_switch);
}
