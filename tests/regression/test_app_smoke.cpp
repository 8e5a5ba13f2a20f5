// Smoke test of every shipped case (cases/*.toml and cases/fuselage/*.toml, discovered at run
// time): `slamsph run CASE --max-steps 3 --threads 1` (fuselage: 2 steps, water at 12 mm) exits 0
// and writes summary.json and case.resolved.toml; the resolved copy is itself a valid case
// (`slamsph check` exits 0) that builds the same particles as the original and, run again, writes
// byte-identical CSV outputs.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> case_files() {
  std::vector<std::string> v;
  for (const char* dir : {"cases", "cases/fuselage"})
    for (const auto& e : fs::directory_iterator(fs::path(SLAMSPH_SOURCE_DIR) / dir))
      if (e.path().extension() == ".toml") v.push_back(e.path().string());
  std::sort(v.begin(), v.end());
  return v;
}

// The fuselage cases (paper §4.2–4.4) at full size take ~1 s per fluid step on one thread:
// the smoke test coarsens their water to 12 mm (8x the 2-layer skin, the largest supported
// ratio) and runs 2 steps; the structure (skin, stringers, floor, columns) is unchanged.
std::string reduced_args(const fs::path& src) {
  return src.parent_path().filename() == "fuselage" ? " --dx 0.012 --max-steps 2"
                                                    : " --max-steps 3";
}
int reduced_steps(const fs::path& src) {
  return src.parent_path().filename() == "fuselage" ? 2 : 3;
}

struct Cli {
  int code = -1;
  std::string out, err;
};

Cli run_cli(const std::string& args, const fs::path& capture) {
  std::ostringstream cmd;
  cmd << "'" << SLAMSPH_BINARY << "' " << args << " > '" << (capture / "stdout.txt").string()
      << "' 2> '" << (capture / "stderr.txt").string() << "'";
  const int st = std::system(cmd.str().c_str());
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, slurp(capture / "stdout.txt"),
          slurp(capture / "stderr.txt")};
}

// "name: ok (N fluid particles, body: M, ...)" and the predicted counts, without the leading
// case name and without the lines that depend on this machine's measured speed (the machine
// factors and the CPU and wall times, app/cost_model.h).
std::string counts(const std::string& check_out) {
  const std::size_t at = check_out.find(": ok (");
  if (at == std::string::npos) return std::string();
  std::istringstream in(check_out.substr(at));
  std::string line, out;
  while (std::getline(in, line))
    if (line.rfind("machine:", 0) != 0 && line.rfind("predicted CPU", 0) != 0 &&
        line.rfind("predicted wall", 0) != 0)
      out += line + "\n";
  return out;
}

class CaseSmoke : public ::testing::TestWithParam<std::string> {};

TEST(CaseSmokeDiscovery, FindsTheShippedCases) {
  const std::vector<std::string> files = case_files();
  EXPECT_GE(files.size(), 4u);
  const auto has = [&](const char* stem) {
    return std::any_of(files.begin(), files.end(),
                       [&](const std::string& f) { return fs::path(f).stem() == stem; });
  };
  EXPECT_TRUE(has("elastic_cylinder_entry"));
  EXPECT_TRUE(has("dam_break"));
  for (const char* f : {"skin_cylinder", "skin_stringer_I", "skin_stringer_L",
                        "skin_L_floor_column", "skin_I_floor_column"})
    EXPECT_TRUE(has(f)) << f;
}

TEST_P(CaseSmoke, RunsThreeStepsAndResolvedCopyIsValid) {
  ASSERT_TRUE(fs::exists(SLAMSPH_BINARY)) << "build the slamsph target first";
  const fs::path src = GetParam();
  const fs::path root = fs::temp_directory_path() /
                        ("slamsph_smoke_" + src.stem().string() + "_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const fs::path out = root / "out";

  const Cli r = run_cli("run '" + src.string() + "'" + reduced_args(src) +
                            " --threads 1 --quiet --out '" + out.string() + "'",
                        root);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string summary = slurp(out / "summary.json");
  // Ended by --max-steps before end_time: "stopped", not "completed" (issue 12).
  EXPECT_NE(summary.find("\"status\": \"stopped\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"fluid_steps\": " + std::to_string(reduced_steps(src)) + ","),
            std::string::npos)
      << summary;
  ASSERT_TRUE(fs::exists(out / "case.resolved.toml"));

  const std::string dx = src.parent_path().filename() == "fuselage" ? " --dx 0.012" : "";
  const Cli orig = run_cli("check '" + src.string() + "'" + dx, root);
  const Cli resolved = run_cli("check '" + (out / "case.resolved.toml").string() + "'", root);
  EXPECT_EQ(orig.code, 0) << orig.err;
  EXPECT_EQ(resolved.code, 0) << resolved.err;
  EXPECT_NE(counts(orig.out), "") << orig.out;
  EXPECT_EQ(counts(resolved.out), counts(orig.out)) << "the resolved case builds other particles";
  std::printf("%s%s", src.filename().c_str(), counts(orig.out).c_str());

  // The resolved copy run again gives the same first steps, byte for byte (same case).
  const fs::path out2 = root / "out2";
  const Cli r2 = run_cli("run '" + (out / "case.resolved.toml").string() + "' --max-steps " +
                             std::to_string(reduced_steps(src)) + " --threads 1 --quiet --out '" +
                             out2.string() + "'",
                         root);
  EXPECT_EQ(r2.code, 0) << r2.err;
  for (const char* f : {"forces.csv", "probes.csv", "bodies.csv"}) {
    EXPECT_EQ(fs::exists(out / f), fs::exists(out2 / f)) << f;
    EXPECT_TRUE(slurp(out / f) == slurp(out2 / f)) << f << " differs for the resolved copy";
  }
  if (!HasFailure()) fs::remove_all(root);
}

INSTANTIATE_TEST_SUITE_P(Cases, CaseSmoke, ::testing::ValuesIn(case_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string s = fs::path(info.param).stem().string();
                           for (char& c : s)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return s;
                         });

}  // namespace
