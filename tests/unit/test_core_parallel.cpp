// The executor's own threads (core/parallel.h, issue 13 item 2): every loop form gives the
// same answer on 1, 2 and 3 threads, a team's barrier separates its passes, a job's
// exception reaches the caller, nested loops run on the calling thread, and a waiting
// thread that spins for no time (SLAMSPH_SPIN_US=0, every wait a futex sleep) still wakes.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/parallel.h"
#include "core/vec.h"

namespace slamsph {
namespace {

double value(std::size_t i) {
  return std::sin(0.37 * static_cast<double>(i)) * 1e3 + 1e-7 * static_cast<double>(i);
}

TEST(Executor, LoopsGiveTheSameAnswerOnAnyThreadCount) {
  const std::size_t n = 100003;
  std::vector<double> ref_each;
  double ref_sum = 0.0, ref_max = 0.0;
  for (int threads : {1, 2, 3}) {
    const Executor exec(threads);
    std::vector<double> each(n, 0.0);
    exec.for_each(n, [&](std::size_t i) { each[i] = 2.0 * value(i); });
    const double sum = exec.sum_of<double>(n, [&](std::size_t i) { return value(i); });
    const double mx = exec.max_of(n, [&](std::size_t i) { return value(i); });
    std::vector<int> hits(n, 0);
    exec.for_ranges(n, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) ++hits[i];
    });
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i], 1) << i;
    std::vector<int> band_hits(1001, 0);
    exec.for_alternating(band_hits.size(), [&](std::size_t b) { ++band_hits[b]; });
    for (std::size_t b = 0; b < band_hits.size(); ++b) ASSERT_EQ(band_hits[b], 1) << b;
    if (threads == 1) {
      ref_each = each;
      ref_sum = sum;
      ref_max = mx;
    } else {
      EXPECT_EQ(each, ref_each) << threads;
      EXPECT_EQ(sum, ref_sum) << threads;  // bit-identical: fixed blocks
      EXPECT_EQ(mx, ref_max) << threads;
    }
  }
  EXPECT_EQ(Executor(2).max_of(
                0, [](std::size_t) { return 1.0; }, -5.0),
            -5.0);
}

// for_alternating's band shares (core/band_shares.h): a thread takes its own contiguous share
// from the front, then the others' remainders from their back, so that a band stays on the
// core whose sweep share holds its particles; every index is handed out exactly once, also
// with many threads claiming at once and with more threads than shares.
TEST(BandShares, OwnShareFromTheFrontThenTheOthersFromTheirBack) {
  BandShares two(10, 2);  // shares [0, 5) and [5, 10)
  std::vector<std::size_t> got;
  for (std::size_t k; (k = two.next(1)) < 10;) got.push_back(k);
  EXPECT_EQ(got, (std::vector<std::size_t>{5, 6, 7, 8, 9, 4, 3, 2, 1, 0}));
  EXPECT_EQ(two.next(0), 10u);
  BandShares three(7, 3);  // [0, 2), [2, 4), [4, 7)
  EXPECT_EQ(three.next(0), 0u);
  EXPECT_EQ(three.next(2), 4u);
  EXPECT_EQ(three.next(1), 2u);
  EXPECT_EQ(three.next(1), 3u);
  EXPECT_EQ(three.next(1), 6u);  // share 2's back
  EXPECT_EQ(three.next(1), 5u);
  EXPECT_EQ(three.next(1), 1u);  // then share 0's back
  EXPECT_EQ(three.next(1), 7u);  // none left
  EXPECT_EQ(BandShares(0, 4).next(3), 0u);
}

TEST(BandShares, EveryIndexOnceUnderConcurrentClaims) {
  for (int threads : {2, 3, 5, BandShares::kMaxShares + 6}) {
    for (std::size_t count : {std::size_t{1}, std::size_t{3}, std::size_t{64}, std::size_t{5001}}) {
      BandShares shares(count, threads);
      std::vector<std::atomic<int>> hits(count);
      std::vector<std::thread> team;
      for (int r = 0; r < threads; ++r)
        team.emplace_back([&, r] {
          for (std::size_t k; (k = shares.next(r)) < count;) hits[k].fetch_add(1);
        });
      for (std::thread& t : team) t.join();
      for (std::size_t k = 0; k < count; ++k)
        ASSERT_EQ(hits[k].load(), 1) << threads << " threads, " << count << " bands, band " << k;
    }
  }
}

// maxima_of (app/fsi_stepper.cpp's fused sweeps): each component is max_of's, on any thread
// count, NaN never taken and init for an empty range; g runs once per item, so it may write
// item i's own entries on the way.
TEST(Executor, MaximaOfIsMaxOfForEachComponent) {
  const std::size_t n = 100003;
  auto item = [](std::size_t i) {
    return std::array<double, 3>{value(i), -value(i),
                                 i % 7 == 3 ? std::nan("") : std::cos(static_cast<double>(i))};
  };
  std::array<double, 3> ref{};
  for (std::size_t k = 0; k < 3; ++k)
    ref[k] = Executor(1).max_of(
        n, [&](std::size_t i) { return item(i)[k]; }, -7.0, Executor::kMinParallelCheap);
  for (int threads : {1, 2, 3}) {
    const Executor exec(threads);
    std::vector<int> hits(n, 0);
    const std::array<double, 3> m = exec.maxima_of<3>(
        n,
        [&](std::size_t i) {
          ++hits[i];
          return item(i);
        },
        -7.0, Executor::kMinParallelCheap);
    EXPECT_EQ(m, ref) << threads;
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i], 1) << i;
    EXPECT_EQ(exec.maxima_of<2>(
                  0,
                  [](std::size_t) {
                    return std::array<double, 2>{1.0, 2.0};
                  },
                  -5.0),
              (std::array<double, 2>{-5.0, -5.0}));
  }
}

// for_each_weighted visits every item once, and each thread's share costs about the same
// when the work clusters at one end (here all pairs in the first tenth of the items, as the
// fluid next to a tank's bottom wall in cell order).
TEST(Executor, WeightedLoopsSplitTheWorkNotTheItems) {
  const std::size_t n = 20000;
  std::vector<std::uint32_t> work(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) work[i + 1] = work[i] + (i < n / 10 ? 40u : 0u);
  for (int threads : {1, 2, 3}) {
    const Executor exec(threads);
    std::vector<int> hits(n, 0);
    std::vector<std::thread::id> who(n);
    exec.for_each_weighted(n, work.data(), [&](std::size_t i) {
      ++hits[i];
      who[i] = std::this_thread::get_id();
    });
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i], 1) << i;
    // Shares are contiguous: cut the items where the thread changes and weigh each part.
    std::vector<std::uint64_t> parts{0};
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0 && who[i] != who[i - 1]) parts.push_back(0);
      parts.back() += work[i + 1] - work[i] + 1;
    }
    ASSERT_EQ(parts.size(), static_cast<std::size_t>(threads)) << threads;
    const double total = static_cast<double>(work[n] + n);
    for (const std::uint64_t p : parts)
      EXPECT_NEAR(static_cast<double>(p), total / threads, 41.0) << threads;
  }
  // With pair_units u a pair weighs u items: the shares balance u·pairs + items.
  const Executor two(2);
  for (std::uint32_t units : {1u, 8u}) {
    std::vector<std::thread::id> who(n);
    two.for_each_weighted(
        n, work.data(), [&](std::size_t i) { who[i] = std::this_thread::get_id(); }, units);
    std::size_t cut = 1;
    while (cut < n && who[cut] == who[0]) ++cut;
    const double first = static_cast<double>(units) * work[cut] + static_cast<double>(cut);
    const double total = static_cast<double>(units) * work[n] + static_cast<double>(n);
    EXPECT_NEAR(first, 0.5 * total, units * 40.0 + 1.0) << units;
  }
}

// The learnt split of a weighted loop (Executor::learn_shares): each bound moves half-way to
// where the measured cost splits evenly, by at most kMaxShareStep per call, and converges to
// the even split of a cost that is not uniform over the units.
TEST(Executor, WeightedLoopSharesFollowTheMeasuredTimes) {
  // Two shares of 500 units; the first took 3 s, the second 1 s: the even split lies a third
  // of the way in (at 333 units), so the bound moves by the largest step, 0.05, to 0.45.
  std::vector<double> bound{0.0, 0.5, 1.0};
  Executor::learn_shares(bound, {0.0, 500.0, 1000.0}, {3.0, 1.0});
  EXPECT_DOUBLE_EQ(bound[1], 0.5 - Executor::kMaxShareStep);
  // A small difference moves it half-way: 1 s against 0.83 s puts the even split at
  // 0.5 (1 + 1/1.2) / 2 = 0.458 of the units, so the bound goes to 0.479.
  bound = {0.0, 0.5, 1.0};
  Executor::learn_shares(bound, {0.0, 500.0, 1000.0}, {1.0, 1.0 / 1.2});
  EXPECT_NEAR(bound[1], 0.5 + 0.5 * (0.5 * (1.0 + 1.0 / 1.2) / 2.0 - 0.5), 1e-12);
  // Times too short to measure leave the bounds alone.
  bound = {0.0, 0.5, 1.0};
  Executor::learn_shares(bound, {0.0, 500.0, 1000.0}, {1e-7, 3e-7});
  EXPECT_EQ(bound[1], 0.5);
  // Convergence on a cost density of 3 per unit over the first half of the units and 1 over
  // the second (total 2): every share ends with cost 2 / t (bounds 1/3 for t = 2; 2/9 and 4/9
  // for t = 3).
  const auto cost = [](double u) { return u < 0.5 ? 3.0 * u : 1.5 + (u - 0.5); };
  for (int t : {2, 3}) {
    std::vector<double> b(static_cast<std::size_t>(t) + 1), units(b.size()), sec(b.size() - 1);
    for (int r = 0; r <= t; ++r) b[static_cast<std::size_t>(r)] = double(r) / t;
    for (int it = 0; it < 60; ++it) {
      for (std::size_t r = 0; r < b.size(); ++r) units[r] = 1000.0 * b[r];
      for (std::size_t r = 0; r < sec.size(); ++r) sec[r] = cost(b[r + 1]) - cost(b[r]);
      Executor::learn_shares(b, units, sec);
    }
    for (std::size_t r = 0; r < sec.size(); ++r)
      EXPECT_NEAR(cost(b[r + 1]) - cost(b[r]), 2.0 / t, 1e-3) << "t " << t << " share " << r;
  }
}

// A weighted loop visits every item exactly once whatever its learnt split: a loop whose
// first items cost far more than their units say, run many times on 2 threads.
TEST(Executor, WeightedLoopVisitsEveryItemOnceWhileItsSplitMoves) {
  const std::size_t n = 4000;
  std::vector<std::uint32_t> work(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) work[i + 1] = work[i] + 1;
  const Executor two(2);
  std::vector<int> hits(n, 0);
  volatile double sink = 0.0;
  for (int call = 0; call < 50; ++call) {
    two.for_each_weighted(n, work.data(), [&](std::size_t i) {
      ++hits[i];
      if (i < n / 4)
        for (int k = 0; k < 200; ++k) sink = sink + 1e-9 * k;
    });
  }
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i], 50) << i;
}

// Pass k of a team reads what every thread wrote in pass k − 1 (a shifted neighbour outside
// its own share): wrong as soon as one barrier lets a thread through early.
void check_team_barriers(int threads) {
  const Executor exec(threads);
  const std::size_t n = 4096;
  const int passes = 2000;
  std::vector<long> a(n, 0), b(n, 0);
  exec.run_team(threads, [&](const Team& team) {
    for (int k = 0; k < passes; ++k) {
      std::vector<long>& src = (k % 2 == 0) ? a : b;
      std::vector<long>& dst = (k % 2 == 0) ? b : a;
      team.for_each(n, [&](std::size_t i) { dst[i] = src[(i + n / 2 + 1) % n] + 1; });
      team.barrier();
    }
  });
  const std::vector<long>& last = (passes % 2 == 0) ? a : b;
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(last[i], passes) << i;
  EXPECT_EQ(exec.sync_counts().regions, threads > 1 ? 1u : 0u);
  EXPECT_EQ(exec.sync_counts().barriers, threads > 1 ? static_cast<unsigned>(passes) : 0u);
}

TEST(Executor, TeamBarriersSeparateThePasses) {
  for (int threads : {1, 2, 3}) check_team_barriers(threads);
}

TEST(Executor, ThreadsThatSleepAtOnceStillWake) {
  ASSERT_EQ(setenv("SLAMSPH_SPIN_US", "0", 1), 0);
  EXPECT_EQ(Executor::spin_microseconds(), 0);
  check_team_barriers(2);
  const Executor exec(2);
  for (int k = 0; k < 2000; ++k) {  // many short regions, each a futex wake-up
    std::vector<int> v(1000, 0);
    exec.for_each(v.size(), [&](std::size_t i) { v[i] = k; });
    ASSERT_EQ(std::accumulate(v.begin(), v.end(), 0L), 1000L * k);
  }
  unsetenv("SLAMSPH_SPIN_US");
  EXPECT_EQ(Executor::spin_microseconds(), Executor::kSpinMicroseconds);
}

TEST(Executor, AJobsExceptionReachesTheCaller) {
  const Executor exec(2);
  EXPECT_THROW(exec.for_each(10000,
                             [&](std::size_t i) {
                               if (i == 9999) throw std::runtime_error("late item");
                             }),
               std::runtime_error);
  // The executor is usable afterwards.
  EXPECT_EQ(exec.sum_of<double>(5000, [](std::size_t) { return 1.0; }), 5000.0);
}

TEST(Executor, NestedLoopsRunOnTheCallingThread) {
  const Executor exec(2);
  std::vector<std::thread::id> outer(2), inner(2);
  exec.run_team(2, [&](const Team& team) {
    outer[static_cast<std::size_t>(team.rank())] = std::this_thread::get_id();
    std::thread::id seen;
    exec.for_each(10000, [&](std::size_t i) {
      if (i == 0 || i == 9999) seen = std::this_thread::get_id();
    });
    inner[static_cast<std::size_t>(team.rank())] = seen;
  });
  EXPECT_NE(outer[0], outer[1]);
  EXPECT_EQ(inner[0], outer[0]);
  EXPECT_EQ(inner[1], outer[1]);
  // One region: the nested loops opened none.
  EXPECT_EQ(exec.sync_counts().regions, 1u);
}

// Loops marked cheap (Executor::kMinParallelCheap) run on the caller below that many items
// while a worker sleeps, ordinary ones split from kMinParallel: waking a worker costs more
// than such a loop (the displacement check of a 1 872-particle plate, 43 µs per step on 2
// threads). Results are the same either way.
TEST(Executor, CheapLoopsDoNotWakeASleepingWorker) {
  const Executor exec(2);
  const std::size_t n = Executor::kMinParallelCheap - 1;
  std::vector<double> v(n, 0.0);
  exec.for_each(1000, [&](std::size_t i) { v[i] = 1.0; });  // starts the pool
  EXPECT_EQ(exec.sync_counts().regions, 1u);
  // The worker spins for at most Executor::spin_microseconds() after a region, then sleeps.
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  exec.for_each(
      n, [&](std::size_t i) { v[i] = static_cast<double>(i); }, Executor::kMinParallelCheap);
  const double m = exec.max_of(
      n, [&](std::size_t i) { return v[i]; }, 0.0, Executor::kMinParallelCheap);
  EXPECT_EQ(m, static_cast<double>(n - 1));
  EXPECT_EQ(exec.sync_counts().regions, 1u);
  exec.for_each(n, [&](std::size_t i) { v[i] = 0.0; });  // an ordinary loop: split
  EXPECT_EQ(exec.sync_counts().regions, 2u);
  exec.max_of(
      Executor::kMinParallelCheap, [&](std::size_t i) { return static_cast<double>(i); }, 0.0,
      Executor::kMinParallelCheap);
  EXPECT_EQ(exec.sync_counts().regions, 3u);
}

TEST(Executor, CopiesShareTheirThreads) {
  const Executor a(2);
  const Executor b = a;
  std::vector<double> v(5000, 0.0);
  a.for_each(v.size(), [&](std::size_t i) { v[i] = 1.0; });
  b.for_each(v.size(), [&](std::size_t i) { v[i] += 1.0; });
  EXPECT_EQ(std::accumulate(v.begin(), v.end(), 0.0), 10000.0);
}

}  // namespace
}  // namespace slamsph
