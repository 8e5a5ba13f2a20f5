// ProgressLine with a fake clock: rate limiting (~4 Hz), steps/s, percentage and ETA.
#include <gtest/gtest.h>

#include <algorithm>

#include <sstream>

#include "io/progress_line.h"

namespace slamsph {
namespace {

TEST(IoOutputProgress, HmsFormatting) {
  EXPECT_EQ(format_hms(0), "0:00:00");
  EXPECT_EQ(format_hms(83), "0:01:23");
  EXPECT_EQ(format_hms(3600 * 12 + 61), "12:01:01");
  EXPECT_EQ(format_hms(-1), "--:--:--");
}

TEST(IoOutputProgress, RateLimitedLineWithStepsPerSecondAndEta) {
  double now = 100.0;
  std::ostringstream out;
  ProgressLine p(
      0.05, true, [&] { return now; }, out);

  p.update(0.0, 0, 1e-6);  // first call always draws
  EXPECT_EQ(out.str().substr(0, 1), "\r");
  const std::size_t after_first = out.str().size();

  now = 100.1;
  p.update(0.001, 100, 1e-6);  // 0.1 s later: suppressed
  EXPECT_EQ(out.str().size(), after_first);

  now = 101.0;  // 1 s after start: 1000 steps, t = 0.01 of 0.05 → 20 %, ETA 4 s
  p.update(0.01, 1000, 1.25e-6);
  const std::string all = out.str();
  const std::string line = all.substr(all.rfind('\r') + 1);
  EXPECT_NE(line.find("t 0.01/0.05 s"), std::string::npos) << line;
  EXPECT_NE(line.find(" 20.0%"), std::string::npos) << line;
  EXPECT_NE(line.find("1000 steps  1000 steps/s"), std::string::npos) << line;
  EXPECT_NE(line.find("dt 1.25e-06 s"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 0:00:04"), std::string::npos) << line;

  p.finish();
  EXPECT_EQ(out.str().back(), '\n');
  const std::size_t final_size = out.str().size();
  p.finish();
  p.update(0.02, 2000, 1e-6);
  EXPECT_EQ(out.str().size(), final_size);  // nothing after finish
}

TEST(IoOutputProgress, ShorterLineIsPaddedOverPrevious) {
  double now = 0.0;
  std::ostringstream out;
  ProgressLine p(
      1.0, true, [&] { return now; }, out);
  p.update(0.0, 123456789, 1e-3);
  const std::string first = out.str();
  now = 1.0;
  p.update(0.5, 123456790, 1e-3);
  const std::string second = out.str().substr(first.size());
  EXPECT_GE(second.size(), first.size());  // padded with spaces to cover the old text
}

TEST(IoOutputProgress, DisabledPrintsNothing) {
  double now = 0.0;
  std::ostringstream out;
  ProgressLine p(
      1.0, false, [&] { return now; }, out);
  p.update(0.5, 10, 1e-3);
  now = 10;
  p.update(0.9, 20, 1e-3);
  p.finish();
  EXPECT_TRUE(out.str().empty());
}

// Issue 12: batch logs showed only the last line. Off a terminal, a plain line every N
// seconds of wall time, each ending in a newline, with elapsed time and ETA.
TEST(IoOutputProgress, PlainLinesForLogs) {
  double now = 0.0;
  std::ostringstream out;
  ProgressLine p(
      1.0, true, [&] { return now; }, out);
  p.set_plain(10.0);
  p.update(0.0, 0, 1e-3);  // first update draws
  for (int k = 1; k <= 30; ++k) {
    now = k;
    p.update(0.02 * k, 10 * k, 1e-3);
  }
  p.finish();
  const std::string s = out.str();
  EXPECT_EQ(s.find('\r'), std::string::npos) << s;
  EXPECT_EQ(std::count(s.begin(), s.end(), '\n'), 5) << s;  // t = 0, 10, 20, 30 s + finish
  EXPECT_NE(s.find("progress: t 0.2/1 s"), std::string::npos) << s;
  EXPECT_NE(s.find("elapsed 0:00:10"), std::string::npos) << s;
  EXPECT_NE(s.find("ETA"), std::string::npos) << s;
}

}  // namespace
}  // namespace slamsph
