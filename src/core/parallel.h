// The one place that knows about threads (style.md §5). Every loop over particles goes
// through Executor::for_each with a gather-style body (each iteration writes only its own
// entries), so results are bit-identical for any thread count (no atomics, no
// order-dependent reductions). max_of is exact in any order; sum_of adds in fixed blocks
// whose partial sums are combined in block order, the same for any thread count.
//
// Loops that need several passes with a data dependency between them (the solid sub-step,
// solid/elastic_substep.h) run inside one parallel region instead (Executor::run_team): every
// thread takes the same contiguous share of the particles in every pass and the passes are
// separated by Team::barrier(). Opening a region costs a fork and a join (two barriers), so
// a team saves two thirds of the synchronisation of a loop of for_each calls.
// The executor counts the parallel regions it opens and the barriers of its teams
// (sync_counts) so that tests can hold the synchronisation per sub-step fixed.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace slamsph {

// Synchronisation of an executor since its construction.
struct SyncCounts {
  std::uint64_t regions = 0;   // parallel regions opened (each a fork and a join)
  std::uint64_t barriers = 0;  // Team::barrier() calls of teams of two or more threads
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
  Team(int rank, int size, std::atomic<std::uint64_t>* barriers)
      : rank_(rank), size_(size), barriers_(barriers) {}
  int rank_ = 0;
  int size_ = 1;
  std::atomic<std::uint64_t>* barriers_ = nullptr;
};

class Executor {
 public:
  explicit Executor(int threads = 1);
  Executor(const Executor& o) : threads_(o.threads_) {}
  Executor& operator=(const Executor& o) {
    threads_ = o.threads_;
    return *this;
  }
  int threads() const { return threads_; }

  // The threads worth using for a team over `items` items of which each thread should have
  // at least `min_per_thread` (fewer items make the barriers cost more than the split
  // saves): in [1, threads()].
  int threads_for(std::size_t items, std::size_t min_per_thread) const {
    const std::size_t t = items / std::max<std::size_t>(1, min_per_thread);
    return static_cast<int>(std::clamp<std::size_t>(t, 1, static_cast<std::size_t>(threads_)));
  }

  // f(team) on each of min(threads, threads()) threads of one parallel region (see the
  // header comment); with one thread, f runs on the caller and no region is opened.
  template <class F>
  void run_team(int threads, F&& f) const {
    const int t = std::clamp(threads, 1, threads_);
    if (t == 1) {
      f(Team(0, 1, &barriers_));
      return;
    }
    count_region();
#pragma omp parallel num_threads(t)
    f(Team(team_rank(), team_size(), &barriers_));
  }

  SyncCounts sync_counts() const {
    return {regions_.load(std::memory_order_relaxed), barriers_.load(std::memory_order_relaxed)};
  }

  template <class F>
  void for_each(std::size_t n, F&& f) const {
    const long long count = static_cast<long long>(n);
    if (count > 256 && threads_ > 1) count_region();
#pragma omp parallel for schedule(static) num_threads(threads_) if (count > 256)
    for (long long i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
  }

  // Chunked variant: f(begin, end) on contiguous ranges, one or more per thread.
  template <class F>
  void for_ranges(std::size_t n, F&& f) const {
    const long long chunks = threads_;
    if (threads_ > 1) count_region();
#pragma omp parallel for schedule(static, 1) num_threads(threads_)
    for (long long c = 0; c < chunks; ++c) {
      const std::size_t b = n * static_cast<std::size_t>(c) / static_cast<std::size_t>(chunks);
      const std::size_t e = n * static_cast<std::size_t>(c + 1) / static_cast<std::size_t>(chunks);
      f(b, e);
    }
  }

  // f(b) for every band b in [0, n): first the even bands, in parallel, then the odd ones.
  // For pair loops over banded particles (core/cell_grid.h, BandedPairs) in which the task of
  // band b writes only to bands b and b + 1: tasks running together write disjoint data, and
  // every particle receives its contributions in the same order for any thread count.
  template <class F>
  void for_alternating(std::size_t n, F&& f) const {
    for (std::size_t parity = 0; parity < 2; ++parity) {
      const long long count = static_cast<long long>((n + 1 - parity) / 2);
      if (count > 1 && threads_ > 1) count_region();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_) if (count > 1)
      for (long long k = 0; k < count; ++k) f(2 * static_cast<std::size_t>(k) + parity);
    }
  }

  // max over i of g(i); returns `init` for n == 0. Max is order-independent, hence exact.
  template <class G>
  double max_of(std::size_t n, G&& g,
                double init = -std::numeric_limits<double>::infinity()) const {
    double m = init;
    const long long count = static_cast<long long>(n);
    if (count > 256 && threads_ > 1) count_region();
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(max : m) if (count > 256)
    for (long long i = 0; i < count; ++i) {
      const double v = g(static_cast<std::size_t>(i));
      if (v > m) m = v;
    }
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
    const long long count = static_cast<long long>(blocks);
    if (count > 1 && threads_ > 1) count_region();
#pragma omp parallel for schedule(static) num_threads(threads_) if (count > 1)
    for (long long k = 0; k < count; ++k) {
      const std::size_t b = static_cast<std::size_t>(k) * kSumBlock;
      const std::size_t e = std::min(n, b + kSumBlock);
      T s{};
      for (std::size_t i = b; i < e; ++i) s += g(i);
      part[static_cast<std::size_t>(k)] = s;
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
  static int env_threads();
  // The default thread count of a run: OMP_NUM_THREADS, else the affinity mask, else the
  // hardware.
  static int default_threads();

  // Call first thing in main(). libgomp spins up to ~300 000 iterations at every barrier
  // before it sleeps; when the cores are shared with other processes a spinning thread
  // holds a core its partner needs, and a run with 2 threads on 2 busy cores measured 7-20x
  // slower than with 1 thread (/work notes of issue 12; README "Threads"). Waiting threads
  // should sleep instead (OMP_WAIT_POLICY=passive), but libgomp reads that variable only
  // once, when it is loaded, before main() runs. So, unless the user has chosen a policy
  // (OMP_WAIT_POLICY or GOMP_SPINCOUNT is set), this sets OMP_WAIT_POLICY=passive and
  // re-executes the program (/proc/self/exe) with the same arguments. Returns only if no
  // re-execution was needed or it failed (the run then goes on with libgomp's default).
  static void use_passive_waiting(char** argv);
  // The wait policy in force: "OMP_WAIT_POLICY=<v>", "GOMP_SPINCOUNT=<v>" or "libgomp default".
  static std::string wait_policy();

 private:
  void count_region() const {
    regions_.fetch_add(1, std::memory_order_relaxed);
  }
  static int team_rank();
  static int team_size();

  int threads_ = 1;
  mutable std::atomic<std::uint64_t> regions_{0};
  mutable std::atomic<std::uint64_t> barriers_{0};
};

}  // namespace slamsph
