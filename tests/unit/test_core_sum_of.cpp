// Executor::sum_of (core/parallel.h): the fixed-block sum is bit-identical for 1, 2 and 3
// threads, equals the block-order sum written out serially, and lets g write item i (the
// absorbing zone's use). Broken on purpose: summing each thread's share and then the threads
// (instead of fixed blocks) fails it at 1, 2 and 3 threads: another order, other bits here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/parallel.h"
#include "core/vec.h"

using namespace slamsph;

TEST(SumOf, SameBitsForAnyThreadCountAndBlockOrder) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Values of very different size, so that another summation order changes the last bits.
  const std::size_t n = 10 * Executor::kSumBlock + 37;
  std::vector<Vec2> v(n);
  for (Vec2& x : v) x = {u(rng) * std::exp(20.0 * u(rng)), u(rng) * std::exp(20.0 * u(rng))};
  Vec2 serial;
  for (std::size_t b = 0; b < n; b += Executor::kSumBlock) {
    Vec2 s;
    for (std::size_t i = b; i < std::min(n, b + Executor::kSumBlock); ++i) s += v[i];
    serial += s;
  }
  for (int threads : {1, 2, 3}) {
    const Vec2 s = Executor(threads).sum_of<Vec2>(n, [&](std::size_t i) { return v[i]; });
    EXPECT_EQ(s.x, serial.x) << threads << " threads";
    EXPECT_EQ(s.y, serial.y) << threads << " threads";
  }
  EXPECT_EQ(Executor(2).sum_of<double>(0, [](std::size_t) { return 1.0; }), 0.0);
  std::vector<double> w(n, 2.0);
  const double total = Executor(2).sum_of<double>(n, [&](std::size_t i) {
    w[i] *= 0.5;
    return w[i];
  });
  EXPECT_EQ(total, static_cast<double>(n));
  for (double x : w) EXPECT_EQ(x, 1.0);
}
