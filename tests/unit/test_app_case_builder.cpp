// The case builder (src/app/case_builder.h) converts a body's kind once, with one rule: a
// name outside solid/body_kind.h is an error naming file and key (it once became
// rigid_fixed silently in one of two parsers). It also translates the case into plain
// physics values (BodySetup) and lays out the contact set (bodies first, then ghosts).
#include <gtest/gtest.h>

#include "app/case_builder.h"
#include "core/box.h"
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

// An elastic body is stored along the structure (geometry/structure_order.h): the reference
// partners of a particle are stored near it and the two halves of the storage (the shares
// of two threads) meet in few places. The 2-layer skin of skin_ring_reduced laid out layer by
// layer has its partners in the other layer 1 250 places away and every particle of the first
// half (layer 0) has partners in the second.
TEST(CaseBuilder, ElasticBodiesAreStoredAlongTheStructure) {
  const CaseConfig cfg =
      load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/skin_ring_reduced.toml");
  const BuiltCase built = build_case(cfg);
  const SolidBody& skin = built.system.bodies.at(1);
  ASSERT_EQ(skin.name, "skin");
  const auto& start = skin.topology.pairs.start;
  const auto& index = skin.topology.pairs.index;
  const std::size_t n = skin.size(), half = n / 2;
  double distance = 0.0;
  std::size_t crossing = 0;
  for (std::size_t i = 0; i < n; ++i) {
    bool crosses = false;
    for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) {
      const std::size_t j = index[k];
      distance += static_cast<double>(j > i ? j - i : i - j);
      if (i < half && j >= half) crosses = true;
    }
    crossing += crosses ? 1 : 0;
  }
  distance /= static_cast<double>(index.size());
  EXPECT_LT(distance, 50.0);
  EXPECT_LT(static_cast<double>(crossing), 0.02 * static_cast<double>(n));
}

// `[body.pre_failed]` (cases/breached_plate.toml): the particles inside start failed and fully
// damaged; a box around no particle is an error naming the file and the key.
TEST(CaseBuilder, PreFailedBoxesMarkTheirParticlesFailed) {
  CaseConfig cfg = load_case(std::string(SLAMSPH_SOURCE_DIR) + "/cases/johnson_cook_bar.toml");
  cfg.bodies.at(0).pre_failed = {Box{{0.05, -0.01}, {0.052, 0.01}}};
  const SolidBody body = build_case(cfg).system.bodies.at(0);
  int failed = 0, damaged = 0, inside_box = 0;
  for (std::size_t k = 0; k < body.history.fields.size(); ++k)
    for (std::size_t i = 0; i < body.size(); ++i) {
      const bool in = inside(cfg.bodies[0].pre_failed[0], body.X[i]);
      if (body.history.fields[k].name == "failed") {
        failed += body.history.values[k][i] > 0.5;
        inside_box += in;
        EXPECT_EQ(body.history.values[k][i] > 0.5, in) << i;
      }
      if (body.history.fields[k].name == "damage") damaged += body.history.values[k][i] >= 1.0;
    }
  EXPECT_EQ(failed, 20);  // two columns of 10 particles at dx 1 mm
  EXPECT_EQ(damaged, failed);
  EXPECT_EQ(inside_box, failed);
  cfg.bodies[0].pre_failed = {Box{{0.2, 0.2}, {0.21, 0.21}}};
  try {
    build_case(cfg);
    FAIL() << "an empty pre_failed box was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("body[0].pre_failed"), std::string::npos) << e.what();
  }
}
