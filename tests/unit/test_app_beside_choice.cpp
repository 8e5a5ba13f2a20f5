// BesideChoice (app/beside_choice.h): which way a small body's sub-steps and the water's pass
// run, from measured wall times. The choice changes speed only (the results are the same
// either way: AppThreads.* compares 1 and 2 threads over runs that take both ways).
#include <gtest/gtest.h>

#include "app/beside_choice.h"

using namespace slamsph;

namespace {

// Feeds `n` decisions, each timed by `seconds(beside)`; returns how many went beside.
template <class T>
int feed(BesideChoice& c, int n, T seconds) {
  int beside = 0;
  for (int k = 0; k < n; ++k) {
    const bool b = c.beside();
    beside += b;
    c.record(b, seconds(b));
  }
  return beside;
}

}  // namespace

TEST(BesideChoice, ProbesBothWaysThenTakesTheFaster) {
  BesideChoice c;
  for (std::uint32_t k = 0; k < BesideChoice::kProbe; ++k) {
    EXPECT_FALSE(c.beside());
    c.record(false, 1.0);
  }
  for (std::uint32_t k = 0; k < BesideChoice::kProbe; ++k) {
    EXPECT_TRUE(c.beside());
    c.record(true, 0.8);
  }
  EXPECT_TRUE(c.beside());
  // Over a long run only the rechecks go the slower way.
  const int n = 10 * BesideChoice::kRecheck;
  const int beside = feed(c, n, [](bool b) { return b ? 0.8 : 1.0; });
  EXPECT_EQ(n - beside, 10 * static_cast<int>(BesideChoice::kProbe));
}

TEST(BesideChoice, InTurnWhenBesideIsSlower) {
  BesideChoice c;
  const int n = 4 * BesideChoice::kRecheck;
  const int beside = feed(c, n, [](bool b) { return b ? 1.3 : 1.0; });
  // The first probe and one recheck per kRecheck decisions.
  EXPECT_LE(beside, 5 * static_cast<int>(BesideChoice::kProbe));
  EXPECT_FALSE(c.beside());
}

TEST(BesideChoice, OnePreemptedSampleDoesNotDecide) {
  BesideChoice c;
  feed(c, 40, [](bool b) { return b ? 0.8 : 1.0; });
  ASSERT_TRUE(c.beside());
  c.record(true, 50.0);  // one advance preempted for a long time
  EXPECT_TRUE(c.beside());
  EXPECT_DOUBLE_EQ(c.median_beside(), 0.8);
}

TEST(BesideChoice, FollowsACostThatChanges) {
  BesideChoice c;
  feed(c, 100, [](bool b) { return b ? 0.8 : 1.0; });
  ASSERT_TRUE(c.beside());
  // Beside becomes slower (the water spread, the pass on one thread now sets the pace): the
  // beside window fills with the new times within one window and the choice turns.
  feed(c, 30, [](bool b) { return b ? 1.5 : 1.0; });
  EXPECT_FALSE(c.beside());
  // ... and back, found by the rechecks.
  const int beside = feed(c, 3 * BesideChoice::kRecheck, [](bool b) { return b ? 0.5 : 1.0; });
  EXPECT_TRUE(c.beside());
  EXPECT_GT(beside, BesideChoice::kRecheck);
}
