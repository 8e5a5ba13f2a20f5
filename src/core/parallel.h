// The one place that knows about threads (style.md §5). Every loop over particles goes
// through Executor::for_each with a gather-style body (each iteration writes only its own
// entries), so results are bit-identical for any thread count (no atomics, no
// order-dependent reductions). max_of is exact in any order; sum_of adds in fixed blocks
// whose partial sums are combined in block order, the same for any thread count.
//
// Loops that need several passes with a data dependency between them (the solid sub-step,
// solid/elastic_substep.h) run inside one parallel region instead (Executor::run_team): every
// thread takes the same contiguous share of the particles in every pass and the passes are
// separated by Team::barrier().
// The executor counts the parallel regions it opens and the barriers of its teams
// (sync_counts) so that tests can hold the synchronisation per sub-step fixed.
//
// The threads are slamsph's own (ThreadPool, parallel.cpp), not OpenMP's (issue 13 item 2).
// A waiting thread spins for a bounded time (kSpinMicroseconds) and then sleeps on a futex,
// and does not spin at all while the machine has more runnable threads than this process's
// CPUs: on idle cores a region starts and ends in about a microsecond, as with a spinning
// runtime, and on cores shared with other processes a thread whose partner is descheduled
// gives its core back at once instead of holding it (libgomp's default spins up to
// ~300 000 iterations and collapsed such runs 10-20x; its passive policy made every region
// a futex wake-up and a 3 200-particle fluid 1.75x slower on 2 idle threads than on 1).
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/band_shares.h"

namespace slamsph {

class ThreadPool;  // parallel.cpp: the worker threads and their spin-then-sleep waiting

// Synchronisation of an executor since its construction.
struct SyncCounts {
  std::uint64_t regions = 0;   // parallel regions opened (each a fork and a join)
  std::uint64_t barriers = 0;  // Team::barrier() calls of teams of two or more threads
  std::uint64_t reduced = 0;   // loops run on fewer threads than asked (Load::Adapt)
};

// The threads of one parallel region opened by Executor::run_team. Each thread calls the
// team function with its own Team; rank() is 0..size()-1.
class Team {
 public:
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool leader() const { return rank_ == 0; }
  // This thread's contiguous share [first, second) of n items: the same for every pass, so
  // a thread that wrote item i in one pass reads it back from its own cache in the next.
  std::pair<std::size_t, std::size_t> share(std::size_t n) const {
    return {n * static_cast<std::size_t>(rank_) / static_cast<std::size_t>(size_),
            n * static_cast<std::size_t>(rank_ + 1) / static_cast<std::size_t>(size_)};
  }
  // f(i) for every i of this thread's share (no barrier).
  template <class F>
  void for_each(std::size_t n, F&& f) const {
    const auto [b, e] = share(n);
    for (std::size_t i = b; i < e; ++i) f(i);
  }
  // Every thread of the team waits here until all have arrived (memory is then consistent).
  void barrier() const;

 private:
  friend class Executor;
  Team(int rank, int size, std::atomic<std::uint64_t>* barriers, ThreadPool* pool)
      : rank_(rank), size_(size), barriers_(barriers), pool_(pool) {}
  int rank_ = 0;
  int size_ = 1;
  std::atomic<std::uint64_t>* barriers_ = nullptr;
  ThreadPool* pool_ = nullptr;
};

class Executor {
 public:
  // Fixed: every loop uses the threads asked for (tests, benchmarks). Adapt (the runs of
  // the command line): while the machine has more runnable threads than this process's
  // CPUs, a loop uses only as many threads as there are CPUs left by the other programs
  // (at least 1). A loop's result does not depend on its thread count, so this changes
  // the speed, never the results. ThreadPool::threads_now in parallel.cpp.
  enum class Load { Fixed, Adapt };
  explicit Executor(int threads = 1, Load load = Load::Fixed);
  // Copies share the worker threads (the pool is made at the first parallel region); an
  // executor and its copies must not open regions from two threads at once.
  Executor(const Executor& o) : threads_(o.threads_), load_(o.load_), pool_(o.pool_) {}
  Executor& operator=(const Executor& o) {
    threads_ = o.threads_;
    load_ = o.load_;
    pool_ = o.pool_;
    return *this;
  }
  ~Executor();
  int threads() const { return threads_; }

  // The threads worth using for a team over `items` items of which each thread should have
  // at least `min_per_thread` (fewer items make the barriers cost more than the split
  // saves): in [1, threads()].
  int threads_for(std::size_t items, std::size_t min_per_thread) const {
    const std::size_t t = items / std::max<std::size_t>(1, min_per_thread);
    return static_cast<int>(std::clamp<std::size_t>(t, 1, static_cast<std::size_t>(threads_)));
  }

  // f(team) on each of min(threads, threads()) threads of one parallel region (see the
  // header comment); with one thread, or called from inside a region, f runs on the caller
  // as a team of one and no region is opened.
  template <class F>
  void run_team(int threads, F&& f) const {
    const int t = team_now(std::clamp(threads, 1, threads_));
    if (t == 1) {
      f(Team(0, 1, &barriers_, nullptr));
      return;
    }
    ThreadPool* pool = this->pool();
    region(t, [&](int rank) { f(Team(rank, t, &barriers_, pool)); });
  }

  // a() and b() at the same time, a on the caller and b on a second thread of one region, or
  // a() then b() on the caller when only one thread is available (one thread asked for, or
  // Load::Adapt finds the other CPU taken, or called from inside a region). Loops inside
  // either run serially (nested). For two independent tasks whose own loops scale poorly on
  // two threads: a small body's sub-steps (two barriers per sub-step) beside the water's
  // pair pass (app/fsi_stepper.h). a and b must not write what the other reads; each then
  // computes what it would alone, on any thread count.
  template <class A, class B>
  void concurrently(A&& a, B&& b) const {
    const int t = team_now(std::min(threads_, 2));
    if (t == 1) {
      a();
      b();
      return;
    }
    region(2, [&](int rank) {
      if (rank == 0)
        a();
      else
        b();
    });
  }

  SyncCounts sync_counts() const {
    return {regions_.load(std::memory_order_relaxed), barriers_.load(std::memory_order_relaxed),
            reduced_.load(std::memory_order_relaxed)};
  }

  // f(i) for i in [0, n), each thread a contiguous share (fewer than min_items items run on
  // the caller).
  static constexpr std::size_t kMinParallel = 257;
  // min_items for loops of a few nanoseconds per item (a kick or drift with the equation of
  // state, a norm for a maximum): below it such a loop runs on the caller while a worker
  // sleeps. A region costs ~1 µs while the workers spin (between the passes of the water
  // phases) but 40-60 µs when one has gone to sleep during a longer serial phase (a futex
  // wake of an idle virtual CPU, measured on this machine kind: the displacement check of a
  // 1 872-particle plate after its one-thread sub-step took 43 µs per step on 2 threads and
  // 2 µs on 1, session 13), while 16 384 such items at a few ns each take tens of µs on one
  // thread. Results are the same either way (docs/validation.md §6).
  static constexpr std::size_t kMinParallelCheap = 16384;
  template <class F>
  void for_each(std::size_t n, F&& f, std::size_t min_items = kMinParallel) const {
    const int t = on_caller(n, min_items) ? 1 : team_now(threads_);
    if (t == 1) {
      for (std::size_t i = 0; i < n; ++i) f(i);
      return;
    }
    region(t, [&](int rank) {
      const auto [b, e] = share(n, rank, t);
      for (std::size_t i = b; i < e; ++i) f(i);
    });
  }

  // f(i) for i in [0, n) where item i costs about pair_units (work[i + 1] - work[i]) + 1 units
  // (`work` a prefix sum with n + 1 entries, e.g. NeighbourList::start: pair_units per pair and
  // one per item): each thread takes a contiguous share of about equal cost. For gathers over
  // lists whose long entries cluster in one part of the index range (the fluid next to a
  // tank's bottom wall, the wetted face of a body), where equal counts of items leave one
  // thread with most of the pairs. pair_units is what a pair costs against an item without
  // pairs: with 1 where a pair costs ten times more, the thread that got the wall's
  // neighbours took 2.5x the other's time (docs/validation.md §6, Threads, Session 15).
  // The units are the first guess only: a loop's shares then follow the times its threads
  // took (learn_shares below), since what an item costs beyond its pairs differs from loop to
  // loop and along the index range (a body's particles against a tank's, vector lanes against
  // the scalar path). Each iteration writes only its own entries, as in for_each, so the
  // result does not depend on the split.
  template <class F>
  void for_each_weighted(std::size_t n, const std::uint32_t* work, F&& f,
                         std::uint32_t pair_units = 1) const {
    const int t = n < kMinParallel ? 1 : team_now(threads_);
    if (t == 1) {
      for (std::size_t i = 0; i < n; ++i) f(i);
      return;
    }
    weighted_region(loop_key<F>(), n, work, pair_units, t, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) f(i);
    });
  }

  // for_each_weighted with f(begin, end) called once on each thread's share (the same shares):
  // for loops that work on runs of items (coupling/contact_pair_lanes.h packs the pairs of
  // consecutive items).
  template <class F>
  void for_ranges_weighted(std::size_t n, const std::uint32_t* work, F&& f,
                           std::uint32_t pair_units = 1) const {
    const int t = n < kMinParallel ? 1 : team_now(threads_);
    if (t == 1) {
      f(std::size_t{0}, n);
      return;
    }
    weighted_region(loop_key<F>(), n, work, pair_units, t, f);
  }

  // The shares of one weighted loop, as fractions of its units (0 = bound[0] <= bound[1] <=
  // ... <= bound[t] = 1), learnt from the seconds each thread took for its share the last
  // time: the cost is taken as uniform over the units within each share, the bounds are put
  // where that cost splits evenly, and each bound moves half-way there and by at most
  // kMaxShareStep of the units per call (a thread preempted once must not throw the split
  // far). Loops shorter than kMinLearnSeconds in all leave the bounds as they are (their
  // times are the clock's noise). units[r] is the unit count at the start of share r as it
  // ran (units[t] the total), seconds[r] its thread's time.
  static constexpr double kMaxShareStep = 0.05;
  static constexpr double kMinLearnSeconds = 2e-6;
  static void learn_shares(std::vector<double>& bound, const std::vector<double>& units,
                           const std::vector<double>& seconds);

  // Chunked variant: f(begin, end) on threads() contiguous ranges (the same ranges whatever
  // the threads that run them).
  template <class F>
  void for_ranges(std::size_t n, F&& f) const {
    const int t = team_now(threads_);
    if (t == 1) {
      for (int c = 0; c < threads_; ++c) {
        const auto [b, e] = share(n, c, threads_);
        f(b, e);
      }
      return;
    }
    region(t, [&](int rank) {
      for (int c = rank; c < threads_; c += t) {
        const auto [b, e] = share(n, c, threads_);
        f(b, e);
      }
    });
  }

  // f(b) for every band b in [0, n): first the even bands, in parallel, then the odd ones.
  // For pair loops over banded particles (core/cell_grid.h, BandedPairs) in which the task of
  // band b writes only to bands b and b + 1: tasks running together write disjoint data, and
  // every particle receives its contributions in the same order for any thread count.
  // Each thread first takes the bands of its own contiguous share, from the front, and then
  // takes what is left of the others' from their back (their costs differ). So a band stays
  // with the core whose share of the particles the sweeps between the passes (for_each,
  // maxima_of: the same contiguous shares) write: handed out one at a time to whichever
  // thread asked, half the bands went to the other core, and every pass and sweep first
  // fetched those lines from the other core's cache (the 3 200-particle dam break on 2
  // threads: the integrator's three sweeps 2.4x their 1-thread time; docs/validation.md §6,
  // Session 20).
  template <class F>
  void for_alternating(std::size_t n, F&& f) const {
    for (std::size_t parity = 0; parity < 2; ++parity) {
      const std::size_t count = (n + 1 - parity) / 2;
      const int t = count < 2 ? 1 : team_now(threads_);
      if (t == 1) {
        for (std::size_t k = 0; k < count; ++k) f(2 * k + parity);
        continue;
      }
      BandShares shares(count, t);
      region(t, [&](int rank) {
        for (std::size_t k; (k = shares.next(rank)) < count;) f(2 * k + parity);
      });
    }
  }

  // max over i of g(i); returns `init` for n == 0. Max is order-independent, hence exact.
  // min_items as for for_each (kMinParallelCheap for cheap g).
  template <class G>
  double max_of(std::size_t n, G&& g, double init = -std::numeric_limits<double>::infinity(),
                std::size_t min_items = kMinParallel) const {
    return maxima_of<1>(
        n, [&g](std::size_t i) { return std::array<double, 1>{g(i)}; }, init, min_items)[0];
  }

  // Component-wise max over i of g(i), an std::array<double, N>: N maxima in one sweep, each
  // exact as max_of's (the same comparison, init for n == 0, NaN never taken). g(i) may also
  // write item i's own entries: a per-particle sweep that reduces what the next operator
  // would otherwise read again (app/fsi_stepper.cpp, the step limit and the state check in
  // the integrator's last sweep). Each thread takes the same contiguous share as for_each,
  // and calls its own copy of g.
  template <std::size_t N, class G>
  std::array<double, N> maxima_of(std::size_t n, G&& g, double init,
                                  std::size_t min_items = kMinParallel) const {
    auto max_range = [&](std::size_t b, std::size_t e) {
      // A copy per share: what g captures by value (pointers, constants) stays in registers
      // instead of being loaded again after each of g's stores.
      std::decay_t<G> item(g);
      std::array<double, N> m;
      m.fill(init);
      for (std::size_t i = b; i < e; ++i) {
        const std::array<double, N> v = item(i);
        for (std::size_t k = 0; k < N; ++k)
          if (v[k] > m[k]) m[k] = v[k];
      }
      return m;
    };
    const int t = on_caller(n, min_items) ? 1 : team_now(threads_);
    if (t == 1) return max_range(0, n);
    std::vector<std::array<double, N>> part(static_cast<std::size_t>(t));
    region(t, [&](int rank) {
      const auto [b, e] = share(n, rank, t);
      part[static_cast<std::size_t>(rank)] = max_range(b, e);
    });
    std::array<double, N> m;
    m.fill(init);
    for (const std::array<double, N>& v : part)
      for (std::size_t k = 0; k < N; ++k)
        if (v[k] > m[k]) m[k] = v[k];
    return m;
  }

  // Σ_i g(i) over [0, n) (T a value type with += and T{} = 0, e.g. double or Vec2): g(i) over
  // blocks of kSumBlock consecutive items, each block summed in index order (in parallel),
  // then the block sums in block order. Neither order depends on the thread count, so the
  // result is bit-identical for any threads(). g may write item i's own entries (as in
  // for_each).
  static constexpr std::size_t kSumBlock = 1024;
  template <class T, class G>
  T sum_of(std::size_t n, G&& g) const {
    const std::size_t blocks = (n + kSumBlock - 1) / kSumBlock;
    std::vector<T> part(blocks, T{});
    auto sum_blocks = [&](std::size_t kb, std::size_t ke) {
      for (std::size_t k = kb; k < ke; ++k) {
        const std::size_t b = k * kSumBlock;
        const std::size_t e = std::min(n, b + kSumBlock);
        T s{};
        for (std::size_t i = b; i < e; ++i) s += g(i);
        part[k] = s;
      }
    };
    const int t = blocks < 2 ? 1 : team_now(threads_);
    if (t == 1) {
      sum_blocks(0, blocks);
    } else {
      region(t, [&](int rank) {
        const auto [kb, ke] = share(blocks, rank, t);
        sum_blocks(kb, ke);
      });
    }
    T total{};
    for (const T& s : part) total += s;
    return total;
  }

  static constexpr int kMaxThreads = 1024;
  // Threads the hardware offers (std::thread::hardware_concurrency, at least 1).
  static int hardware_threads();
  // CPUs in this process's affinity mask (what taskset or a batch scheduler allows), 0 if
  // unknown.
  static int affinity_threads();
  // The first entry of OMP_NUM_THREADS if it is a whole number in [1, kMaxThreads], else 0.
  // (slamsph does not use OpenMP; the variable is honoured as the usual way to set a
  // thread count.)
  static int env_threads();
  // The default thread count of a run: OMP_NUM_THREADS, else the affinity mask, else the
  // hardware.
  static int default_threads();

  // How long a waiting thread spins at most before it sleeps on a futex [µs]:
  // kSpinMicroseconds, or SLAMSPH_SPIN_US (0 to 100 000) when set, read when an executor's
  // threads start. It spins only while the machine has no more runnable threads than this
  // process's CPUs (ThreadPool::probe in parallel.cpp).
  static constexpr int kSpinMicroseconds = 200;
  static int spin_microseconds();
  // The wait policy in force, for summary.json.
  static std::string wait_policy();

 private:
  // [b, e) of rank's contiguous share of n items among t threads.
  static std::pair<std::size_t, std::size_t> share(std::size_t n, int rank, int t) {
    return {n * static_cast<std::size_t>(rank) / static_cast<std::size_t>(t),
            n * static_cast<std::size_t>(rank + 1) / static_cast<std::size_t>(t)};
  }
  // A weighted loop's identity (its body's type): one learnt split per loop.
  template <class F>
  static const void* loop_key() {
    static const char key = 0;
    return &key;
  }
  // The learnt bounds of `loop` on t threads with pair_units u (at r / t on first use).
  struct LearntShares {
    const void* loop = nullptr;
    int t = 0;
    std::uint64_t pair_units = 0;
    std::vector<double> bound, units, seconds;
    std::vector<std::size_t> at;
  };
  LearntShares& learnt_shares(const void* loop, int t, std::uint64_t u) const;
  // The least i with u (work[i] - work[0]) + i >= goal (n if none).
  static std::size_t unit_bound(std::size_t n, const std::uint32_t* work, std::uint64_t u,
                                double goal) {
    std::size_t lo = 0, hi = n;
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (static_cast<double>(u * (std::uint64_t{work[mid]} - work[0]) + mid) < goal)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo;
  }
  // run(begin, end) on each of t threads, the shares from the loop's learnt bounds; then the
  // bounds learn from the threads' times.
  template <class R>
  void weighted_region(const void* loop, std::size_t n, const std::uint32_t* work, std::uint64_t u,
                       int t, R&& run) const {
    LearntShares& s = learnt_shares(loop, t, u);
    const double total = static_cast<double>(u * (std::uint64_t{work[n]} - work[0]) + n);
    for (std::size_t k = 0; k <= static_cast<std::size_t>(t); ++k) {
      s.at[k] = k == 0                             ? 0
                : k == static_cast<std::size_t>(t) ? n
                                                   : unit_bound(n, work, u, s.bound[k] * total);
      s.units[k] = static_cast<double>(u * (std::uint64_t{work[s.at[k]]} - work[0]) + s.at[k]);
    }
    region(t, [&](int rank) {
      const auto k = static_cast<std::size_t>(rank);
      const auto start = std::chrono::steady_clock::now();
      run(s.at[k], s.at[k + 1]);
      s.seconds[k] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    });
    learn_shares(s.bound, s.units, s.seconds);
  }
  // job(rank) for rank in [0, t) on t threads, rank 0 on the caller; returns when all are
  // done. An exception thrown by a job is rethrown here (the first one).
  template <class J>
  void region(int t, J&& job) const {
    regions_.fetch_add(1, std::memory_order_relaxed);
    using Job = std::remove_reference_t<J>;
    run_region(
        t, [](void* ctx, int rank) { (*static_cast<Job*>(ctx))(rank); },
        const_cast<void*>(static_cast<const void*>(&job)));
  }
  void run_region(int t, void (*fn)(void*, int), void* ctx) const;
  // The threads a loop asking for t threads runs on now: 1 inside a region, t with
  // Load::Fixed, with Load::Adapt possibly fewer (counted in sync_counts().reduced).
  int team_now(int t) const;
  // A loop of n items runs on the caller: fewer than kMinParallel, or fewer than min_items
  // while a worker sleeps (see kMinParallelCheap).
  bool on_caller(std::size_t n, std::size_t min_items) const {
    return n < kMinParallel || (n < min_items && threads_ > 1 && workers_asleep());
  }
  bool workers_asleep() const;
  ThreadPool* pool() const;
  // True on a thread that is running a region's job (nested loops then run serially).
  static bool in_region();

  int threads_ = 1;
  Load load_ = Load::Fixed;
  mutable std::shared_ptr<ThreadPool> pool_;
  mutable std::atomic<std::uint64_t> regions_{0};
  mutable std::atomic<std::uint64_t> barriers_{0};
  mutable std::atomic<std::uint64_t> reduced_{0};
  mutable std::vector<LearntShares> learnt_;  // one per weighted loop (used by the caller only)
};

}  // namespace slamsph
