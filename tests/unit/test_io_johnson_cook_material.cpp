// Case-file input of the Johnson–Cook material (model = "johnson_cook", docs/case_format.md):
// the preset (paper Table 1), overrides, the failure choice, and file:line:key errors.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "io/case_file.h"
#include "solid/materials/material_presets.h"

using namespace slamsph;

namespace {

const std::string kBase = R"(schema_version = 1
name = "jc"

[numerics]
dx = 0.01
end_time = 1.0

[numerics.domain]
min = [-0.5, -0.5]
max = [2.0, 2.0]

[materials.al]
model = "johnson_cook"
preset = "al2024_t3"

[[body]]
name = "plate"
material = "al"
gravity = false

[body.shape]
type = "rectangle"
min = [0.0, 0.0]
max = [0.1, 0.02]
)";

std::string with(const std::string& extra) {
  std::string t = kBase;
  const std::string anchor = "preset = \"al2024_t3\"\n";
  return t.replace(t.find(anchor), anchor.size(), anchor + extra);
}

std::string error_of(const std::string& text) {
  try {
    parse_case_string(text, "cases/bad.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

int line_of(const std::string& text, const std::string& start) {
  int line = 1;
  std::size_t b = 0;
  while (b < text.size()) {
    if (text.compare(b, start.size(), start) == 0) return line;
    b = text.find('\n', b);
    if (b == std::string::npos) break;
    ++b;
    ++line;
  }
  throw std::logic_error("test: no line starts with " + start);
}

void expect_error(const std::string& text, int line, const std::string& key,
                  const std::string& part) {
  const std::string msg = error_of(text);
  const std::string prefix = "cases/bad.toml:" + std::to_string(line) + ": " + key + ": ";
  EXPECT_EQ(msg.rfind(prefix, 0), 0u) << "message: " << msg << "\nexpected prefix: " << prefix;
  EXPECT_NE(msg.find(part), std::string::npos) << msg << "\nmissing: " << part;
}

const JohnsonCookModel& model_of(const CaseConfig& c) {
  return std::get<JohnsonCookModel>(c.find_material("al")->model);
}

}  // namespace

TEST(IoJohnsonCookMaterial, PresetIsTheShippedTable1) {
  const CaseConfig c = parse_case_string(kBase, "cases/jc.toml");
  const MaterialConfig& m = *c.find_material("al");
  EXPECT_EQ(m.density, 2700.0);
  EXPECT_EQ(m.youngs_modulus, 67.5e9);
  EXPECT_EQ(m.poisson_ratio, 0.34);
  EXPECT_EQ(model_of(c), kAl2024T3.model);
  EXPECT_EQ(model_of(c).failure.kind, FailureKind::JohnsonCook);
  // The resolved copy writes every parameter and parses back to the same model.
  const CaseConfig back = parse_case_string(resolved_case_toml(c), "cases/jc.resolved.toml");
  EXPECT_EQ(model_of(back), model_of(c));
  EXPECT_EQ(back.find_material("al")->density, 2700.0);
}

TEST(IoJohnsonCookMaterial, KeysOverrideThePresetAndFailureIsSelectable) {
  const CaseConfig c = parse_case_string(
      with("jc_c = 0.0\ninitial_temperature = 400.0\nfailure = \"critical_plastic_strain\"\n"
           "critical_plastic_strain = 0.15\ndensity = 2800.0\n"),
      "cases/jc.toml");
  const JohnsonCookModel& m = model_of(c);
  EXPECT_EQ(m.c, 0.0);
  EXPECT_EQ(m.a, 265e6);
  EXPECT_EQ(m.initial_temperature, 400.0);
  EXPECT_EQ(m.failure.kind, FailureKind::CriticalPlasticStrain);
  EXPECT_EQ(m.failure.critical_plastic_strain, 0.15);
  EXPECT_EQ(c.find_material("al")->density, 2800.0);
  const CaseConfig back = parse_case_string(resolved_case_toml(c), "cases/jc.resolved.toml");
  EXPECT_EQ(model_of(back), m);
  EXPECT_EQ(model_of(parse_case_string(with("failure = \"none\"\n"), "cases/jc.toml")).failure.kind,
            FailureKind::None);
}

TEST(IoJohnsonCookMaterial, WithoutPresetEveryConstantIsRequired) {
  std::string t = kBase;
  t.replace(t.find("preset = \"al2024_t3\"\n"), 21,
            "density = 2700.0\nyoungs_modulus = 7e10\npoisson_ratio = 0.3\njc_a = 3e8\njc_b = 4e8\n"
            "jc_n = 0.3\njc_c = 0.01\njc_m = 1.0\nmelting_temperature = 800.0\n"
            "specific_heat = 900.0\neos_sound_speed = 5300.0\ngruneisen_gamma = 2.0\n");
  // hugoniot_slope missing: reported at the table's line.
  expect_error(t, line_of(t, "[materials.al]"), "materials.al.hugoniot_slope",
               "missing required key");
  const std::string ok = t + "";
  std::string full = ok;
  full.replace(full.find("gruneisen_gamma = 2.0\n"), 22,
               "gruneisen_gamma = 2.0\nhugoniot_slope = 1.3\n");
  const JohnsonCookModel m = model_of(parse_case_string(full, "cases/jc.toml"));
  EXPECT_EQ(m.reference_temperature, 293.0);  // documented defaults
  EXPECT_EQ(m.reference_strain_rate, 1.0);
  EXPECT_EQ(m.heating_fraction, 0.9);
  EXPECT_EQ(m.initial_temperature, 293.0);
  EXPECT_EQ(m.failure.kind, FailureKind::None);
}

TEST(IoJohnsonCookMaterial, BadValuesNameFileLineAndKey) {
  const std::string a = with("jc_a = -1.0\n");
  expect_error(a, line_of(a, "jc_a"), "materials.al.jc_a", "must be > 0");
  const std::string tm = with("melting_temperature = 250.0\n");
  expect_error(tm, line_of(tm, "melting_temperature"), "materials.al.melting_temperature",
               "above reference_temperature");
  const std::string hf = with("heating_fraction = 1.5\n");
  expect_error(hf, line_of(hf, "heating_fraction"), "materials.al.heating_fraction",
               "must be in [0, 1]");
  const std::string p = with("");
  std::string bp = p;
  bp.replace(bp.find("al2024_t3"), 9, "al2024");
  expect_error(bp, line_of(bp, "preset"), "materials.al.preset", "al2024_t3");
  const std::string f = with("failure = \"jc\"\n");
  expect_error(f, line_of(f, "failure"), "materials.al.failure", "johnson_cook");
  // Failure constants of another failure model are unknown keys.
  const std::string d = with("failure = \"none\"\nfailure_d1 = 0.1\n");
  expect_error(d, line_of(d, "failure_d1"), "materials.al.failure_d1", "with failure 'none'");
  const std::string cr = with("failure = \"critical_plastic_strain\"\n");
  expect_error(cr, line_of(cr, "[materials.al]"), "materials.al.critical_plastic_strain",
               "missing required key");
  const std::string neg = with("failure_d1 = -0.2\n");
  expect_error(neg, line_of(neg, "failure_d1"), "materials.al.failure_d1", "D1 + D2 > 0");
  // JC keys on an svk material are unknown keys.
  std::string s = kBase;
  s.replace(s.find("model = \"johnson_cook\"\npreset = \"al2024_t3\"\n"), 43,
            "density = 2700.0\nyoungs_modulus = 7e10\njc_a = 3e8\n");
  expect_error(s, line_of(s, "jc_a"), "materials.al.jc_a", "for material model 'svk'");
}
