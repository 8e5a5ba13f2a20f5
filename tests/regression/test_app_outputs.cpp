// The output folder of a short `slamsph run` (README "Running cases"): fields.pvd is
// well-formed XML listing exactly the .vtp files that exist (each well-formed, with the
// particle counts of summary.json); every CSV header entry carries a unit in [...] and every
// row has one finite number per column; summary.json is valid JSON with the keys README
// promises, and its numbers agree with the CSVs (peak force = largest |F| in forces.csv,
// impulse = trapezoidal integral of forces.csv, end time = last row).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
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

// ---- minimal JSON reader (objects, arrays, strings, numbers, true/false/null) ----
struct Json {
  enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
  double number = 0.0;
  bool boolean = false;
  std::string str;
  std::vector<Json> items;
  std::map<std::string, Json> fields;
  bool has(const std::string& k) const { return kind == Object && fields.count(k); }
  const Json& operator[](const std::string& k) const {
    const auto it = fields.find(k);
    if (it == fields.end()) throw std::runtime_error("no key " + k);
    return it->second;
  }
};

class JsonReader {
 public:
  explicit JsonReader(const std::string& s) : s_(s) {}
  Json parse() {
    Json v = value();
    ws();
    if (i_ != s_.size()) fail("trailing content");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(i_));
  }
  void ws() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    ws();
    if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
    return false;
  }
  void expect(char c) {
    if (!eat(c)) fail(std::string("expected '") + c + "'");
  }
  std::string string_lit() {
    expect('"');
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      if (s_[i_] == '\\') {
        if (++i_ >= s_.size()) fail("bad escape");
        const char e = s_[i_];
        if (e == 'u') {
          if (i_ + 4 >= s_.size()) fail("bad \\u");
          out += '?';
          i_ += 4;
        } else {
          const std::string from = "\"\\/bfnrt", to = "\"\\/\b\f\n\r\t";
          const std::size_t k = from.find(e);
          if (k == std::string::npos) fail("bad escape");
          out += to[k];
        }
        ++i_;
      } else {
        if (static_cast<unsigned char>(s_[i_]) < 0x20) fail("control character in string");
        out += s_[i_++];
      }
    }
    expect('"');
    return out;
  }
  Json value() {
    ws();
    if (i_ >= s_.size()) fail("unexpected end");
    Json v;
    const char c = s_[i_];
    if (c == '{') {
      v.kind = Json::Object;
      ++i_;
      if (eat('}')) return v;
      do {
        ws();
        const std::string k = string_lit();
        if (v.fields.count(k)) fail("duplicate key " + k);
        expect(':');
        v.fields[k] = value();
      } while (eat(','));
      expect('}');
    } else if (c == '[') {
      v.kind = Json::Array;
      ++i_;
      if (eat(']')) return v;
      do v.items.push_back(value());
      while (eat(','));
      expect(']');
    } else if (c == '"') {
      v.kind = Json::String;
      v.str = string_lit();
    } else if (s_.compare(i_, 4, "true") == 0 || s_.compare(i_, 5, "false") == 0) {
      v.kind = Json::Bool;
      v.boolean = s_[i_] == 't';
      i_ += v.boolean ? 4 : 5;
    } else if (s_.compare(i_, 4, "null") == 0) {
      i_ += 4;
    } else {
      // JSON number grammar (no NaN/Infinity, no leading '+').
      const std::size_t start = i_;
      if (s_[i_] == '-') ++i_;
      auto digits = [&] {
        const std::size_t d = i_;
        while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
        if (i_ == d) fail("bad number");
      };
      digits();
      if (i_ < s_.size() && s_[i_] == '.') ++i_, digits();
      if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
        ++i_;
        if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
        digits();
      }
      v.kind = Json::Number;
      v.number = std::strtod(s_.substr(start, i_ - start).c_str(), nullptr);
    }
    return v;
  }
  const std::string& s_;
  std::size_t i_ = 0;
};

// ---- minimal XML well-formedness check: balanced tags, quoted attributes ----
struct XmlTag {
  std::string name;
  std::map<std::string, std::string> attrs;
};

// Returns the start tags in document order; fails the test on malformed XML.
std::vector<XmlTag> xml_tags(const std::string& s, const std::string& what) {
  std::vector<XmlTag> tags;
  std::vector<std::string> open;
  std::size_t i = 0;
  while ((i = s.find('<', i)) != std::string::npos) {
    const std::size_t end = s.find('>', i);
    if (end == std::string::npos) {
      ADD_FAILURE() << what << ": unterminated tag";
      return tags;
    }
    std::string body = s.substr(i + 1, end - i - 1);
    i = end + 1;
    if (body.rfind("?", 0) == 0 || body.rfind("!--", 0) == 0) continue;
    if (body.rfind("/", 0) == 0) {
      const std::string name = body.substr(1);
      if (open.empty() || open.back() != name) {
        ADD_FAILURE() << what << ": mismatched </" << name << ">";
        return tags;
      }
      open.pop_back();
      continue;
    }
    const bool self_closing = !body.empty() && body.back() == '/';
    if (self_closing) body.pop_back();
    XmlTag t;
    std::size_t p = body.find_first_of(" \t\n");
    t.name = body.substr(0, p);
    while (p != std::string::npos) {
      p = body.find_first_not_of(" \t\n", p);
      if (p == std::string::npos) break;
      const std::size_t eq = body.find('=', p);
      if (eq == std::string::npos || eq + 1 >= body.size() || body[eq + 1] != '"') {
        ADD_FAILURE() << what << ": bad attribute in <" << body << ">";
        return tags;
      }
      const std::size_t close = body.find('"', eq + 2);
      if (close == std::string::npos) {
        ADD_FAILURE() << what << ": unterminated attribute in <" << body << ">";
        return tags;
      }
      t.attrs[body.substr(p, eq - p)] = body.substr(eq + 2, close - eq - 2);
      p = close + 1;
    }
    if (!self_closing) open.push_back(t.name);
    tags.push_back(std::move(t));
  }
  EXPECT_TRUE(open.empty()) << what << ": unclosed <" << (open.empty() ? "" : open.back()) << ">";
  return tags;
}

// ---- CSV ----
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

Csv read_csv(const fs::path& p) {
  Csv c;
  std::ifstream in(p);
  std::string line;
  EXPECT_TRUE(static_cast<bool>(std::getline(in, line))) << p << " is empty";
  c.header = split(line);
  while (std::getline(in, line)) {
    std::vector<double> row;
    for (const std::string& cell : split(line)) {
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      EXPECT_TRUE(!cell.empty() && *end == '\0' && std::isfinite(v))
          << p.filename() << ": bad value '" << cell << "'";
      row.push_back(v);
    }
    EXPECT_EQ(row.size(), c.header.size()) << p.filename() << " row " << c.rows.size() + 1;
    c.rows.push_back(std::move(row));
  }
  return c;
}

std::size_t column(const Csv& c, const std::string& name) {
  const auto it = std::find(c.header.begin(), c.header.end(), name);
  EXPECT_NE(it, c.header.end()) << "no column '" << name << "'";
  return static_cast<std::size_t>(it - c.header.begin());
}

// elastic_cylinder_entry.toml at dx 0.01, cylinder starting 2 cm into the water (so the
// force is not zero), VTK every 0.5 ms, probes every 0.2 ms.
std::string small_case() {
  std::string text = slurp(fs::path(SLAMSPH_SOURCE_DIR) / "cases" / "elastic_cylinder_entry.toml");
  const std::vector<std::pair<std::string, std::string>> edits{
      {"\ndx = 0.005", "\ndx = 0.01"},
      {"centre = [0.5, 0.515]", "centre = [0.5, 0.48]"},
      {"interval = 0.001 ", "interval = 0.0005 "},
      {"probe_interval = 0.0", "probe_interval = 0.0002"}};
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "cases/elastic_cylinder_entry.toml changed: " << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

constexpr long kSteps = 40;

// One run shared by all tests of the suite.
class Outputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = fs::temp_directory_path() / ("slamsph_outputs_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
    std::ofstream(root_ / "case.toml") << small_case();
    std::ostringstream cmd;
    cmd << "'" << SLAMSPH_BINARY << "' run '" << (root_ / "case.toml").string() << "' --out '"
        << out().string() << "' --threads 1 --quiet --max-steps " << kSteps << " > '"
        << (root_ / "log.txt").string() << "' 2>&1";
    const int st = std::system(cmd.str().c_str());
    code_ = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  }
  static void TearDownTestSuite() {
    if (!failed_)
      fs::remove_all(root_);
    else
      std::printf("kept %s for inspection\n", root_.c_str());
  }
  void SetUp() override { ASSERT_EQ(code_, 0) << slurp(root_ / "log.txt"); }
  void TearDown() override { failed_ = failed_ || HasFailure(); }
  static fs::path out() { return root_ / "out"; }
  static Json summary() { return JsonReader(slurp(out() / "summary.json")).parse(); }

  static inline fs::path root_;
  static inline int code_ = -1;
  static inline bool failed_ = false;
};

TEST_F(Outputs, PvdIsValidXmlListingExactlyTheVtpFilesThatExist) {
  const std::vector<XmlTag> tags = xml_tags(slurp(out() / "fields.pvd"), "fields.pvd");
  ASSERT_FALSE(tags.empty());
  EXPECT_EQ(tags[0].name, "VTKFile");
  EXPECT_EQ(tags[0].attrs.count("type") ? tags[0].attrs.at("type") : "", "Collection");
  const Json s = summary();
  std::set<std::string> listed;
  std::map<std::string, int> frames_per_part;
  double last_t = -1.0;
  for (const XmlTag& t : tags) {
    if (t.name != "DataSet") continue;
    ASSERT_TRUE(t.attrs.count("file") && t.attrs.count("timestep") && t.attrs.count("name"));
    const std::string file = t.attrs.at("file");
    EXPECT_TRUE(listed.insert(file).second) << file << " listed twice";
    const double time = std::stod(t.attrs.at("timestep"));
    EXPECT_GE(time, last_t) << "timesteps go backwards";
    last_t = time;
    ++frames_per_part[t.attrs.at("name")];
    // Each listed file exists, is well-formed and holds the part's particles.
    const fs::path vtp = out() / file;
    ASSERT_TRUE(fs::exists(vtp)) << vtp;
    // The XML header up to the appended binary data; the file must end the data properly.
    const std::string text = slurp(vtp);
    const std::size_t app = text.find("<AppendedData encoding=\"raw\">");
    ASSERT_NE(app, std::string::npos) << file;
    EXPECT_TRUE(text.ends_with("\n  </AppendedData>\n</VTKFile>\n")) << file;
    const std::vector<XmlTag> vt = xml_tags(text.substr(0, app) + "</VTKFile>\n", file);
    const auto piece =
        std::find_if(vt.begin(), vt.end(), [](const XmlTag& x) { return x.name == "Piece"; });
    ASSERT_NE(piece, vt.end()) << file;
    const std::string part = t.attrs.at("name");
    ASSERT_TRUE(s["particles"].has(part)) << part;
    EXPECT_EQ(std::stol(piece->attrs.at("NumberOfPoints")),
              static_cast<long>(s["particles"][part].number))
        << file;
  }
  // Every .vtp in the folder is listed.
  long on_disk = 0;
  for (const auto& e : fs::recursive_directory_iterator(out()))
    if (e.path().extension() == ".vtp") {
      ++on_disk;
      EXPECT_TRUE(listed.count(fs::relative(e.path(), out()).generic_string()))
          << e.path() << " is not in fields.pvd";
    }
  EXPECT_EQ(on_disk, static_cast<long>(listed.size()));
  // fluid, tank and cylinder in every frame; 40 steps of ~60 us with 0.5 ms output: >= 4 frames.
  EXPECT_EQ(frames_per_part.size(), 3u);
  for (const auto& [part, n] : frames_per_part) {
    EXPECT_EQ(n, frames_per_part.begin()->second) << part;
    EXPECT_GE(n, 4) << part;
  }
}

TEST_F(Outputs, EveryCsvHeaderEntryHasAUnitAndRowsAreNumbers) {
  for (const char* name : {"forces.csv", "probes.csv", "bodies.csv"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(fs::exists(out() / name));
    const Csv c = read_csv(out() / name);
    EXPECT_GE(c.header.size(), 2u);
    EXPECT_GE(c.rows.size(), 2u);
    for (const std::string& h : c.header) {
      const std::size_t open = h.rfind(" [");
      EXPECT_TRUE(open != std::string::npos && open > 0 && h.back() == ']' && h.size() > open + 3)
          << "header entry without a unit: '" << h << "'";
    }
    EXPECT_EQ(c.header[0], "time [s]");
    for (std::size_t r = 1; r < c.rows.size(); ++r) EXPECT_GT(c.rows[r][0], c.rows[r - 1][0]);
  }
  // Probes of the case: body pressure in Pa, displacement in m, and the leak counter.
  const Csv p = read_csv(out() / "probes.csv");
  column(p, "p_keel [Pa]");
  column(p, "keel_displacement_x [m]");
  column(p, "keel_displacement_y [m]");
  column(p, "leaked_particles [-]");
}

TEST_F(Outputs, SummaryHasThePromisedKeysConsistentWithTheCsvs) {
  const Json s = summary();
  ASSERT_EQ(s.kind, Json::Object);
  for (const char* k : {"case", "particles", "fluid_steps", "end_time_reached", "wall_seconds",
                        "fluid_particle_steps_per_second", "threads", "version", "bodies",
                        "leaked_particles", "status", "warnings"})
    EXPECT_TRUE(s.has(k)) << "summary.json lacks '" << k << "'";
  if (HasFailure()) return;
  EXPECT_EQ(s["case"].str, "elastic_cylinder_entry");
  EXPECT_EQ(s["status"].str, "stopped");  // --max-steps before end_time (issue 12)
  EXPECT_FALSE(s["version"].str.empty());
  EXPECT_EQ(s["threads"].number, 1.0);
  EXPECT_EQ(s["fluid_steps"].number, double(kSteps));
  EXPECT_EQ(s["leaked_particles"].kind, Json::Number);
  const double nf = s["particles"]["fluid"].number;
  EXPECT_GT(nf, 3000.0);
  EXPECT_GT(s["particles"]["cylinder"].number, 100.0);
  EXPECT_GT(s["particles"]["tank"].number, 100.0);
  const double wall = s["wall_seconds"].number;
  EXPECT_GT(wall, 0.0);
  EXPECT_NEAR(s["fluid_particle_steps_per_second"].number, nf * kSteps / wall,
              1e-6 * nf * kSteps / wall);
  // Where the time went: every phase non-negative, together no more than the wall time
  // (app/phase_times.h), and the CPU time of the loop positive.
  ASSERT_TRUE(s.has("time_split_s"));
  double phases = 0.0;
  for (const char* k : {"step_limit", "fluid_integration", "solid_substeps", "neighbour_lists",
                        "fluid_rates", "contact", "checks_and_zone"}) {
    ASSERT_TRUE(s["time_split_s"].has(k)) << k;
    EXPECT_GE(s["time_split_s"][k].number, 0.0) << k;
    phases += s["time_split_s"][k].number;
  }
  EXPECT_GT(s["time_split_s"]["fluid_rates"].number, 0.0);
  EXPECT_GT(s["time_split_s"]["solid_substeps"].number, 0.0);
  EXPECT_LE(phases, wall);
  EXPECT_NEAR(s["time_split_s"]["other"].number, wall - phases, 1e-9 * wall);
  EXPECT_GT(s["cpu_seconds"].number, 0.0);

  // forces.csv: one row per fluid step plus the initial one; the last time is the end time.
  const Csv f = read_csv(out() / "forces.csv");
  ASSERT_EQ(static_cast<long>(f.rows.size()), kSteps + 1);
  EXPECT_NEAR(s["end_time_reached"].number, f.rows.back()[0], 1e-12);

  const Json& bodies = s["bodies"];
  ASSERT_EQ(bodies.kind, Json::Array);
  ASSERT_EQ(bodies.items.size(), 2u);
  for (const Json& b : bodies.items) {
    SCOPED_TRACE(b["body"].str);
    const Json& peak = b["peak_force_N_per_m"];
    const Json& imp = b["impulse_N_s_per_m"];
    ASSERT_EQ(peak.items.size(), 2u);
    ASSERT_EQ(imp.items.size(), 2u);
    const std::size_t cx = column(f, b["body"].str + " Fx [N/m]");
    const std::size_t cy = column(f, b["body"].str + " Fy [N/m]");
    double peak_mag = 0.0, ix = 0.0, iy = 0.0;
    for (std::size_t r = 0; r < f.rows.size(); ++r) {
      peak_mag = std::max(peak_mag, std::hypot(f.rows[r][cx], f.rows[r][cy]));
      if (r > 0) {
        const double dt = f.rows[r][0] - f.rows[r - 1][0];
        ix += 0.5 * dt * (f.rows[r][cx] + f.rows[r - 1][cx]);
        iy += 0.5 * dt * (f.rows[r][cy] + f.rows[r - 1][cy]);
      }
    }
    const double pk = std::hypot(peak.items[0].number, peak.items[1].number);
    EXPECT_GT(peak_mag, 1.0) << "the body feels no water";
    EXPECT_NEAR(pk, peak_mag, 1e-9 * peak_mag);
    const double iscale = std::hypot(ix, iy) + 1e-12;
    EXPECT_NEAR(imp.items[0].number, ix, 1e-6 * iscale);
    EXPECT_NEAR(imp.items[1].number, iy, 1e-6 * iscale);
    std::printf("%s: peak |F| %.4g N/m, impulse (%.4g, %.4g) N s/m\n", b["body"].str.c_str(), pk,
                imp.items[0].number, imp.items[1].number);
  }
}

TEST_F(Outputs, ResolvedCaseIsWritten) {
  const std::string r = slurp(out() / "case.resolved.toml");
  EXPECT_NE(r.find("schema_version = 1"), std::string::npos) << r;
  EXPECT_NE(r.find("dx = 0.01"), std::string::npos) << "the run's own case, not the shipped one";
}

}  // namespace
