// The slamsph binary on bad input (README "Exit codes", docs/case_format.md "Errors"): every
// class of case-file error and every bad command line exits 2 with one message on stderr
// that names the file, the line and the key, writes nothing to stdout and creates no output
// folder. A good case passes `slamsph check` with exit 0.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// A tiny valid case: 100 water particles in a tank. Line numbers matter to the tests below.
const char* kGood =
    "schema_version = 1\n"      // 1
    "name = \"tiny\"\n"         // 2
    "\n"                        // 3
    "[numerics]\n"              // 4
    "dx = 0.05\n"               // 5
    "end_time = 0.05\n"         // 6
    "[numerics.domain]\n"       // 7
    "min = [-0.5, -0.5]\n"      // 8
    "max = [1.5, 1.5]\n"        // 9
    "\n"                        // 10
    "[fluid]\n"                 // 11
    "sound_speed = 20.0\n"      // 12
    "[[fluid.block]]\n"         // 13
    "min = [0.0, 0.0]\n"        // 14
    "max = [0.5, 0.5]\n"        // 15
    "\n"                        // 16
    "[[body]]\n"                // 17
    "name = \"tank\"\n"         // 18
    "kind = \"rigid_fixed\"\n"  // 19
    "[body.shape]\n"            // 20
    "type = \"tank\"\n"         // 21
    "min = [0.0, 0.0]\n"        // 22
    "max = [1.0, 1.0]\n";       // 23

// kGood with the first occurrence of `from` replaced by `to` (fails the test if absent).
std::string edit(const std::string& from, const std::string& to) {
  std::string s = kGood;
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << from << "' not in the base case";
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// s with the first occurrence of `from` replaced by `to`.
std::string with(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << "test bug: '" << from << "' not in the text";
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

struct CliResult {
  int code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A fresh temporary folder per test: work/ is the current directory of the binary, capture/
// receives its stdout and stderr (so work/ can be checked for stray files).
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::exists(SLAMSPH_BINARY)) << "build the slamsph target first";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            ("slamsph_cli_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(work());
    fs::create_directories(root_ / "capture");
  }
  void TearDown() override {
    if (!HasFailure())
      fs::remove_all(root_);
    else
      std::printf("kept %s for inspection\n", root_.c_str());
  }
  fs::path work() const { return root_ / "work"; }

  void write_case(const std::string& name, const std::string& text) const {
    std::ofstream(work() / name) << text;
  }

  CliResult run(const std::string& args) const {
    const fs::path out = root_ / "capture" / "stdout.txt";
    const fs::path err = root_ / "capture" / "stderr.txt";
    const std::string cmd = "cd '" + work().string() + "' && '" + SLAMSPH_BINARY + "' " + args +
                            " >'" + out.string() + "' 2>'" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  // Files in work/ other than the case files we wrote.
  std::vector<std::string> stray_files(const std::vector<std::string>& ours) const {
    std::vector<std::string> stray;
    for (const auto& e : fs::directory_iterator(work())) {
      const std::string n = e.path().filename().string();
      if (std::find(ours.begin(), ours.end(), n) == ours.end()) stray.push_back(n);
    }
    return stray;
  }

  fs::path root_;
};

struct BadCase {
  const char* label;
  std::string text;
  int line;                       // expected line in "bad.toml:<line>:"
  const char* key;                // expected key path after the line
  std::vector<const char*> also;  // further fragments the message must contain
};

std::vector<BadCase> bad_cases() {
  return {
      {"malformed TOML (unclosed table header)",
       edit("[numerics]\n", "[numerics\n"),
       4,
       "(toml syntax)",
       {"expected valid TOML"}},
      {"unknown key with a suggestion",
       edit("sound_speed = 20.0", "sound_sped = 20.0"),
       12,
       "fluid.sound_sped",
       {"unknown key", "did you mean 'sound_speed'"}},
      {"unknown enumeration value with a suggestion",
       edit("kind = \"rigid_fixed\"", "kind = \"rigid_fixd\""),
       19,
       "body[0].kind",
       {"did you mean 'rigid_fixed'"}},
      {"unknown key for the shape type",
       edit("type = \"tank\"\n", "type = \"tank\"\nradius = 1\n"),
       22,
       "body[0].shape.radius",
       {"unknown key"}},
      {"missing required key (line of its table)",
       edit("dx = 0.05\n", ""),
       4,
       "numerics.dx",
       {"missing required key"}},
      {"missing required key in an array of tables",
       edit("type = \"tank\"\n", ""),
       20,
       "body[0].shape.type",
       {"missing required key"}},
      {"wrong type (string for a length)",
       edit("dx = 0.05", "dx = \"small\""),
       5,
       "numerics.dx",
       {"wrong type"}},
      {"wrong type (number for a vector)",
       edit("end_time = 0.05\n", "end_time = 0.05\ngravity = 9.81\n"),
       7,
       "numerics.gravity",
       {"wrong type"}},
      {"dx = 0", edit("dx = 0.05", "dx = 0.0"), 5, "numerics.dx", {"must be > 0"}},
      {"dx < 0", edit("dx = 0.05", "dx = -0.05"), 5, "numerics.dx", {"must be > 0", "-0.05"}},
      {"negative density",
       edit("sound_speed = 20.0\n", "sound_speed = 20.0\ndensity = -1000.0\n"),
       13,
       "fluid.density",
       {"-1000"}},
      {"negative sound speed",
       edit("sound_speed = 20.0", "sound_speed = -20.0"),
       12,
       "fluid.sound_speed",
       {}},
      {"h_over_dx out of range",
       edit("dx = 0.05\n", "dx = 0.05\nh_over_dx = 5.0\n"),
       6,
       "numerics.h_over_dx",
       {}},
      {"domain with min >= max",
       edit("max = [1.5, 1.5]", "max = [1.5, -0.6]"),
       9,
       "numerics.domain.max",
       {"min < max"}},
      {"fluid outside the tank",
       edit("max = [0.5, 0.5]", "max = [1.2, 0.5]"),
       15,
       "fluid.block[0].max",
       {"tank"}},
      {"fluid outside the domain",
       edit("max = [0.5, 0.5]", "max = [0.5, 1.7]"),
       15,
       "fluid.block[0].max",
       {"domain"}},
      // Issue 12: inputs `check` accepted and the run then crashed on or lost.
      {"body with no particles (thinner than dx) and a probe on it",
       std::string(kGood) +
           "[[body]]\nname = \"sliver\"\nkind = \"rigid_fixed\"\n[body.shape]\n"
           "type = \"polygon\"\nvertices = [[0.61, 0.61], [0.69, 0.61], [0.69, 0.62], "
           "[0.61, 0.62]]\n[output]\n[[output.probe]]\nname = \"p\"\n"
           "kind = \"body_pressure\"\nbody = \"sliver\"\nposition = [0.65, 0.615]\n",
       27,
       "body[1].shape",
       {"has no particles"}},
      {"body name with a space",
       edit("name = \"tank\"", "name = \"my tank\""),
       18,
       "body[0].name",
       {"unusable as a file name"}},
      {"body name with a slash",
       edit("name = \"tank\"", "name = \"a/b\""),
       18,
       "body[0].name",
       {"unusable as a file name"}},
      {"body named fluid",
       edit("name = \"tank\"", "name = \"fluid\""),
       18,
       "body[0].name",
       {"'fluid'"}},
      {"probe CSV columns clash",
       std::string(kGood) +
           "[output]\n[[output.probe]]\nname = \"a\"\nkind = \"body_displacement\"\n"
           "body = \"tank\"\nposition = [0.0, 0.0]\n[[output.probe]]\nname = \"a_x\"\n"
           "kind = \"pressure\"\nposition = [0.2, 0.2]\n",
       31,
       "output.probe[1].name",
       {"clashes"}},
      {"dam-break plot without gravity",
       edit("end_time = 0.05\n", "end_time = 0.05\ngravity = [0.0, 0.0]\n") +
           "[output]\nplot = \"dam_break\"\n",
       26,
       "output.plot",
       {"gravity"}},
      {"material too stiff for the fluid step",
       std::string(kGood) +
           "[materials.steel]\ndensity = 7800.0\nyoungs_modulus = 1e22\n[[body]]\n"
           "name = \"plate\"\nmaterial = \"steel\"\n[body.shape]\ntype = \"rectangle\"\n"
           "min = [0.6, 0.6]\nmax = [0.8, 0.7]\n",
       26,
       "materials.steel.youngs_modulus",
       {"too stiff for the fluid step", "sub-steps"}},
      {"particle count above --max-particles",
       edit("dx = 0.05", "dx = 1e-5"),
       5,
       "numerics.dx",
       {"particles", "--max-particles"}},
      {"body far from the rest (neighbour grid by bounding box)",
       with(edit("dx = 0.05", "dx = 0.005"), "max = [1.5, 1.5]", "max = [1000.0, 1000.0]") +
           "[[body]]\nname = \"far\"\nkind = \"rigid_fixed\"\n[body.shape]\ntype = \"disc\"\n"
           "centre = [900.0, 900.0]\nradius = 0.2\n",
       27,
       "body[1].shape",
       {"neighbour-search cells"}},
      {"tank layers beyond int",
       std::string(kGood) + "layers = 2147483648\n",
       24,
       "body[0].shape.layers",
       {"2147483648"}},
      {"overlapping bodies",
       std::string(kGood) + "[[body]]\nname = \"block\"\nkind = \"rigid_fixed\"\n[body.shape]\n"
                            "type = \"rectangle\"\nmin = [0.9, 0.5]\nmax = [1.1, 0.6]\n",
       27,
       "body[1].shape",
       {"overlaps body 'tank'"}},
      {"self-intersecting polygon",
       std::string(kGood) +
           "[[body]]\nname = \"bowtie\"\nkind = \"rigid_fixed\"\n[body.shape]\n"
           "type = \"polygon\"\nvertices = [[0.6, 0.6], [0.9, 0.8], [0.9, 0.6], [0.6, 0.7]]\n",
       29,
       "body[1].shape.vertices",
       {"intersect"}},
      {"case name unusable as a folder",
       edit("name = \"tiny\"", "name = \"../up\""),
       2,
       "name",
       {"folder"}},
      {"no particles (no fluid block, no body)",
       "schema_version = 1\nname = \"empty\"\n[numerics]\ndx = 0.05\nend_time = 0.05\n"
       "[numerics.domain]\nmin = [-0.5, -0.5]\nmax = [1.5, 1.5]\n[fluid]\nsound_speed = 20.0\n",
       1,
       "case",
       {"no particles"}},
  };
}

TEST_F(CliTest, GoodCasePassesCheckAndRuns) {
  write_case("good.toml", kGood);
  const CliResult c = run("check good.toml");
  EXPECT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find("100 fluid particles"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("tank: "), std::string::npos) << c.out;
  EXPECT_EQ(stray_files({"good.toml"}), std::vector<std::string>{}) << "check wrote files";
  // The base of every bad case really runs, so the failures below are due to the edits.
  const CliResult r = run("run good.toml --out out --threads 1 --max-steps 2 --quiet");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(fs::exists(work() / "out" / "summary.json"));
}

// `check --end-time T` predicts the run `run --end-time T` makes: fewer steps than to the
// case's end time, and an --end-time that drops listed snapshots says so.
TEST_F(CliTest, CheckEndTimePredictsTheShortenedRun) {
  write_case("good.toml", std::string(kGood) + "\n[output]\nsnapshots = [0.05]\n");
  auto steps = [](const std::string& out) {
    const std::size_t at = out.find(" fluid steps");
    std::size_t b = at;
    while (b > 0 && std::isdigit(static_cast<unsigned char>(out[b - 1]))) --b;
    return at == std::string::npos ? -1L : std::stol(out.substr(b, at - b));
  };
  const CliResult whole = run("check good.toml --no-machine-probe");
  ASSERT_EQ(whole.code, 0) << whole.err;
  const CliResult part = run("check good.toml --no-machine-probe --end-time 0.01");
  ASSERT_EQ(part.code, 0) << part.err;
  EXPECT_NE(part.err.find("output.snapshots at 0.05 s"), std::string::npos) << part.err;
  ASSERT_GT(steps(whole.out), 0) << whole.out;
  EXPECT_LT(steps(part.out), steps(whole.out)) << part.out;
}

TEST_F(CliTest, BadCaseFilesExitTwoNamingFileLineKeyAndWriteNothing) {
  for (const BadCase& bc : bad_cases()) {
    SCOPED_TRACE(bc.label);
    fs::remove_all(work());
    fs::create_directories(work());
    write_case("bad.toml", bc.text);
    for (const char* cmd : {"run bad.toml --out out --threads 1", "check bad.toml"}) {
      SCOPED_TRACE(cmd);
      const CliResult r = run(cmd);
      EXPECT_EQ(r.code, 2) << r.err;
      const std::string where = "bad.toml:" + std::to_string(bc.line) + ": " + bc.key + ": ";
      EXPECT_NE(r.err.find(where), std::string::npos) << "expected '" << where << "' in stderr:\n"
                                                      << r.err;
      for (const char* frag : bc.also)
        EXPECT_NE(r.err.find(frag), std::string::npos) << "expected '" << frag << "' in:\n"
                                                       << r.err;
      EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one message:\n" << r.err;
      EXPECT_EQ(r.out, "") << "nothing on stdout";
      EXPECT_FALSE(fs::exists(work() / "out")) << "output folder created for bad input";
      EXPECT_EQ(stray_files({"bad.toml"}), std::vector<std::string>{});
    }
  }
}

TEST_F(CliTest, MissingCaseFileExitsTwo) {
  const CliResult r = run("run nowhere.toml --out out");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nowhere.toml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(work() / "out"));
}

TEST_F(CliTest, BadCommandLinesExitTwoAndWriteNothing) {
  write_case("good.toml", kGood);
  struct Bad {
    const char* args;
    const char* fragment;
  };
  const std::vector<Bad> bad{
      {"frobnicate good.toml", "unknown command 'frobnicate'"},
      {"", "no command given"},
      {"run", "case is required"},
      {"run good.toml --out out --threads 0", "--threads"},
      {"run good.toml --out out --threads -2", "--threads"},
      {"run good.toml --out out --threads 1.5", "--threads"},
      {"run good.toml --out out --threads two", "--threads"},
      {"run good.toml --out out --threads", "--threads: 1 required N"},
      {"run good.toml --out out --threads=0", "--threads"},
      {"run good.toml --out out --dx=-1", "--dx"},
      {"run good.toml --out out --set numerics.dx", "--set numerics.dx: no '='"},
      {"run good.toml --out out --set body[3].dx=1", "no body[3] in the case (it has 1)"},
      {"check good.toml other.toml", "other.toml"},
      {"help frobnicate", "no command 'frobnicate'"},
      {"run good.toml --out out --end-time -1", "--end-time"},
      {"run good.toml --out out --end-time 0", "--end-time"},
      {"run good.toml --out out --max-steps -1", "--max-steps"},
      {"run good.toml --out out --bogus", "not expected: --bogus"},
  };
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.args);
    const CliResult r = run(b.args);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(b.fragment), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(work() / "out"));
    EXPECT_FALSE(fs::exists(work() / "results")) << "default output folder created";
  }
  EXPECT_EQ(run("--version").code, 0);
  EXPECT_EQ(run("--help").code, 0);
}

// Issue 12: `slamsph run --help` failed with "cannot open the case file" and no command
// described its options. Each command's --help (and `slamsph help COMMAND`) exits 0 and lists
// every option with its default.
TEST_F(CliTest, EveryCommandHasHelpListingItsOptionsAndDefaults) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected{
      {"run",
       {"--out", "default: results/<case name>", "--threads", "OMP_NUM_THREADS", "--end-time",
        "--max-steps", "--dx", "--set", "--quiet", "--no-output", "Exit codes"}},
      {"check", {"--set", "--dx", "CASE.toml"}},
      {"plot", {"DIR"}},
  };
  for (const auto& [cmd, words] : expected) {
    SCOPED_TRACE(cmd);
    for (const std::string& args : {cmd + " --help", "help " + cmd, cmd + " -h"}) {
      const CliResult r = run(args);
      EXPECT_EQ(r.code, 0) << args << ": " << r.err;
      EXPECT_NE(r.out.find("Usage: slamsph " + cmd), std::string::npos) << args << "\n" << r.out;
      for (const std::string& w : words)
        EXPECT_NE(r.out.find(w), std::string::npos) << args << ": no '" << w << "' in\n" << r.out;
    }
  }
  const CliResult top = run("help");
  EXPECT_EQ(top.code, 0);
  for (const char* w : {"run", "check", "plot", "--version"})
    EXPECT_NE(top.out.find(w), std::string::npos) << top.out;
  const CliResult v = run("--version");
  EXPECT_EQ(v.out.rfind("slamsph ", 0), 0u) << v.out;
}

// Issue 12: options had to follow the case file and --threads=2 was rejected. Options may
// come anywhere, in either spelling.
TEST_F(CliTest, OptionsInAnyPositionAndEitherSpelling) {
  write_case("good.toml", kGood);
  for (const std::string& args :
       {std::string("run --threads=1 --max-steps=2 --out=o1 --quiet good.toml"),
        std::string("run --out o2 good.toml --threads 1 -q --max-steps 2"),
        std::string("run -t1 -o o3 --max-steps 2 --quiet good.toml")}) {
    SCOPED_TRACE(args);
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "") << "--quiet prints nothing but errors";
    EXPECT_EQ(r.out, "");
  }
  for (const char* d : {"o1", "o2", "o3"})
    EXPECT_TRUE(fs::exists(work() / d / "summary.json")) << d;
}

// --set KEY=VALUE overrides any key, goes through the same validation as the file (an error
// names the override and the key) and is recorded in case.resolved.toml.
TEST_F(CliTest, SetOverridesAreValidatedLikeTheFileAndRecorded) {
  write_case("good.toml", kGood);
  const CliResult c = run("check good.toml --set numerics.dx=0.025");
  EXPECT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find("400 fluid particles"), std::string::npos) << c.out;  // 4x the 100
  struct Bad {
    const char* set;
    const char* where;  // the override and the key path, then what is wrong
  };
  const std::vector<Bad> bad{
      {"numerics.dx=abc", "--set numerics.dx=abc: numerics.dx: wrong type"},
      {"numerics.dx=-1", "--set numerics.dx=-1: numerics.dx: must be > 0"},
      {"numerics.dxx=1", "--set numerics.dxx=1: numerics.dxx: unknown key (did you mean 'dx'?)"},
      {"body[0].kind=rigid_fre",
       "--set body[0].kind=rigid_fre: body[0].kind: unknown value (did you mean 'rigid_free'?)"},
      {"fluid.block[0].max=[1.5,0.5]", "--set fluid.block[0].max=[1.5,0.5]: fluid.block[0].max"},
      {"name.x=1", "name is not a table"},
  };
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.set);
    const CliResult r = run(std::string("run good.toml --out out --set ") + b.set);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(b.where), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(work() / "out"));
  }
  const CliResult r =
      run("run good.toml --out out --max-steps 1 --quiet --set numerics.end_time=0.02 "
          "--set \"name=renamed case\"");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string resolved = slurp(work() / "out" / "case.resolved.toml");
  EXPECT_NE(resolved.find("end_time = 0.02"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("name = \"renamed case\""), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("# overridden on the command line: --set numerics.end_time=0.02"),
            std::string::npos)
      << resolved;
}

// Issue 12: the thread count ignored OMP_NUM_THREADS and the CPU affinity. Default: the
// environment, else the affinity mask (taskset), else the hardware; --threads wins.
TEST_F(CliTest, ThreadDefaultFollowsEnvironmentThenAffinity) {
  write_case("good.toml", kGood);
  auto threads_of = [&](const std::string& prefix, const std::string& extra) {
    fs::remove_all(work() / "out");
    const std::string cmd = "run good.toml --out out --max-steps 1 --quiet " + extra;
    const fs::path out = root_ / "capture" / "stdout.txt";
    const fs::path err = root_ / "capture" / "stderr.txt";
    const std::string sh = "cd '" + work().string() + "' && " + prefix + " '" + SLAMSPH_BINARY +
                           "' " + cmd + " >'" + out.string() + "' 2>'" + err.string() + "'";
    EXPECT_EQ(std::system(sh.c_str()), 0) << sh << "\n" << slurp(err);
    const std::string s = slurp(work() / "out" / "summary.json");
    const std::size_t at = s.find("\"threads\": ");
    return at == std::string::npos ? -1 : std::atoi(s.c_str() + at + 11);
  };
  EXPECT_EQ(threads_of("env OMP_NUM_THREADS=3", ""), 3);
  EXPECT_EQ(threads_of("env OMP_NUM_THREADS=3", "--threads 2"), 2);
  if (std::system("command -v taskset >/dev/null 2>&1") == 0) {
    EXPECT_EQ(threads_of("env -u OMP_NUM_THREADS taskset -c 0", ""), 1);
  }
  EXPECT_GE(threads_of("env OMP_NUM_THREADS=junk", ""), 1);  // ignored, not fatal
  // Waiting threads spin for a bounded time, then sleep (core/parallel.h); the summary says
  // how long, and SLAMSPH_SPIN_US changes it.
  auto policy = [&](const std::string& prefix) {
    EXPECT_GE(threads_of(prefix, ""), 1);
    const std::string s = slurp(work() / "out" / "summary.json");
    const std::size_t at = s.find("\"thread_wait_policy\": \"");
    return at == std::string::npos ? std::string("?")
                                   : s.substr(at + 23, s.find('"', at + 23) - at - 23);
  };
  EXPECT_EQ(policy("env -u SLAMSPH_SPIN_US"),
            "spin up to 200 us unless the CPUs are oversubscribed, then sleep");
  EXPECT_EQ(policy("env SLAMSPH_SPIN_US=0"),
            "spin up to 0 us unless the CPUs are oversubscribed, then sleep");
  EXPECT_EQ(policy("env SLAMSPH_SPIN_US=junk"),
            "spin up to 200 us unless the CPUs are oversubscribed, then sleep");
}

// Issue 12: a run stopped by --max-steps 0 was reported "completed" with a 0 N/m "peak";
// "1 threads".
TEST_F(CliTest, MaxStepsZeroIsStoppedNotCompleted) {
  write_case("good.toml", kGood);
  const CliResult r = run("run good.toml --out out --threads 1 --max-steps 0");
  EXPECT_EQ(r.code, 0) << r.err;
  const std::string s = slurp(work() / "out" / "summary.json");
  EXPECT_NE(s.find("\"status\": \"stopped\""), std::string::npos) << s;
  EXPECT_NE(s.find("--max-steps 0"), std::string::npos) << s;
  EXPECT_EQ(s.find("peak_force"), std::string::npos) << "a peak without a single step:\n" << s;
  EXPECT_NE(r.err.find("1 thread)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("results are incomplete"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("results in out"), std::string::npos) << "last line names the folder";
  // `slamsph plot` on that incomplete run says so.
  const CliResult s2 =
      run("run good.toml --out out2 --threads 1 --max-steps 2 --quiet "
          "--set output.plot=dam_break");
  ASSERT_EQ(s2.code, 0) << s2.err;
  EXPECT_FALSE(fs::exists(work() / "out2" / "surge_front.png")) << "plotted an incomplete run";
  const CliResult p = run("plot out2");  // (fails to draw: the tiny case has no front probe)
  EXPECT_NE(p.err.find("the run is stopped, not completed"), std::string::npos) << p.err;
}

// Issue 12: Ctrl-C or SIGTERM killed the run with no message, no summary.json and unflushed
// CSV rows. Now the step in progress finishes, the final frame and every file are written,
// summary.json says "interrupted", and the exit code is 128 + signal.
TEST_F(CliTest, SigintAndSigtermStopCleanly) {
  write_case("good.toml", kGood);
  for (const auto& [sig, code] : {std::pair<std::string, int>{"INT", 130}, {"TERM", 143}}) {
    SCOPED_TRACE(sig);
    const std::string out = "out_" + sig;
    const std::string sh = "cd '" + work().string() + "' && ('" + SLAMSPH_BINARY +
                           "' run good.toml --out " + out +
                           " --threads 1 --quiet --end-time 1000 & pid=$!; sleep 1.5; cp " + out +
                           "/summary.json running_" + sig + ".json; kill -" + sig +
                           " $pid; wait $pid; echo $? > rc_" + sig + ".txt)";
    ASSERT_EQ(std::system(sh.c_str()), 0);
    EXPECT_EQ(std::atoi(slurp(work() / ("rc_" + sig + ".txt")).c_str()), code);
    // While the run is going, summary.json exists and says so.
    const std::string running = slurp(work() / ("running_" + sig + ".json"));
    EXPECT_NE(running.find("\"status\": \"running\""), std::string::npos) << running;
    const std::string s = slurp(work() / out / "summary.json");
    EXPECT_NE(s.find("\"status\": \"interrupted\""), std::string::npos) << s;
    EXPECT_NE(s.find("SIG" + sig + " received"), std::string::npos) << s;
    // The last probe row and the last frame are at the time the run stopped.
    const std::string probes = slurp(work() / out / "probes.csv");
    const std::string last = probes.substr(probes.rfind('\n', probes.size() - 2) + 1);
    const double t_stop = std::atof(last.c_str());
    EXPECT_GT(t_stop, 0.0) << probes.substr(0, 200);
    EXPECT_NE(s.find("\"end_time_reached\": "), std::string::npos);
    const std::string pvd = slurp(work() / out / "fields.pvd");
    EXPECT_NE(pvd.find("</VTKFile>"), std::string::npos);
  }
}

// Issue 12: an unwritable output folder was an "internal error" (exit 1). It is an
// environment error: exit 4 with the path and the OS reason.
TEST_F(CliTest, UnwritableOutputFolderExitsFourWithPathAndReason) {
  write_case("good.toml", kGood);
  const CliResult r = run("run good.toml --out /proc/slamsph_no_such_dir --max-steps 1");
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("/proc/slamsph_no_such_dir"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
}

// Issue 12: a second run into the same --out silently left the previous run's frames and a
// summary saying "completed" next to the new files. Now a folder holding a run is refused
// (exit 2, naming the folder and --overwrite) and left as it was; --overwrite removes only
// what slamsph wrote there (its manifest .slamsph_files), never the user's files.
TEST_F(CliTest, FolderHoldingARunIsRefusedUnlessOverwriteWhichKeepsUserFiles) {
  write_case("good.toml", kGood);
  const std::string first = "run good.toml --out out --threads 1 --quiet --max-steps ";
  ASSERT_EQ(run(first + "4").code, 0);
  ASSERT_TRUE(fs::exists(work() / "out" / "vtk" / "fluid_00001.vtp"));
  std::ofstream(work() / "out" / "notes.txt") << "mine";
  std::ofstream(work() / "out" / "vtk" / "view.pvsm") << "mine too";
  const std::string summary = slurp(work() / "out" / "summary.json");
  const std::string manifest = slurp(work() / "out" / ".slamsph_files");
  EXPECT_NE(manifest.find("\nvtk/fluid_00001.vtp\n"), std::string::npos) << manifest;
  EXPECT_EQ(manifest.find("notes.txt"), std::string::npos) << manifest;

  const CliResult again = run(first + "4");
  EXPECT_EQ(again.code, 2) << again.err;
  EXPECT_NE(again.err.find("error: out: "), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
  EXPECT_EQ(std::count(again.err.begin(), again.err.end(), '\n'), 1) << again.err;
  EXPECT_EQ(slurp(work() / "out" / "summary.json"), summary) << "refused, yet changed";
  // Bad input with --overwrite refuses before touching the previous results.
  EXPECT_EQ(run(first + "4 --overwrite --set numerics.dx=-1").code, 2);
  EXPECT_EQ(slurp(work() / "out" / "summary.json"), summary);
  EXPECT_TRUE(fs::exists(work() / "out" / "vtk" / "fluid_00001.vtp"));

  // Replaced by a run without VTK: no frame of the first run survives, the user's files do.
  const CliResult r = run(first + "2 --overwrite --set output.vtk=false");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(work() / "out" / "vtk" / "fluid_00001.vtp"));
  EXPECT_FALSE(fs::exists(work() / "out" / "fields.pvd"));
  EXPECT_EQ(slurp(work() / "out" / "notes.txt"), "mine");
  EXPECT_EQ(slurp(work() / "out" / "vtk" / "view.pvsm"), "mine too");
  EXPECT_NE(slurp(work() / "out" / "summary.json").find("\"fluid_steps\": 2"), std::string::npos);

  // A folder of an older slamsph (summary.json, no manifest) is a run too.
  fs::create_directories(work() / "old");
  std::ofstream(work() / "old" / "summary.json") << "{\"status\": \"completed\"}\n";
  EXPECT_EQ(run("run good.toml --out old --threads 1 --max-steps 1 --quiet").code, 2);
  EXPECT_EQ(run("run good.toml --out old --threads 1 --max-steps 1 --quiet --overwrite").code, 0);
  // A folder with only the user's files is not a run: used as it is, files kept.
  fs::create_directories(work() / "mine");
  std::ofstream(work() / "mine" / "readme.txt") << "x";
  EXPECT_EQ(run("run good.toml --out mine --threads 1 --max-steps 1 --quiet").code, 0);
  EXPECT_EQ(slurp(work() / "mine" / "readme.txt"), "x");
  EXPECT_EQ(slurp(work() / "mine" / ".slamsph_files").find("readme"), std::string::npos);
}

// Issue 12: a write failure in the middle of a run (disk full) or a CSV that cannot be
// opened was an "internal error" (exit 1) with no summary. Now: exit 4, the path and the OS
// reason, and summary.json says "failed" with the same reason. /dev/full stands in for a
// full disk: every write to it fails with ENOSPC.
TEST_F(CliTest, WriteFailuresMidRunExitFourWithAFailedSummary) {
  write_case("good.toml", kGood);
  fs::create_directories(work() / "full" / "vtk");
  fs::create_symlink("/dev/full", work() / "full" / "vtk" / "fluid_00002.vtp");
  const CliResult r = run("run good.toml --out full --threads 1 --max-steps 20 --quiet");
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("error: cannot write full/vtk/fluid_00002.vtp: No space left on device"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  std::string s = slurp(work() / "full" / "summary.json");
  EXPECT_NE(s.find("\"status\": \"failed\""), std::string::npos) << s;
  EXPECT_NE(s.find("No space left on device"), std::string::npos) << s;
  EXPECT_TRUE(fs::exists(work() / "full" / "vtk" / "fluid_00001.vtp")) << "earlier frames kept";

  fs::create_directories(work() / "csv" / "probes.csv");  // a folder where the CSV should go
  const CliResult c = run("run good.toml --out csv --threads 1 --max-steps 2 --quiet");
  EXPECT_EQ(c.code, 4) << c.err;
  EXPECT_NE(c.err.find("cannot open csv/probes.csv for writing: Is a directory"), std::string::npos)
      << c.err;
  s = slurp(work() / "csv" / "summary.json");
  EXPECT_NE(s.find("\"status\": \"failed\""), std::string::npos) << s;
  // No half-written summary or resolved case under the final names.
  EXPECT_FALSE(fs::exists(work() / "csv" / "summary.json.tmp"));
  EXPECT_FALSE(fs::exists(work() / "csv" / "case.resolved.toml.tmp"));
}

// Issue 12: a valid negative Poisson ratio (auxetic foam) was refused, naming body[1].shape.
TEST_F(CliTest, NegativePoissonRatioIsAccepted) {
  write_case("foam.toml", std::string(kGood) +
                              "[materials.foam]\ndensity = 300.0\nyoungs_modulus = 1e6\n"
                              "poisson_ratio = -0.3\n[[body]]\nname = \"foam\"\n"
                              "material = \"foam\"\n[body.shape]\ntype = \"rectangle\"\n"
                              "min = [0.6, 0.6]\nmax = [0.8, 0.7]\n");
  const CliResult c = run("check foam.toml");
  EXPECT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find("foam: "), std::string::npos) << c.out;
  const CliResult r = run("run foam.toml --out out --threads 1 --max-steps 3 --quiet");
  EXPECT_EQ(r.code, 0) << r.err;
}

// An elastic body too small to have a finite-particle neighbour set (one particle) is bad
// input: exit 2, nothing written, the body named.
const char* kTinyDisc =
    "schema_version = 1\n"
    "name = \"tiny disc\"\n"
    "[numerics]\n"
    "dx = 0.05\n"
    "end_time = 0.05\n"
    "[numerics.domain]\n"
    "min = [-0.5, -0.5]\n"
    "max = [1.5, 1.5]\n"
    "[materials.m]\n"
    "density = 1000.0\n"
    "youngs_modulus = 1e6\n"
    "[[body]]\n"
    "name = \"d\"\n"
    "material = \"m\"\n"
    "[body.shape]\n"
    "type = \"disc\"\n"
    "centre = [0.5, 0.5]\n"
    "radius = 0.01\n";  // line 18

TEST_F(CliTest, DegenerateElasticBodyExitsTwoAndWritesNothing) {
  write_case("bad.toml", kTinyDisc);
  const CliResult r = run("run bad.toml --out out --threads 1");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("body 'd'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(work() / "out"));
  EXPECT_EQ(stray_files({"bad.toml"}), std::vector<std::string>{});
}

// The README contract for the same error: the message should name file, line and key
// (bad.toml:18: body[0].shape.radius). Today it is "error: body 'd': select_fpm_sets: ...",
// thrown from setup_body after parsing. Enable when the parser or the driver adds the location.
TEST_F(CliTest, DegenerateElasticBodyNamesFileAndKey) {
  write_case("bad.toml", kTinyDisc);
  const CliResult r = run("check bad.toml");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("bad.toml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("body[0].shape"), std::string::npos) << r.err;
}

}  // namespace
