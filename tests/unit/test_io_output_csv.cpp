// CsvWriter: headers must carry units, values round-trip exactly through read_csv, rows are
// flushed periodically and on destruction.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "io/csv_writer.h"

namespace slamsph {
namespace {

namespace fs = std::filesystem;

std::string tmp_file(const std::string& name) {
  return (fs::path(testing::TempDir()) / ("slamsph_" + name)).string();
}

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

TEST(IoOutputCsv, HeaderWithoutUnitIsRejected) {
  const std::string p = tmp_file("csv_units.csv");
  EXPECT_THROW(CsvWriter(p, {"time [s]", "Fx"}), std::invalid_argument);
  EXPECT_THROW(CsvWriter(p, {"time [s]", "Fx []"}), std::invalid_argument);
  EXPECT_THROW(CsvWriter(p, {"time [s]", "time [s]"}), std::invalid_argument);
  EXPECT_NO_THROW(CsvWriter(p, {"time [s]", "Z [-]", "cyl Fy [N/m]"}));
  EXPECT_TRUE(csv_header_has_unit("rho [kg/m^3]"));
  EXPECT_FALSE(csv_header_has_unit("[s] time"));
}

TEST(IoOutputCsv, ValuesRoundTripExactly) {
  const std::string p = tmp_file("csv_roundtrip.csv");
  const std::vector<std::string> h{"time [s]", "cyl Fy [N/m]", "odd, \"quoted\" [m]"};
  std::vector<std::vector<double>> rows{
      {0.0, 1.0 / 3.0, -1e-300},
      {1e-7, 2796.123456789012, 6.02214076e23},
      {2e-7, std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()}};
  {
    CsvWriter w(p, h);
    for (const auto& r : rows) w.row(r);
    EXPECT_THROW(w.row({1.0}), std::invalid_argument);
    EXPECT_EQ(w.rows_written(), 3u);
  }
  const std::string text = slurp(p);
  EXPECT_EQ(text.substr(0, text.find('\n')), "time [s],cyl Fy [N/m],\"odd, \"\"quoted\"\" [m]\"");
  const CsvTable t = read_csv(p);
  EXPECT_EQ(t.headers, h);
  ASSERT_EQ(t.rows(), 3u);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 3; ++c) {
      if (std::isnan(rows[r][c]))
        EXPECT_TRUE(std::isnan(t.columns[c][r]));
      else
        EXPECT_EQ(t.columns[c][r], rows[r][c]) << "row " << r << " col " << c;
    }
  EXPECT_EQ(t.find("cyl Fy [N/m]"), 1);
  EXPECT_EQ(t.find("Fy"), -1);
}

TEST(IoOutputCsv, FlushesEveryNRowsAndOnDestruction) {
  const std::string p = tmp_file("csv_flush.csv");
  {
    CsvWriter w(p, {"time [s]", "x [m]"}, /*flush_rows=*/2, /*flush_seconds=*/1e9);
    w.row({0, 1});
    EXPECT_EQ(read_csv(p).rows(), 0u);  // still buffered
    w.row({1, 2});
    EXPECT_EQ(read_csv(p).rows(), 2u);  // flushed after 2 rows
    w.row({2, 3});
  }
  EXPECT_EQ(read_csv(p).rows(), 3u);  // destructor flushed
}

TEST(IoOutputCsv, ReaderNamesBadLine) {
  const std::string p = tmp_file("csv_bad.csv");
  std::ofstream(p) << "time [s],x [m]\n0,1\n1,abc\n";
  try {
    read_csv(p);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(":3:"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamsph
