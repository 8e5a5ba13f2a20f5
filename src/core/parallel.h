// The one place that knows about threads (style.md §5). Every loop over particles goes
// through Executor::for_each with a gather-style body (each iteration writes only its own
// entries), so results are bit-identical for any thread count (no atomics, no
// order-dependent reductions). max_of is exact in any order.
#pragma once
#include <cstddef>
#include <limits>
#include <string>

namespace slamsph {

class Executor {
 public:
  explicit Executor(int threads = 1);
  int threads() const { return threads_; }

  template <class F>
  void for_each(std::size_t n, F&& f) const {
    const long long count = static_cast<long long>(n);
#pragma omp parallel for schedule(static) num_threads(threads_) if (count > 256)
    for (long long i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
  }

  // Chunked variant: f(begin, end) on contiguous ranges, one or more per thread.
  template <class F>
  void for_ranges(std::size_t n, F&& f) const {
    const long long chunks = threads_;
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
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(max : m) if (count > 256)
    for (long long i = 0; i < count; ++i) {
      const double v = g(static_cast<std::size_t>(i));
      if (v > m) m = v;
    }
    return m;
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
  int threads_ = 1;
};

}  // namespace slamsph
