#include "core/parallel.h"

#include <fcntl.h>
#include <linux/futex.h>
#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <thread>

namespace slamsph {

namespace {

thread_local bool t_in_region = false;

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

// A word threads wait on for a change of value, and how many of them sleep on it (so that
// a change wakes the kernel only when somebody sleeps).
struct alignas(64) WaitWord {
  std::atomic<std::uint32_t> value{0};
  std::atomic<std::uint32_t> sleepers{0};
};

static_assert(sizeof(std::atomic<std::uint32_t>) == sizeof(std::uint32_t));

void futex_wait(std::atomic<std::uint32_t>& word, std::uint32_t seen) {
  syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word), FUTEX_WAIT_PRIVATE, seen, nullptr,
          nullptr, 0);
}

void futex_wake_all(std::atomic<std::uint32_t>& word) {
  syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr,
          nullptr, 0);
}

// Returns once w.value differs from `seen`: spins (checking the clock every 64 pauses) for
// `spin`, then sleeps on the futex. The sleeper count and the value are sequentially
// consistent on both sides (here and in change()), so either this thread sees the new
// value or the changer sees the sleeper and wakes it; FUTEX_WAIT itself re-checks the
// value before sleeping, so no wake-up is lost.
void wait_for_change(WaitWord& w, std::uint32_t seen, std::int64_t spin_ns) {
  if (spin_ns > 0) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::nanoseconds(spin_ns);
    for (unsigned k = 1;; ++k) {
      if (w.value.load(std::memory_order_acquire) != seen) return;
      cpu_relax();
      if ((k & 63u) == 0 && std::chrono::steady_clock::now() >= until) break;
    }
  }
  w.sleepers.fetch_add(1, std::memory_order_seq_cst);
  while (w.value.load(std::memory_order_seq_cst) == seen) futex_wait(w.value, seen);
  w.sleepers.fetch_sub(1, std::memory_order_seq_cst);
}

void change(WaitWord& w) {
  w.value.fetch_add(1, std::memory_order_seq_cst);
  if (w.sleepers.load(std::memory_order_seq_cst) != 0) futex_wake_all(w.value);
}

// Runnable threads of the whole machine now (the fourth field of /proc/loadavg,
// "running/total"), or -1 if unknown.
int runnable_threads() {
  const int fd = open("/proc/loadavg", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return -1;
  char buf[128];
  const ssize_t n = read(fd, buf, sizeof buf - 1);
  close(fd);
  if (n <= 0) return -1;
  buf[n] = '\0';
  const char* slash = std::strchr(buf, '/');
  if (!slash) return -1;
  const char* p = slash;
  while (p > buf && p[-1] >= '0' && p[-1] <= '9') --p;
  return p == slash ? -1 : std::atoi(p);
}

}  // namespace

// threads − 1 workers; the thread that opens a region is rank 0. Every worker takes part in
// the completion count of every region (a worker whose rank is beyond the region's team
// only reports back), so the job fields are never read while the next region writes them.
class ThreadPool {
 public:
  ThreadPool(int threads, std::chrono::nanoseconds spin)
      : max_spin_ns_(spin.count()), cpus_(std::max(1, Executor::affinity_threads())) {
    spin_ns_.store(max_spin_ns_, std::memory_order_relaxed);
    workers_.reserve(static_cast<std::size_t>(threads - 1));
    for (int r = 1; r < threads; ++r) workers_.emplace_back([this, r] { work(r); });
  }
  ~ThreadPool() {
    stop_ = true;
    change(start_);
    for (std::thread& t : workers_) t.join();
  }
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  void run(int t, void (*fn)(void*, int), void* ctx) {
    fn_ = fn;
    ctx_ = ctx;
    team_ = t;
    error_ = nullptr;
    const std::uint32_t done = done_.value.load(std::memory_order_relaxed);
    remaining_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
    change(start_);  // publishes the job fields above
    t_in_region = true;
    call(0);
    t_in_region = false;
    wait_for_change(done_, done, spin_ns_.load(std::memory_order_relaxed));
    if (error_) std::rethrow_exception(error_);
  }

  // A worker sleeps on the start of the next region (its spin has run out, or spinning is
  // off): opening a region now costs a futex wake.
  bool asleep() const { return start_.sleepers.load(std::memory_order_relaxed) != 0; }

  // Sense-reversing barrier of the `team` threads of the running region.
  void barrier(int team) {
    const std::uint32_t sense = barrier_.value.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == static_cast<std::uint32_t>(team)) {
      arrived_.store(0, std::memory_order_relaxed);
      change(barrier_);
    } else {
      wait_for_change(barrier_, sense, spin_ns_.load(std::memory_order_relaxed));
    }
  }

  // Spinning pays only while every runnable thread has a CPU. With more runnable threads
  // than CPUs (another program, or this one's threads beyond the CPUs) a thread that spins
  // for its partner keeps the partner, which is waiting for a CPU, off it, and a thread that
  // sleeps is woken promptly by the scheduler instead (measured on 2 cores next to two
  // compilers: 2 threads on the 3 200-particle dam break 5.7 s wall sleeping at once, 6.5 s
  // after 2 µs spins, 8.7 s after 5 µs, 15.4 s after 50 µs; 1 thread 6.1 s). And a region
  // of two threads on cores that other programs keep busy ends only when both threads have
  // been given a CPU: there one thread is faster than two (docs/validation.md §6 "Threads").
  // So rank 0 looks at the machine's runnable count at most every kProbeInterval and
  // counts the other programs' runnable threads (the count less this thread and the
  // workers not asleep between regions); the threads that fit beside them on this
  // process's CPUs are what an adapting executor uses (threads_now), and the workers spin
  // only while all of the pool's threads fit (when the count cannot be read, nothing
  // fits: one thread, no spinning). A count is one instant: a kernel thread or a short
  // command that happens to be runnable at the probe would put 20 ms of loops on one
  // thread (on an idle machine 5-7 % of the loops of the 3 200-particle dam break), so the
  // other programs' threads are the lesser count of the last two probes: a competitor
  // is followed within 40 ms, a blip is not.
  int threads_now(int t) {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_probe_ >= kProbeInterval) {
      last_probe_ = now;
      const int runnable = runnable_threads();
      const int pool = static_cast<int>(workers_.size()) + 1;
      const int asleep = static_cast<int>(start_.sleepers.load(std::memory_order_relaxed));
      const int seen = runnable < 0 ? cpus_ : std::max(0, runnable - 1 - (pool - 1 - asleep));
      const int others = std::min(seen, others_before_);
      others_before_ = seen;
      fitting_ = std::clamp(cpus_ - others, 1, pool);
      spin_ns_.store(others + pool > cpus_ ? 0 : max_spin_ns_, std::memory_order_relaxed);
    }
    return std::min(t, fitting_);
  }

 private:
  void call(int rank) {
    try {
      fn_(ctx_, rank);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex_);
      if (!error_) error_ = std::current_exception();
    }
  }

  void work(int rank) {
    t_in_region = true;
    std::uint32_t seen = 0;
    for (;;) {
      wait_for_change(start_, seen, spin_ns_.load(std::memory_order_relaxed));
      seen = start_.value.load(std::memory_order_acquire);
      if (stop_) return;
      if (rank < team_) call(rank);
      if (remaining_.fetch_sub(1, std::memory_order_acq_rel) == 1) change(done_);
    }
  }

  static constexpr std::chrono::milliseconds kProbeInterval{20};
  const std::int64_t max_spin_ns_;
  const int cpus_;
  int fitting_ = 1;
  int others_before_ = 0;  // the other programs' runnable threads at the previous probe
  std::atomic<std::int64_t> spin_ns_{0};
  std::chrono::steady_clock::time_point last_probe_{};
  WaitWord start_, done_, barrier_;
  alignas(64) std::atomic<std::uint32_t> arrived_{0};
  alignas(64) std::atomic<int> remaining_{0};
  // The running region's job, written by rank 0 before start_ changes.
  void (*fn_)(void*, int) = nullptr;
  void* ctx_ = nullptr;
  int team_ = 0;
  bool stop_ = false;
  std::mutex error_mutex_;
  std::exception_ptr error_;
  std::vector<std::thread> workers_;
};

Executor::Executor(int threads, Load load)
    : threads_(std::clamp(threads, 1, kMaxThreads)), load_(load) {}

Executor::~Executor() = default;

ThreadPool* Executor::pool() const {
  if (!pool_)
    pool_ = std::make_shared<ThreadPool>(threads_, std::chrono::microseconds(spin_microseconds()));
  return pool_.get();
}

void Executor::run_region(int t, void (*fn)(void*, int), void* ctx) const {
  pool()->run(t, fn, ctx);
}

int Executor::team_now(int t) const {
  if (t <= 1 || in_region()) return 1;
  ThreadPool* p = pool();
  const int now = p->threads_now(t);  // also keeps the spin limit up to date
  if (load_ == Load::Fixed) return t;
  if (now < t) reduced_.fetch_add(1, std::memory_order_relaxed);
  return now;
}

Executor::LearntShares& Executor::learnt_shares(const void* loop, int t, std::uint64_t u) const {
  for (LearntShares& s : learnt_)
    if (s.loop == loop && s.t == t && s.pair_units == u) return s;
  LearntShares s;
  s.loop = loop;
  s.t = t;
  s.pair_units = u;
  const auto n = static_cast<std::size_t>(t);
  s.bound.resize(n + 1);
  for (std::size_t r = 0; r <= n; ++r) s.bound[r] = static_cast<double>(r) / static_cast<double>(t);
  s.units.assign(n + 1, 0.0);
  s.seconds.assign(n, 0.0);
  s.at.assign(n + 1, 0);
  learnt_.push_back(std::move(s));
  return learnt_.back();
}

void Executor::learn_shares(std::vector<double>& bound, const std::vector<double>& units,
                            const std::vector<double>& seconds) {
  const std::size_t t = seconds.size();
  const double total_units = units[t];
  double total = 0.0;
  for (const double s : seconds) total += s;
  if (!(total >= kMinLearnSeconds) || !(total_units > 0.0)) return;
  // Cumulative cost over the units, linear within each share as it ran.
  std::size_t r = 0;
  double before = 0.0;  // the seconds of shares 0 .. r-1
  for (std::size_t k = 1; k < t; ++k) {
    const double goal = total * static_cast<double>(k) / static_cast<double>(t);
    while (r + 1 < t && before + seconds[r] < goal) before += seconds[r++];
    const double into = seconds[r] > 0.0 ? std::clamp((goal - before) / seconds[r], 0.0, 1.0) : 0.5;
    const double even = (units[r] + into * (units[r + 1] - units[r])) / total_units;
    bound[k] += std::clamp(0.5 * (even - bound[k]), -kMaxShareStep, kMaxShareStep);
  }
  for (std::size_t k = 1; k < t; ++k) bound[k] = std::clamp(bound[k], bound[k - 1], 1.0);
}

bool Executor::workers_asleep() const {
  return !in_region() && pool()->asleep();
}

bool Executor::in_region() {
  return t_in_region;
}

void Team::barrier() const {
  if (size_ < 2) return;
  if (rank_ == 0) barriers_->fetch_add(1, std::memory_order_relaxed);
  pool_->barrier(size_);
}

int Executor::hardware_threads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

int Executor::affinity_threads() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 0;
  return CPU_COUNT(&set);
}

int Executor::env_threads() {
  // OMP_NUM_THREADS may be a list ("4,2" for nested levels); the first entry is ours.
  const char* s = std::getenv("OMP_NUM_THREADS");
  if (!s) return 0;
  char* end = nullptr;
  const long n = std::strtol(s, &end, 10);
  if (end == s || (*end != '\0' && *end != ',') || n < 1 || n > kMaxThreads) return 0;
  return static_cast<int>(n);
}

int Executor::default_threads() {
  if (const int n = env_threads(); n > 0) return n;
  if (const int n = affinity_threads(); n > 0) return n;
  return hardware_threads();
}

int Executor::spin_microseconds() {
  const char* s = std::getenv("SLAMSPH_SPIN_US");
  if (!s) return kSpinMicroseconds;
  char* end = nullptr;
  const long n = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || n < 0 || n > 100000) return kSpinMicroseconds;
  return static_cast<int>(n);
}

std::string Executor::wait_policy() {
  return "spin up to " + std::to_string(spin_microseconds()) +
         " us unless the CPUs are oversubscribed, then sleep";
}

}  // namespace slamsph
