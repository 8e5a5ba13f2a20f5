// plot_results / plot_csv_columns: PNGs with a valid signature next to their .gp scripts;
// clear non-zero returns for a missing gnuplot, file or column.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/csv_writer.h"
#include "io/plot.h"
#include "io/reference_curves.h"

namespace slamsph {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(testing::TempDir()) / ("slamsph_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

bool is_png(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  char sig[8] = {};
  f.read(sig, 8);
  const unsigned char want[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  return f.gcount() == 8 && std::equal(sig, sig + 8, reinterpret_cast<const char*>(want));
}

#define SKIP_WITHOUT_GNUPLOT() \
  if (find_gnuplot().empty()) GTEST_SKIP() << "gnuplot not installed"

// forces.csv for a cylinder (V 2.33, R 0.1) following Campbell–Weynberg from t = 1 ms.
void write_forces(const fs::path& dir) {
  CsvWriter w((dir / "forces.csv").string(),
              {"time [s]", "tank Fx [N/m]", "tank Fy [N/m]", "cylinder Fx [N/m]",
               "cylinder Fy [N/m]", "cylinder Fy_pressure [N/m]"});
  for (int i = 0; i <= 300; ++i) {
    const double t = 1e-4 * i;
    const double sd = 2.33 * (t - 1e-3) / 0.2;
    const double f =
        sd < 0 ? 0.0 : slamming_force(SlammingTheory::CampbellWeynberg, sd, 1000, 2.33, 0.1);
    w.row({t, 0.0, -f, 0.01 * std::sin(1e3 * t), f, f});
  }
}

TEST(IoOutputPlot, CylinderEntryWritesPngs) {
  SKIP_WITHOUT_GNUPLOT();
  const fs::path dir = fresh_dir("plot_cyl");
  write_forces(dir);
  PlotParams p;
  p.body = "cylinder";
  p.velocity = 2.33;
  p.radius = 0.1;
  p.t_contact = 1e-3;
  std::string msg;
  ASSERT_EQ(plot_results(dir.string(), "cylinder_entry", p, msg), 0) << msg;
  EXPECT_TRUE(is_png(dir / "slamming_force.png"));
  EXPECT_TRUE(is_png(dir / "slamming_coefficient.png"));
  EXPECT_TRUE(fs::exists(dir / "slamming_force.gp"));
  EXPECT_FALSE(fs::exists(dir / "slamming_force.gp.log"));
  EXPECT_TRUE(is_png(dir / "entry_velocity.png"));
  EXPECT_TRUE(fs::exists(dir / "slamming_cs.csv"));
  // The synthetic force is Campbell–Weynberg itself (constant speed: no bodies.csv): the
  // peak is reported as it is (no theory's F(0) to agree with), the mean Cs like with like.
  EXPECT_NE(msg.find("peak 2795.9 N/m at t - t0 = 0.00 ms, s/D 0.0000, Cs 5.15"), std::string::npos)
      << msg;
  EXPECT_EQ(msg.find("F(0)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("vs Campbell-Weynberg (3D fit) 1.551: +0.0%"), std::string::npos) << msg;
}

TEST(IoOutputPlot, MissingColumnFileAndGnuplotAreReported) {
  const fs::path dir = fresh_dir("plot_missing");
  write_forces(dir);
  PlotParams p;
  p.velocity = 2.33;
  p.radius = 0.1;
  std::string msg;
  p.gnuplot = "/nonexistent/gnuplot";
  EXPECT_EQ(plot_results(dir.string(), "cylinder_entry", p, msg), 1);
  EXPECT_NE(msg.find("not found"), std::string::npos) << msg;

  SKIP_WITHOUT_GNUPLOT();
  p.gnuplot = "gnuplot";
  p.body = "wedge";
  EXPECT_EQ(plot_results(dir.string(), "cylinder_entry", p, msg), 2);
  EXPECT_NE(msg.find("\"wedge Fy [N/m]\""), std::string::npos) << msg;
  EXPECT_NE(msg.find("cylinder Fy [N/m]"), std::string::npos) << msg;  // lists columns

  p.dam_width = 0.146;
  EXPECT_EQ(plot_results(dir.string(), "dam_break", p, msg), 2);
  EXPECT_NE(msg.find("probes.csv does not exist"), std::string::npos) << msg;
  EXPECT_EQ(plot_results(dir.string(), "sloshing", p, msg), 2);
  EXPECT_EQ(plot_csv_columns(dir.string(), "forces.csv", {"nope [m]"}, "x.png", "gnuplot", msg), 2);
  EXPECT_FALSE(fs::exists(dir / "slamming_force.png"));
}

// "structure" (fuselage studies): the studied body's Fy and every structural probe column,
// by unit (displacements, strains, stresses), with the leak count and the reference
// positions of a body_max_strain probe left out of the panels.
TEST(IoOutputPlot, StructureDrawsForceAndProbePanels) {
  SKIP_WITHOUT_GNUPLOT();
  const fs::path dir = fresh_dir("plot_structure");
  write_forces(dir);
  {
    CsvWriter w((dir / "probes.csv").string(),
                {"time [s]", "keel [m]", "emax [-]", "emax_X [m]", "emax_Y [m]",
                 "keel_stress_von_mises [Pa]", "leaked_particles [-]"});
    for (int i = 0; i <= 100; ++i) {
      const double t = 3e-4 * i;
      w.row({t, 0.02 * std::sin(100 * t), 1e-3 * t, 1.5, 2.0, 4e7 * t, 0.0});
    }
  }
  PlotParams p;
  p.body = "cylinder";
  std::string msg;
  ASSERT_EQ(plot_results(dir.string(), "structure", p, msg), 0) << msg;
  EXPECT_TRUE(is_png(dir / "slamming_force.png"));
  EXPECT_TRUE(is_png(dir / "structure_response.png"));
  // Peak of the synthetic Campbell–Weynberg force (as in CylinderEntryWritesPngs).
  EXPECT_NE(msg.find("peak 2795.9 N/m at 0.001 s"), std::string::npos) << msg;
  std::ifstream in(dir / "structure_response.gp");
  std::stringstream gp;
  gp << in.rdbuf();
  const std::string script = gp.str();
  EXPECT_NE(script.find("layout 3,1"), std::string::npos) << script;
  EXPECT_NE(script.find("title 'keel'"), std::string::npos) << script;
  EXPECT_NE(script.find("(1e-06*column(6))"), std::string::npos) << script;  // Pa -> MPa
  EXPECT_EQ(script.find("emax_X"), std::string::npos) << script;
  EXPECT_EQ(script.find("leaked"), std::string::npos) << script;
  // A body the forces do not name is reported, not drawn.
  p.body = "nobody";
  EXPECT_EQ(plot_results(dir.string(), "structure", p, msg), 2);
  EXPECT_NE(msg.find("nobody Fy [N/m]"), std::string::npos) << msg;
}

TEST(IoOutputPlot, DamBreakPlateGateAndGeneric) {
  SKIP_WITHOUT_GNUPLOT();
  const fs::path dir = fresh_dir("plot_other");
  const double a = 0.146, g = 9.81;
  {
    CsvWriter w((dir / "probes.csv").string(), {"time [s]", "p1 [Pa]", "surge_front [m]"});
    const FrontTable mm = martin_moyce_1952();
    for (std::size_t i = 0; i < mm.T.size(); ++i)
      w.row({mm.T[i] / std::sqrt(2 * g / a), 1000.0, mm.Z[i] * a});
  }
  {
    CsvWriter w((dir / "bodies.csv").string(),
                {"time [s]", "plate tip_dx [m]", "plate tip_dy [m]", "plate ke [J/m]"});
    for (int i = 0; i <= 200; ++i) {
      const double t = 0.002 * i;
      w.row({t, 0.001 * (1 - std::cos(24.73 * t)), 0.023 * std::sin(24.73 * t), 1.0});
    }
  }
  PlotParams p;
  p.dam_width = a;
  std::string msg;
  ASSERT_EQ(plot_results(dir.string(), "dam_break", p, msg), 0) << msg;
  EXPECT_TRUE(is_png(dir / "surge_front.png"));
  EXPECT_NE(msg.find("Martin & Moyce 1952 (T <= 3, 13 points): rms 0.0%"), std::string::npos)
      << msg;

  p.plate_omega = 24.73;
  p.plate_amplitude = 0.023;
  ASSERT_EQ(plot_results(dir.string(), "plate", p, msg), 0) << msg;
  EXPECT_TRUE(is_png(dir / "plate_tip.png"));
  ASSERT_EQ(plot_results(dir.string(), "gate", p, msg), 0) << msg;
  EXPECT_TRUE(is_png(dir / "gate_tip.png"));
  EXPECT_NE(msg.find("plate tip_dy [m] peak"), std::string::npos) << msg;

  // Issue 12: a plot of an incomplete run carries that in its title (PlotParams::note);
  // gnuplot accepts the two-line title (the PNG is drawn).
  const std::string note = "INCOMPLETE RUN (stopped), not the case's result";
  auto script = [&](const char* gp) {
    std::ifstream in(dir / gp);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  EXPECT_EQ(script("gate_tip.gp").find("INCOMPLETE"), std::string::npos);
  p.note = note;
  fs::remove(dir / "gate_tip.png");
  ASSERT_EQ(plot_results(dir.string(), "gate", p, msg), 0) << msg;
  EXPECT_TRUE(is_png(dir / "gate_tip.png"));
  EXPECT_NE(script("gate_tip.gp")
                .find("set title 'Dam break through an elastic gate: tip "
                      "displacement' . \"\\n\" . 'INCOMPLETE RUN (stopped), "
                      "not the case''s result'"),
            std::string::npos)
      << script("gate_tip.gp");
  for (const char* kind : {"dam_break", "plate"}) {
    ASSERT_EQ(plot_results(dir.string(), kind, p, msg), 0) << msg;
    EXPECT_NE(script(std::string(kind) == "plate" ? "plate_tip.gp" : "surge_front.gp")
                  .find("INCOMPLETE RUN"),
              std::string::npos)
        << kind;
  }
  p.note.clear();

  ASSERT_EQ(plot_csv_columns(dir.string(), "bodies.csv", {"plate ke [J/m]"}, "energy.png",
                             "gnuplot", msg),
            0)
      << msg;
  EXPECT_TRUE(is_png(dir / "energy.png"));
  EXPECT_TRUE(fs::exists(dir / "energy.gp"));
}

// Column names as the app writes them: bodies.csv "<body> com_x [m]" (not a tip), probes.csv
// "<probe>_x [m]" / "<probe>_y [m]" for a body_displacement probe, "<probe> [m]" for a front.
TEST(IoOutputPlot, FindsProbeColumnsByConvention) {
  SKIP_WITHOUT_GNUPLOT();
  const fs::path dir = fresh_dir("plot_probes");
  {
    CsvWriter b((dir / "bodies.csv").string(), {"time [s]", "gate com_x [m]", "gate com_y [m]"});
    CsvWriter w((dir / "probes.csv").string(),
                {"time [s]", "front [m]", "free_end_x [m]", "free_end_y [m]"});
    for (int i = 0; i <= 40; ++i) {
      const double t = 0.01 * i;
      b.row({t, 0.5, 0.5});
      w.row({t, 0.1 + t, 0.04 * std::sin(10 * t), 0.013 * std::sin(10 * t)});
    }
  }
  PlotParams p;
  p.dam_width = 0.1;
  std::string msg;
  ASSERT_EQ(plot_results(dir.string(), "dam_break", p, msg), 0) << msg;
  EXPECT_TRUE(is_png(dir / "surge_front.png"));
  ASSERT_EQ(plot_results(dir.string(), "gate", p, msg), 0) << msg;
  EXPECT_NE(msg.find("from probes.csv; free_end_x [m] peak 0.039983 m at 0.16 s"),
            std::string::npos)
      << msg;
  EXPECT_EQ(msg.find("com_x"), std::string::npos) << msg;
  EXPECT_TRUE(is_png(dir / "gate_tip.png"));
}

}  // namespace
}  // namespace slamsph
