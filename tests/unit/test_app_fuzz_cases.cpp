// Fuzzing the case reader through the binary (issue 12): mutated case files — values,
// types, keys, lines, truncation, random bytes — go through `slamsph check`, and some through
// `slamsph run --max-steps 5`. No run may die of a signal, hang, or exit 1 (internal error);
// every exit 2 must name the file, a line and a key ("fuzz.toml:<line>: <key>: ..."). The
// seed is fixed, so a failure reproduces; SLAMSPH_FUZZ_CHECKS / SLAMSPH_FUZZ_RUNS raise the
// counts (CI: 300 and 30, about 20-40 s on 2 cores).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const char* kSeeds[] = {
    // Tank with water and a rigid free disc, probes.
    "schema_version = 1\n"
    "name = \"fuzz\"\n"
    "[numerics]\n"
    "dx = 0.05\n"
    "end_time = 0.05\n"
    "h_over_dx = 1.3\n"
    "cfl = 0.25\n"
    "gravity = [0.0, -9.81]\n"
    "[numerics.domain]\n"
    "min = [-0.5, -0.5]\n"
    "max = [1.5, 1.5]\n"
    "[fluid]\n"
    "sound_speed = 20.0\n"
    "density = 1000.0\n"
    "[[fluid.block]]\n"
    "min = [0.0, 0.0]\n"
    "max = [0.5, 0.5]\n"
    "[[body]]\n"
    "name = \"tank\"\n"
    "kind = \"rigid_fixed\"\n"
    "[body.shape]\n"
    "type = \"tank\"\n"
    "min = [0.0, 0.0]\n"
    "max = [1.0, 1.0]\n"
    "layers = 3\n"
    "[[body]]\n"
    "name = \"ball\"\n"
    "kind = \"rigid_free\"\n"
    "density = 500.0\n"
    "velocity = [0.0, -1.0]\n"
    "[body.shape]\n"
    "type = \"disc\"\n"
    "centre = [0.75, 0.7]\n"
    "radius = 0.1\n"
    "[output]\n"
    "interval = 0.01\n"
    "[[output.probe]]\n"
    "name = \"p\"\n"
    "kind = \"pressure\"\n"
    "position = [0.25, 0.1]\n"
    "[[output.probe]]\n"
    "name = \"front\"\n"
    "kind = \"surge_front\"\n",
    // An elastic plate with a clamp and a material, no fluid.
    "schema_version = 1\n"
    "name = \"fuzz plate\"\n"
    "[numerics]\n"
    "dx = 0.02\n"
    "end_time = 0.01\n"
    "[numerics.domain]\n"
    "min = [-0.5, -0.5]\n"
    "max = [1.0, 1.0]\n"
    "[materials.rubber]\n"
    "density = 1100.0\n"
    "youngs_modulus = 2.0e6\n"
    "poisson_ratio = 0.45\n"
    "hourglass = 0.1\n"
    "[[body]]\n"
    "name = \"plate\"\n"
    "material = \"rubber\"\n"
    "velocity = [0.0, 0.5]\n"
    "[body.shape]\n"
    "type = \"rectangle\"\n"
    "min = [0.0, 0.0]\n"
    "max = [0.4, 0.06]\n"
    "[body.clamp]\n"
    "box = {min = [0.0, 0.0], max = [0.04, 0.06]}\n"
    "[[body]]\n"
    "name = \"wedge\"\n"
    "kind = \"rigid_prescribed\"\n"
    "motion = [[0.0, 0.0, -1.0], [0.01, 0.0, -0.5]]\n"
    "[body.shape]\n"
    "type = \"polygon\"\n"
    "vertices = [[0.5, 0.5], [0.7, 0.5], [0.6, 0.3]]\n"
    "[[output.probe]]\n"
    "name = \"tip\"\n"
    "kind = \"body_displacement\"\n"
    "body = \"plate\"\n"
    "position = [0.4, 0.03]\n",
};

const std::vector<std::string> kValues{"0",
                                       "-1",
                                       "1e308",
                                       "-1e-300",
                                       "1e22",
                                       "2147483648",
                                       "9223372036854775807",
                                       "nan",
                                       "inf",
                                       "-inf",
                                       "\"x\"",
                                       "true",
                                       "[]",
                                       "[1, 2, 3]",
                                       "[\"a\", 1]",
                                       "{}",
                                       "{min = [0, 0]}",
                                       "0.5",
                                       "1e-12",
                                       "\"tank\"",
                                       "\"fluid\"",
                                       "\"a b/c\"",
                                       "[[1, 2], [2, 1], [1, 1], [2, 2]]",
                                       "-0.0",
                                       "1_000",
                                       "0x10",
                                       "\"\""};

std::string mutate(const std::string& seed, std::mt19937& rng) {
  std::vector<std::string> lines;
  std::istringstream in(seed);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const int kinds = 7;
  const int k = static_cast<int>(pick(kinds));
  std::size_t li = pick(lines.size());
  std::string& line = lines[li];
  const std::size_t eq = line.find(" = ");
  switch (k) {
    case 0:  // value
    case 1:
      if (eq != std::string::npos) line = line.substr(0, eq + 3) + kValues[pick(kValues.size())];
      break;
    case 2:  // key renamed (one character changed) or value becomes a key
      if (eq != std::string::npos && eq > 0)
        line[pick(eq)] = "abcxyz_.[]"[pick(10)];
      else
        line += "]";
      break;
    case 3:  // line deleted or duplicated
      if (pick(2))
        lines.erase(lines.begin() + static_cast<long>(li));
      else
        lines.insert(lines.begin() + static_cast<long>(li), line);
      break;
    case 4:  // a table header repeated or moved
      lines.insert(lines.begin() + static_cast<long>(pick(lines.size())),
                   lines[pick(lines.size())]);
      break;
    default:
      break;
  }
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  if (k == 5) out.resize(pick(out.size()));  // truncation
  if (k == 6) {                              // random bytes
    const std::size_t n = 1 + pick(4);
    for (std::size_t i = 0; i < n && !out.empty(); ++i)
      out[pick(out.size())] = static_cast<char>(pick(256));
  }
  return out;
}

struct Outcome {
  int code = -1;  // exit code, -1 if killed by a signal or timed out
  bool signal = false;
  std::string err;
};

Outcome run(const fs::path& dir, const std::string& args) {
  const fs::path err = dir / "stderr.txt";
  // timeout: a mutated case must not hang; 124 is timeout's own exit code.
  const std::string cmd = "cd '" + dir.string() + "' && timeout 60 '" + SLAMSPH_BINARY + "' " +
                          args + " >/dev/null 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  Outcome o;
  o.signal = WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) >= 124);
  o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  o.err = ss.str();
  return o;
}

long env_count(const char* name, long def) {
  const char* s = std::getenv(name);
  return s ? std::atol(s) : def;
}

TEST(FuzzCases, MutatedCasesNeverCrashAndEveryRefusalNamesFileLineKey) {
  const fs::path dir = fs::temp_directory_path() / ("slamsph_fuzz_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::mt19937 rng(20261129);
  const long checks = env_count("SLAMSPH_FUZZ_CHECKS", 300);
  const long runs = env_count("SLAMSPH_FUZZ_RUNS", 30);
  const std::regex located(R"(^error: fuzz\.toml:[0-9]+: [^ :][^:]*: .+)");
  std::map<std::string, long> outcomes;
  for (long n = 0; n < checks + runs; ++n) {
    const std::string text = mutate(kSeeds[n % 2], rng);
    {
      std::ofstream f(dir / "fuzz.toml", std::ios::binary);
      f << text;
    }
    const bool is_run = n >= checks;
    fs::remove_all(dir / "out");
    const Outcome o = run(dir, is_run ? "run fuzz.toml --out out --threads 1 --quiet "
                                        "--max-steps 5 --max-particles 2e5"
                                      : "check fuzz.toml --max-particles 2e5 --no-machine-probe");
    const std::string what = std::string(is_run ? "run" : "check") + " exit " +
                             (o.signal ? std::string("signal/timeout") : std::to_string(o.code));
    ++outcomes[what];
    SCOPED_TRACE("mutation " + std::to_string(n) + ":\n" + text + "\nstderr: " + o.err);
    ASSERT_FALSE(o.signal) << "killed by a signal or timed out";
    ASSERT_NE(o.code, 1) << "internal error";
    if (is_run)
      ASSERT_TRUE(o.code == 0 || o.code == 2 || o.code == 3) << o.code;
    else
      ASSERT_TRUE(o.code == 0 || o.code == 2) << o.code;
    if (o.code == 2) {
      const std::string first = o.err.substr(0, o.err.find('\n'));
      ASSERT_TRUE(std::regex_match(first, located)) << "exit 2 without file:line:key";
    }
  }
  for (const auto& [k, v] : outcomes) std::printf("%-22s %ld\n", k.c_str(), v);
  fs::remove_all(dir);
}

}  // namespace
