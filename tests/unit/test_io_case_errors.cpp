// Case-file validation: every class of bad input gives one InputError whose message names
// the file, the line and the key path ("<file>:<line>: <key>: <what>; expected <what>").
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "io/case_file.h"

using namespace slamsph;

namespace {

const std::string kBase = R"(schema_version = 1
name = "base"

[numerics]
dx = 0.01
end_time = 1.0

[numerics.domain]
min = [-0.5, -0.5]
max = [2.0, 2.0]

[fluid]
sound_speed = 20.0

[[fluid.block]]
min = [0.0, 0.0]
max = [1.0, 0.5]

[materials.rubber]
density = 1100.0
youngs_modulus = 1.2e7
poisson_ratio = 0.4

[[body]]
name = "tank"
kind = "rigid_fixed"

[body.shape]
type = "tank"
min = [0.0, 0.0]
max = [1.0, 1.0]

[[body]]
name = "cyl"
material = "rubber"

[body.shape]
type = "disc"
centre = [0.5, 0.7]
radius = 0.1

[output]

[[output.probe]]
name = "bp"
kind = "body_pressure"
body = "cyl"
position = [0.5, 0.6]
)";

// Replace the n-th (1-based) occurrence of a whole line.
std::string replace_line(std::string text, const std::string& from, const std::string& to,
                         int occurrence = 1) {
  std::size_t pos = 0;
  for (int k = 0; k < occurrence; ++k) {
    pos = text.find(from + "\n", k == 0 ? 0 : pos + 1);
    while (pos != std::string::npos && pos > 0 && text[pos - 1] != '\n')
      pos = text.find(from + "\n", pos + 1);
    if (pos == std::string::npos) throw std::logic_error("test: line not found: " + from);
  }
  return text.replace(pos, from.size(), to);
}

// 1-based line of the first line starting with `start`.
int line_of(const std::string& text, const std::string& start, int occurrence = 1) {
  int line = 1, seen = 0;
  std::size_t b = 0;
  while (b < text.size()) {
    const std::size_t e = text.find('\n', b);
    if (text.compare(b, start.size(), start) == 0 && ++seen == occurrence) return line;
    if (e == std::string::npos) break;
    b = e + 1;
    ++line;
  }
  throw std::logic_error("test: no line starts with " + start);
}

std::string error_of(const std::string& text) {
  try {
    parse_case_string(text, "cases/bad.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// Asserts the message starts with "cases/bad.toml:<line>: <key>: " and contains `part`.
void expect_error(const std::string& text, int line, const std::string& key,
                  const std::string& part = "") {
  const std::string msg = error_of(text);
  const std::string prefix = "cases/bad.toml:" + std::to_string(line) + ": " + key + ": ";
  EXPECT_EQ(msg.rfind(prefix, 0), 0u) << "message: " << msg << "\nexpected prefix: " << prefix;
  EXPECT_NE(msg.find("; expected "), std::string::npos) << msg;
  if (!part.empty()) {
    EXPECT_NE(msg.find(part), std::string::npos) << msg << "\nmissing: " << part;
  }
}

}  // namespace

TEST(IoCaseErrors, BaseCaseIsValid) {
  EXPECT_EQ(error_of(kBase), "(no error)");
}

TEST(IoCaseErrors, MalformedToml) {
  const std::string t = replace_line(kBase, "end_time = 1.0", "end_time = = 1.0");
  expect_error(t, line_of(t, "end_time"), "(toml syntax)", "valid TOML");
}

TEST(IoCaseErrors, UnknownKeySuggestsNearest) {
  const std::string t = replace_line(kBase, "sound_speed = 20.0", "sound_sped = 20.0");
  expect_error(t, line_of(t, "sound_sped"), "fluid.sound_sped", "did you mean 'sound_speed'?");
  const std::string b = replace_line(kBase, "radius = 0.1", "radus = 0.1");
  expect_error(b, line_of(b, "radus"), "body[1].shape.radus", "did you mean 'radius'?");
  const std::string top = replace_line(kBase, "name = \"base\"", "nmae = \"base\"");
  expect_error(top, 2, "nmae", "did you mean 'name'?");
}

TEST(IoCaseErrors, KeyNotValidForBodyKind) {
  const std::string t =
      replace_line(kBase, "kind = \"rigid_fixed\"", "kind = \"rigid_fixed\"\nscheme = \"tlsph\"");
  expect_error(t, line_of(t, "scheme"), "body[0].scheme",
               "unknown key for a body of kind 'rigid_fixed'");
}

TEST(IoCaseErrors, MissingRequiredKeyReportsTableLine) {
  const std::string t = replace_line(kBase, "dx = 0.01", "");
  expect_error(t, line_of(t, "[numerics]"), "numerics.dx", "missing required key");
  const std::string s = replace_line(kBase, "sound_speed = 20.0", "");
  expect_error(s, line_of(s, "[fluid]"), "fluid.sound_speed", "missing required key");
  const std::string r = replace_line(kBase, "radius = 0.1", "");
  expect_error(r, line_of(r, "[body.shape]", 2), "body[1].shape.radius", "missing required key");
  const std::string v = replace_line(kBase, "schema_version = 1", "");
  expect_error(v, 1, "schema_version", "missing required key");
}

TEST(IoCaseErrors, WrongType) {
  const std::string t = replace_line(kBase, "dx = 0.01", "dx = \"0.01\"");
  expect_error(t, line_of(t, "dx"), "numerics.dx",
               "wrong type; expected a positive length in m, got a string");
  const std::string v = replace_line(kBase, "centre = [0.5, 0.7]", "centre = [0.5, 0.7, 0.0]");
  expect_error(v, line_of(v, "centre"), "body[1].shape.centre", "wrong length");
  const std::string b = replace_line(kBase, "name = \"cyl\"", "name = \"cyl\"\ngravity = 1");
  expect_error(b, line_of(b, "gravity"), "body[1].gravity",
               "expected true or false, got an integer");
}

TEST(IoCaseErrors, IntegersAcceptedWhereFloatsExpected) {
  const std::string t = replace_line(kBase, "end_time = 1.0", "end_time = 2");
  EXPECT_EQ(parse_case_string(t, "x").numerics.end_time, 2.0);
}

TEST(IoCaseErrors, NonPositiveDx) {
  const std::string t = replace_line(kBase, "dx = 0.01", "dx = -0.01");
  EXPECT_EQ(error_of(t),
            "cases/bad.toml:" + std::to_string(line_of(t, "dx")) +
                ": numerics.dx: must be > 0; expected a positive length in m, got -0.01");
  const std::string b = replace_line(kBase, "name = \"cyl\"", "name = \"cyl\"\ndx = 0");
  expect_error(b, line_of(b, "dx = 0", 2), "body[1].dx", "must be > 0");
}

TEST(IoCaseErrors, SpacingRatioOutOfRange) {
  // Water coarser than the body by 1-8x is supported (docs/model.md §4); outside is an error,
  // whether given as spacing_ratio or through an explicit body dx.
  for (const char* r : {"0.5", "9", "16"}) {
    const std::string t =
        replace_line(kBase, "name = \"cyl\"", std::string("name = \"cyl\"\nspacing_ratio = ") + r);
    expect_error(t, line_of(t, "spacing_ratio"), "body[1].spacing_ratio", "must be in [1, 8]");
  }
  for (const char* dx : {"0.001", "0.02"}) {  // ratios 10 and 0.5
    const std::string t =
        replace_line(kBase, "name = \"cyl\"", std::string("name = \"cyl\"\ndx = ") + dx);
    expect_error(t, line_of(t, "dx = ", 2), "body[1].dx", "spacing ratio numerics.dx / dx");
  }
  const std::string both =
      replace_line(kBase, "name = \"cyl\"", "name = \"cyl\"\ndx = 0.005\nspacing_ratio = 2");
  expect_error(both, line_of(both, "spacing_ratio"), "body[1].spacing_ratio", "not both");
  // In range: the body spacing follows the water's.
  for (double r : {1.0, 2.0, 4.0, 8.0}) {
    const std::string t = replace_line(kBase, "name = \"cyl\"",
                                       "name = \"cyl\"\nspacing_ratio = " + std::to_string(r));
    EXPECT_DOUBLE_EQ(parse_case_string(t, "x").bodies[1].dx, 0.01 / r);
  }
  const std::string eight = replace_line(kBase, "name = \"cyl\"", "name = \"cyl\"\ndx = 0.00125");
  EXPECT_EQ(error_of(eight), "(no error)");
}

TEST(IoCaseErrors, NonPositiveDensity) {
  const std::string t = replace_line(kBase, "density = 1100.0", "density = -1100.0");
  expect_error(t, line_of(t, "density"), "materials.rubber.density", "must be > 0");
  const std::string f =
      replace_line(kBase, "sound_speed = 20.0", "sound_speed = 20.0\ndensity = 0");
  expect_error(f, line_of(f, "density"), "fluid.density", "got 0.0");
}

TEST(IoCaseErrors, PoissonRatioOutOfRange) {
  for (const char* nu : {"0.5", "-1.0", "0.7"}) {
    const std::string t =
        replace_line(kBase, "poisson_ratio = 0.4", std::string("poisson_ratio = ") + nu);
    expect_error(t, line_of(t, "poisson_ratio"), "materials.rubber.poisson_ratio",
                 "must be in (-1, 0.5)");
  }
}

TEST(IoCaseErrors, NonPositiveEndTime) {
  const std::string t = replace_line(kBase, "end_time = 1.0", "end_time = 0.0");
  expect_error(t, line_of(t, "end_time"), "numerics.end_time", "must be > 0");
}

TEST(IoCaseErrors, FluidBlockOutsideDomain) {
  const std::string t = replace_line(kBase, "max = [1.0, 0.5]", "max = [2.5, 0.5]");
  expect_error(t, line_of(t, "max = [2.5"), "fluid.block[0].max", "outside the domain");
}

TEST(IoCaseErrors, FluidBlockOutsideTankInnerBox) {
  const std::string t = replace_line(kBase, "max = [1.0, 0.5]", "max = [1.2, 0.5]");
  expect_error(t, line_of(t, "max = [1.2"), "fluid.block[0].max", "outside the tank's inner box");
}

TEST(IoCaseErrors, BoxMinNotBelowMax) {
  const std::string t = replace_line(kBase, "max = [1.0, 0.5]", "max = [1.0, 0.0]");
  expect_error(t, line_of(t, "max = [1.0, 0.0]"), "fluid.block[0].max", "must exceed min");
  const std::string d = replace_line(kBase, "max = [2.0, 2.0]", "max = [-1.0, 2.0]");
  expect_error(d, line_of(d, "max = [-1.0"), "numerics.domain.max", "must exceed min");
}

TEST(IoCaseErrors, ClampBoxAndBoxesTogether) {
  const std::string one = "radius = 0.1\n[body.clamp]\nbox = {min = [0.4, 0.6], max = [0.6, 0.65]}";
  const std::string t = replace_line(kBase, "radius = 0.1",
                                     one + "\nboxes = [{min = [0.4, 0.75], max = [0.6, 0.8]}]");
  expect_error(t, line_of(t, "boxes ="), "body[1].clamp.boxes", "not both");
  const std::string e =
      replace_line(kBase, "radius = 0.1", "radius = 0.1\n[body.clamp]\nboxes = []");
  expect_error(e, line_of(e, "boxes ="), "body[1].clamp.boxes", "empty list");
  const std::string b =
      replace_line(kBase, "radius = 0.1",
                   "radius = 0.1\n[body.clamp]\nboxes = [{min = [0.4, 0.6], max = [0.6, 0.65]}, "
                   "{min = [0.4, 0.8], max = [0.3, 0.9]}]");
  expect_error(b, line_of(b, "boxes ="), "body[1].clamp.boxes[1].max", "must exceed min");
}

TEST(IoCaseErrors, BodyShapeOutsideDomain) {
  const std::string t = replace_line(kBase, "centre = [0.5, 0.7]", "centre = [1.95, 0.7]");
  expect_error(t, line_of(t, "[body.shape]", 2), "body[1].shape", "body 'cyl'");
  // Tank walls (4 layers of 0.01 m) stick out below a domain starting at -0.02.
  const std::string w = replace_line(kBase, "min = [-0.5, -0.5]", "min = [-0.5, -0.02]");
  expect_error(w, line_of(w, "[body.shape]", 1), "body[0].shape", "outside the domain");
}

TEST(IoCaseErrors, UnknownMaterial) {
  const std::string t = replace_line(kBase, "material = \"rubber\"", "material = \"ruber\"");
  expect_error(t, line_of(t, "material = "), "body[1].material", "did you mean 'rubber'?");
}

TEST(IoCaseErrors, UnknownEnumerations) {
  const std::string k = replace_line(kBase, "dx = 0.01", "dx = 0.01\nkernel = \"wendland\"");
  expect_error(k, line_of(k, "kernel"), "numerics.kernel", "unknown value");
  const std::string kind = replace_line(kBase, "kind = \"rigid_fixed\"", "kind = \"rigid_fxed\"");
  expect_error(kind, line_of(kind, "kind"), "body[0].kind", "did you mean 'rigid_fixed'?");
  const std::string sch =
      replace_line(kBase, "material = \"rubber\"", "material = \"rubber\"\nscheme = \"sph\"");
  expect_error(sch, line_of(sch, "scheme"), "body[1].scheme", "'tl_sfpm', 'tlsph'");
  const std::string shp = replace_line(kBase, "type = \"disc\"", "type = \"circle\"");
  expect_error(shp, line_of(shp, "type = \"circle\""), "body[1].shape.type", "unknown value");
  const std::string pk = replace_line(kBase, "kind = \"body_pressure\"", "kind = \"presure\"");
  expect_error(pk, line_of(pk, "kind = \"presure\""), "output.probe[0].kind",
               "did you mean 'pressure'?");
}

TEST(IoCaseErrors, ProbeNamesUnknownBody) {
  const std::string t = replace_line(kBase, "body = \"cyl\"", "body = \"cylinder\"");
  expect_error(t, line_of(t, "body = "), "output.probe[0].body", "unknown body");
}

// Structural probes (app/probes.h): strain and stress need an elastic body; two-point
// probes need both points, distinct; keys of other kinds are refused.
TEST(IoCaseErrors, StructuralProbes) {
  const std::string rigid =
      replace_line(replace_line(kBase, "kind = \"body_pressure\"", "kind = \"body_strain\""),
                   "body = \"cyl\"", "body = \"tank\"");
  expect_error(rigid, line_of(rigid, "body = \"tank\""), "output.probe[0].body",
               "reads the strain or stress of an elastic body");
  const std::string no_to =
      replace_line(kBase, "kind = \"body_pressure\"", "kind = \"shortening\"");
  expect_error(no_to, line_of(no_to, "[[output.probe]]"), "output.probe[0].to",
               "missing required key");
  const std::string same =
      replace_line(no_to, "position = [0.5, 0.6]", "position = [0.5, 0.6]\nto = [0.5, 0.6]");
  expect_error(same, line_of(same, "to = "), "output.probe[0].to", "the same point as position");
  const std::string extra =
      replace_line(kBase, "kind = \"body_pressure\"", "kind = \"keel_deflection\"");
  expect_error(extra, line_of(extra, "position = [0.5, 0.6]"), "output.probe[0].position",
               "for probe kind 'keel_deflection'");
  const std::string outside = replace_line(same, "to = [0.5, 0.6]", "to = [5.0, 0.6]");
  expect_error(outside, line_of(outside, "to = "), "output.probe[0].to", "outside the domain");
}

// [output] snapshots, snapshot_view and skin_profile (app/snapshots.h).
TEST(IoCaseErrors, SnapshotsAndSkinProfile) {
  const std::string order = replace_line(kBase, "[output]", "[output]\nsnapshots = [0.5, 0.2]");
  expect_error(order, line_of(order, "snapshots"), "output.snapshots",
               "not after the one before it");
  const std::string late = replace_line(kBase, "[output]", "[output]\nsnapshots = [2.0]");
  expect_error(late, line_of(late, "snapshots"), "output.snapshots", "outside (0, end_time]");
  const std::string type = replace_line(kBase, "[output]", "[output]\nsnapshots = [0.1, \"a\"]");
  expect_error(type, line_of(type, "snapshots"), "output.snapshots[1]", "wrong type");
  const std::string disc =
      replace_line(kBase, "[output]", "[output]\nsnapshots = [0.5]\nskin_profile = \"cyl\"");
  expect_error(disc, line_of(disc, "skin_profile"), "output.skin_profile",
               "elastic body of shape type 'ring' or 'fuselage'");
  // The disc as a ring (its radius line dropped; a ring takes inner and outer radii).
  const std::string ringed = replace_line(
      replace_line(kBase, "type = \"disc\"",
                   "type = \"ring\"\ninner_radius = 0.09\nouter_radius = 0.1\nlayers = 2"),
      "radius = 0.1", "");
  const std::string nosnap = replace_line(ringed, "[output]", "[output]\nskin_profile = \"cyl\"");
  expect_error(nosnap, line_of(nosnap, "skin_profile"), "output.skin_profile",
               "output.snapshots = [t1, t2, ...] as well");
  const std::string view =
      replace_line(kBase, "[output]",
                   "[output]\nsnapshots = [0.5]\nsnapshot_view = {min = [1, 1], max = [0, 2]}");
  expect_error(view, line_of(view, "snapshot_view"), "output.snapshot_view.max", "must exceed min");
  const std::string ok =
      replace_line(ringed, "[output]", "[output]\nsnapshots = [0.25, 0.5]\nskin_profile = \"cyl\"");
  EXPECT_EQ(error_of(ok), "(no error)");
}

TEST(IoCaseErrors, NoParticles) {
  const std::string t = R"(schema_version = 1
name = "empty"
[numerics]
dx = 0.01
end_time = 1.0
[numerics.domain]
min = [0, 0]
max = [1, 1]
)";
  expect_error(t, 1, "case", "no particles");
}

TEST(IoCaseErrors, SchemaVersionAndDuplicates) {
  const std::string v = replace_line(kBase, "schema_version = 1", "schema_version = 2");
  expect_error(v, 1, "schema_version", "unsupported");
  const std::string d = replace_line(kBase, "name = \"cyl\"", "name = \"tank\"");
  expect_error(d, line_of(d, "name = \"tank\"", 2), "body[1].name", "duplicate body name");
}

TEST(IoCaseErrors, LoadCaseNamesTheFile) {
  const std::string path = ::testing::TempDir() + "slamsph_bad_case.toml";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    const std::string t = replace_line(kBase, "dx = 0.01", "dx = -0.01");
    std::fputs(t.c_str(), f);
    std::fclose(f);
  }
  try {
    load_case(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ":5: numerics.dx: must be > 0", 0), 0u)
        << e.what();
  }
  EXPECT_THROW(load_case(path + ".missing"), InputError);
}

TEST(IoCaseErrors, MaterialModelUnknownOrWithWrongParameters) {
  const std::string u = replace_line(kBase, "density = 1100.0", "model = \"j2\"\ndensity = 1100.0");
  expect_error(u, line_of(u, "model"), "materials.rubber.model", "j2_linear_hardening");
  // j2_linear_hardening needs both of its parameters (missing: the table's line).
  const std::string j =
      replace_line(kBase, "density = 1100.0",
                   "model = \"j2_linear_hardening\"\nyield_stress = 3e5\ndensity = 1100.0");
  expect_error(j, line_of(j, "[materials.rubber]"), "materials.rubber.hardening_modulus",
               "missing required key");
  const std::string n =
      replace_line(j, "yield_stress = 3e5", "yield_stress = -3e5\nhardening_modulus = 1e6");
  expect_error(n, line_of(n, "yield_stress"), "materials.rubber.yield_stress", "must be > 0");
  const std::string h =
      replace_line(j, "yield_stress = 3e5", "yield_stress = 3e5\nhardening_modulus = -1");
  expect_error(h, line_of(h, "hardening_modulus"), "materials.rubber.hardening_modulus",
               "must be >= 0");
  // A plasticity key on an elastic model is an unknown key, not silently ignored.
  const std::string s =
      replace_line(kBase, "density = 1100.0", "density = 1100.0\nyield_stress = 3e5");
  expect_error(s, line_of(s, "yield_stress"), "materials.rubber.yield_stress",
               "for material model 'svk'");
}

TEST(IoCaseErrors, MaterialModelParsedToTypedValue) {
  const std::string j =
      replace_line(kBase, "density = 1100.0",
                   "model = \"j2_linear_hardening\"\nyield_stress = 3e5\nhardening_modulus = 2e6\n"
                   "density = 1100.0");
  const CaseConfig c = parse_case_string(j, "cases/j2.toml");
  const auto* m = std::get_if<J2LinearHardeningModel>(&c.find_material("rubber")->model);
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->yield_stress, 3e5);
  EXPECT_EQ(m->hardening_modulus, 2e6);
  // The resolved copy names the model and its parameters and parses back to the same.
  const CaseConfig back = parse_case_string(resolved_case_toml(c), "cases/j2.resolved.toml");
  EXPECT_EQ(back.find_material("rubber")->model, c.find_material("rubber")->model);
  EXPECT_TRUE(std::holds_alternative<SvkModel>(
      parse_case_string(kBase, "cases/base.toml").find_material("rubber")->model));
}

TEST(IoCaseErrors, AbsorbingZoneIsChecked) {
  const std::string zone = "[fluid.absorbing_zone]\nbottom = 0.1\nright = 0.2\n\n[[fluid.block]]";
  const std::string ok = replace_line(kBase, "[[fluid.block]]", zone);
  EXPECT_EQ(error_of(ok), "(no error)");
  const std::string wide = replace_line(ok, "bottom = 0.1", "bottom = 1.5");
  expect_error(wide, line_of(wide, "bottom"), "fluid.absorbing_zone.bottom",
               "wider than the tank's inner box (1 m)");
  const std::string both = replace_line(ok, "bottom = 0.1", "left = 0.9");
  expect_error(both, line_of(both, "right"), "fluid.absorbing_zone.right",
               "left + right bands cover the whole tank width");
  const std::string none =
      replace_line(replace_line(ok, "bottom = 0.1", "bottom = 0"), "right = 0.2", "strength = 5");
  expect_error(none, line_of(none, "[fluid.absorbing_zone]"), "fluid.absorbing_zone.left",
               "no wall has a zone");
  const std::string neg = replace_line(ok, "right = 0.2", "right = -0.2");
  expect_error(neg, line_of(neg, "right"), "fluid.absorbing_zone.right", "must be >= 0");
  const std::string weak = replace_line(ok, "right = 0.2", "strength = 0");
  expect_error(weak, line_of(weak, "strength"), "fluid.absorbing_zone.strength", "must be > 0");
  const std::string typo = replace_line(ok, "right = 0.2", "rigth = 0.2");
  expect_error(typo, line_of(typo, "rigth"), "fluid.absorbing_zone.rigth", "did you mean 'right'?");
  // Without a tank there are no walls to line.
  const std::string no_tank = replace_line(ok, "type = \"tank\"", "type = \"rectangle\"");
  expect_error(no_tank, line_of(no_tank, "[fluid.absorbing_zone]"), "fluid.absorbing_zone.left",
               "the case has no tank");
}

// Polygon fill (docs/case_format.md): "faces" is refused on an elastic body (its face/interior
// junction is not a regular TL-SFPM neighbourhood, docs/model.md §3) with the key's line;
// an unknown value gets the choices.
TEST(IoCaseErrors, PolygonFaceFillRefusedForElasticBodies) {
  const std::string poly = replace_line(
      replace_line(replace_line(kBase, "type = \"disc\"", "type = \"polygon\""),
                   "centre = [0.5, 0.7]", "vertices = [[0.4, 0.7], [0.6, 0.7], [0.5, 0.8]]"),
      "radius = 0.1", "fill = \"faces\"");
  expect_error(poly, line_of(poly, "fill = "), "body[1].shape.fill", "elastic");
  const std::string typo = replace_line(poly, "fill = \"faces\"", "fill = \"face\"");
  expect_error(typo, line_of(typo, "fill = "), "body[1].shape.fill", "faces");
  const std::string cart = replace_line(poly, "fill = \"faces\"", "fill = \"cartesian\"");
  EXPECT_EQ(parse_case_string(cart, "x").bodies[1].shape.fill, PolygonFill::Cartesian);
  // Without the key an elastic polygon gets the Cartesian lattice.
  const std::string none = replace_line(poly, "fill = \"faces\"", "");
  EXPECT_EQ(parse_case_string(none, "x").bodies[1].shape.fill, PolygonFill::Cartesian);
}

TEST(IoCaseErrors, PreFailedNeedsAMaterialThatCanFail) {
  const std::string t = replace_line(
      kBase, "radius = 0.1",
      "radius = 0.1\n[body.pre_failed]\nbox = {min = [0.45, 0.6], max = [0.55, 0.65]}");
  expect_error(t, line_of(t, "[body.pre_failed]"), "body[1].pre_failed",
               "only a material that can fail");
}

TEST(IoCaseErrors, FluidVolumeProbeNeedsABox) {
  const std::string t = replace_line(kBase, "kind = \"body_pressure\"", "kind = \"fluid_volume\"");
  expect_error(t, line_of(t, "body = \"cyl\""), "output.probe[0].body", "unknown key");
  const std::string m =
      replace_line(replace_line(t, "body = \"cyl\"", ""), "position = [0.5, 0.6]", "");
  expect_error(m, line_of(m, "[[output.probe]]"), "output.probe[0].box", "missing");
}

// numerics.fluid_integrator (docs/case_format.md): one of the two names, kick-drift-kick by
// default; the symplectic step takes every body kind (here an elastic disc in a fixed tank).
TEST(IoCaseErrors, FluidIntegratorIsChecked) {
  const std::string at = "end_time = 1.0";
  const std::string bad = replace_line(kBase, at, at + "\nfluid_integrator = \"leapfrog\"");
  expect_error(bad, line_of(bad, "fluid_integrator"), "numerics.fluid_integrator",
               "one of 'kick_drift_kick', 'symplectic'");
  const std::string sym = replace_line(kBase, at, at + "\nfluid_integrator = \"symplectic\"");
  EXPECT_EQ(parse_case_string(sym, "x").numerics.fluid_integrator, FluidIntegrator::Symplectic);
  EXPECT_EQ(parse_case_string(kBase, "x").numerics.fluid_integrator,
            FluidIntegrator::KickDriftKick);
}
